#!/usr/bin/python3
"""The rest protocol's variants, one scene run per row: the relaxation held
or under the servo, the reload at once or once balanced, a tighter load_tol
(protocol_table.csv, side 7.7), and rest_tol 1e-3 against 1e-4 (side 3.3,
tolerance_table.csv), and Cundall's local damping while loading against a
slower servo (damping_table.csv, side 7.7). Rows already in a table are not
run again.

    /usr/bin/python3 bench/rest_protocol/run.py --out results/rest/force_balance --runs out/rest_protocol

One rank per run, --jobs at a time (about 2 hours on 2 cores).
"""
import argparse
import os
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import oedometer_runs  # noqa: E402
import outputs  # noqa: E402

ONCE = {"reload_early": "no"}
SERVO = {"relax_lid": "servo"}
# (table, rule, soil, seed, relaxation label, scene variables)
PROTOCOL = [("protocol", "DA", "cu2.5", s, "held, reload once balanced", ONCE) for s in (1, 2, 3)] + [
    ("protocol", "DA", "cu2.5", 1, "held, reload early", {})] + [
    ("protocol", "DA", "cu2.5", s, "servo", SERVO) for s in (1, 2, 3)] + [
    ("protocol", "DA", "cu2.5", 1, "servo, rest_tol 1e-4", dict(SERVO, rest_tol="1e-4", relax_max="40000"))] + [
    ("protocol", "LA", "cu2.5", s, "held, reload once balanced", ONCE) for s in (2, 3)] + [
    ("protocol", "LA", "cu2.5", s, "held, reload early", {}) for s in (2, 3)] + [
    ("protocol", "LA", "cu2.5", 2, "held, reload early, load_tol 0.003", {"load_tol": "0.003"})] + [
    ("protocol", "LA", "cu2.5", s, "servo", SERVO) for s in (2, 3)] + [
    ("protocol", "LA", "cu3.0", 2, "held, reload once balanced", ONCE),
    ("protocol", "LA", "cu3.0", 2, "held, reload early", {})] + [
    # the loading's checks every 1,000 steps instead of 2,000: held, and under the servo
    ("protocol", "DA", "cu2.5", s, "held, checks every 1,000 steps", {"every": "1000"})
    for s in (1, 2, 3)] + [
    ("protocol", "DA", "cu2.5", s, "servo, checks every 1,000 steps", dict(SERVO, every="1000"))
    for s in (1, 2, 3)]
# Cundall's local damping while loading (alpha), and the servo four times
# slower with none: steps to rest against the answer (damping_table.csv)
# (alpha 0.4 and 0.7 do not come to rest within 40,000 steps of relaxation
# or t_max: one seed each shows it)
DAMPING = [("damping", "DA", "cu2.5", s, "alpha %s" % a, {"damping": a} if a != "0" else {})
           for a in ("0", "0.1", "0.2") for s in (1, 2, 3)] + [
    ("damping", "DA", "cu2.5", 1, "alpha %s" % a, {"damping": a}) for a in ("0.4", "0.7")] + [
    ("damping", "DA", "cu2.5", s, "alpha 0, the servo 4 times slower", {"kp": "0.05", "vmax": "0.0025"})
    for s in (1, 2, 3)]
TOLERANCE = [("tolerance", "DA", "cu2.5", s, "held, reload once balanced",
              dict(ONCE, side="3.3", rest_tol=tol, relax_max="200000"))
             for s in (1, 2, 3) for tol in ("1e-3", "1e-4")]
FIELDS = {
    "protocol": ["rule", "soil", "seed", "relaxation", "steps", "at_rest", "primary_volume_pct",
                 "lid_stress_Pa", "reloads", "wall_s"],
    "damping": ["rule", "soil", "seed", "relaxation", "steps", "at_rest", "primary_volume_pct",
                "lid_stress_Pa", "reloads", "wall_s"],
    "tolerance": ["side", "rule", "soil", "seed", "rest_tol", "relaxation", "steps", "steps_relaxed",
                  "ratio", "lid_stress_Pa", "primary_volume_pct", "wall_s"],
}


def name(row):
    table, rule, soil, seed, label, var = row
    return "%s_%s_%s_seed%d_%s" % (table, rule, soil, seed,
                                  "_".join("%s%s" % kv for kv in sorted(var.items())) or "default")


def one(row, runs):
    table, rule, soil, seed, label, var = row
    rundir = os.path.join(runs, name(row))
    scene = {"psd": "input_scripts/psd/%s.txt" % soil, "seed": str(seed),
             "arrangement": "discrete" if rule == "DA" else "layerwise", "side": "7.7"}
    scene.update(var)
    r = oedometer_runs.run_scene(rundir, scene)
    if r is None:
        return None
    rest = outputs.read_rest(os.path.join(rundir, "rest.txt"))
    series = outputs.read_series(os.path.join(rundir, "fabric_series.txt"))
    return dict(r, name=name(row), table=table, rule=rule, soil=soil, seed=str(seed), relaxation=label,
                side=scene["side"], rest_tol=var.get("rest_tol", "1e-3"),
                primary_volume_pct=r["primary_mass_pct"], reloads="%d" % rest["reloads"],
                steps_relaxed="%d" % rest["steps_relaxed"],
                ratio="%.3g" % series["unbalanced_force_ratio"][-1])


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", required=True, help="folder of protocol_table.csv and tolerance_table.csv")
    ap.add_argument("--runs", required=True, help="folder of the run folders")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--tables", nargs="+", default=["protocol", "tolerance", "damping"],
                    help="which tables to make (default: all)")
    a = ap.parse_args()
    for table, rows in (("protocol", PROTOCOL), ("tolerance", TOLERANCE), ("damping", DAMPING)):
        if table not in a.tables:
            continue
        path = os.path.join(a.out, "%s_table.csv" % table)
        order = [name(r) for r in rows]
        done = {r["name"] for r in oedometer_runs.read_rows(path)}
        todo = [r for r in rows if name(r) not in done]
        print("%s_table.csv: %d rows, %d to run" % (table, len(rows), len(todo)), flush=True)
        oedometer_runs.run_all(todo, a.jobs, lambda r: one(r, a.runs), path,
                               ["name"] + FIELDS[table], order)


if __name__ == "__main__":
    main()
