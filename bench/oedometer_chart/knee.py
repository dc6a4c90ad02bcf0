#!/usr/bin/python3
"""The energy limit's knee at the scene's default size, from runs to rest.

    /usr/bin/python3 bench/oedometer_chart/knee.py --ref REF_DIR --default DEF_DIR \\
        [--csv out/oedometer_chart/knee_side5.5.csv]

REF_DIR and DEF_DIR are outputs of tools/oedometer_study.py (study.csv and
runs/NAME/fabric_series.txt): the reference runs with a stricter energy limit
(--ref-vrms, 1e-4) and the default runs (--default-vrms, 2e-4), same seeds. The scene's
stop rule is applied again to each reference run's time series with looser
limits (1.4e-4 ... 5e-4 m/s): the series holds every check the scene made,
so the step at which a looser limit would have stopped the run, and the
primary % by mass and loose % by number at that check, are exact (the final
analysis with the lid held at rest may differ from the check's row by a few
tenths). One CSV row per run and limit: seed, ke_vrms, source (run: the
final state of a run; series: a check row of the reference run), wall
seconds (runs only), steps,
primary % by mass, loose % by number; then a summary per limit on stdout.
"""
import argparse
import csv
import os
import re
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import outputs  # noqa: E402

LOOSER = [1.4e-4, 2e-4, 3e-4, 5e-4]


def ke_limit(rundir):
    for name in ("log.lammps", "log.liggghts"):
        path = os.path.join(rundir, name)
        if os.path.exists(path):
            for line in open(path):
                m = re.match(r"KE LIMIT: ([0-9.eE+-]+) J", line)
                if m:
                    return float(m.group(1))
    raise SystemExit("no KE LIMIT line in " + rundir)


def stop_index(s, limit, tol=0.05, pf_tol=1.0):
    """The scene's rule: KE below limit, block rms stress error below tol,
    primary % moved less than pf_tol over the last two blocks."""
    p = [-100.0, -200.0, -300.0]
    primary, ke, err = s["primary_mass_pct"], s["ke_translation"], s["stress_error_rms"]
    for i in range(1, len(primary)):
        p = [primary[i], p[0], p[1]]
        if ke[i] < limit and err[i] < tol and abs(p[0] - p[1]) + abs(p[1] - p[2]) < pf_tol:
            return i
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--ref", required=True)
    ap.add_argument("--default", required=True)
    ap.add_argument("--ref-vrms", type=float, default=1e-4, help="ke_vrms of the reference runs")
    ap.add_argument("--default-vrms", type=float, default=2e-4, help="ke_vrms of the default runs")
    ap.add_argument("--csv", default=os.path.join("out", "oedometer_chart", "knee_side5.5.csv"),
                    help="where the CSV goes (default out/oedometer_chart/knee_side5.5.csv)")
    a = ap.parse_args()
    rows = []
    for d, v, looser in ((a.ref, a.ref_vrms, True), (a.default, a.default_vrms, False)):
        for r in csv.DictReader(open(os.path.join(d, "study.csv"))):
            rundir = os.path.join(d, "runs", r["name"])
            rows.append(dict(seed=r["seed"], ke_vrms="%g" % v, source="run", wall_s=r["wall_s"], steps=r["steps"],
                             primary_mass_pct=r["primary_mass_pct"],
                             loose_number_pct=r["loose_number_pct"], at_rest=r["at_rest"]))
            if not looser:
                continue
            s = outputs.read_series(os.path.join(rundir, "fabric_series.txt"))
            lim = ke_limit(rundir)
            for w in LOOSER:
                i = stop_index(s, lim * (w / v) ** 2)
                if i is None:
                    continue
                rows.append(dict(seed=r["seed"], ke_vrms="%g" % w, source="series", wall_s="",
                                 steps="%d" % s["step"][i],
                                 primary_mass_pct="%.2f" % s["primary_mass_pct"][i],
                                 loose_number_pct="%.2f" % s["loose_number_pct"][i], at_rest="yes"))
    rows.sort(key=lambda r: (float(r["ke_vrms"]), r["source"], int(r["seed"])))
    os.makedirs(os.path.dirname(a.csv) or ".", exist_ok=True)
    with open(a.csv, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print("%-8s %-7s %6s %22s %16s %18s" % ("ke_vrms", "source", "seeds", "steps (mean)",
                                            "primary % mean", "loose % mean"))
    keys = sorted({(float(r["ke_vrms"]), r["source"]) for r in rows})
    for k, src in keys:
        g = [r for r in rows if float(r["ke_vrms"]) == k and r["source"] == src]
        st = [int(r["steps"]) for r in g]
        pm = [float(r["primary_mass_pct"]) for r in g]
        lo = [float(r["loose_number_pct"]) for r in g]
        print("%-8g %-7s %6d %22s %16s %18s" % (
            k, src, len(g), "%d (%d-%d)" % (np.mean(st), min(st), max(st)),
            "%.1f (%.1f-%.1f)" % (np.mean(pm), min(pm), max(pm)),
            "%.1f (%.1f-%.1f)" % (np.mean(lo), min(lo), max(lo))))
    print("wrote", a.csv)


if __name__ == "__main__":
    main()
