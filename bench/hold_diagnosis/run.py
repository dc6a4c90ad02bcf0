#!/usr/bin/python3
"""The hold diagnosis: what makes the oedometer specimen lose its stress when
the lid stops (results/rest/creep_diagnosis); with --study rest, the rest by force
balance: the unbalanced-force ratio's tolerance, contact and local damping
against the steps to rest, the answer there and the hold (results/rest/force_balance).

Each row runs input_scripts/in.oedometer (a copy, so that editing the scene
cannot change a running job) on DA Cu 2.5, side 3.3 (4,188 grains), seed 1,
one rank, with one setting moved from the defaults, to the scene's rest;
then the servo stops and the lid is held for 20,000 steps (-var hold). Two
rows run at a time (one per core), about 20 minutes for the table.
Writes OUT/hold_table.csv (one row per setting), OUT/hold_series.csv (the
lid stress every 2,000 steps of each hold) and OUT/hold_diagnosis.png.

Usage, from the repository root:
  /usr/bin/python3 bench/hold_diagnosis/run.py [--out DIR] [--rows NAME ...]
  /usr/bin/python3 bench/hold_diagnosis/run.py --study rest --side 7.7 --hold 0 --out DIR
"""
import argparse
import csv
import os
import re
import shutil
import subprocess
import sys
import time
from concurrent.futures import ThreadPoolExecutor

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import outputs  # noqa: E402

# name, the setting moved (LIGGGHTS -var pairs), what it tests
ROWS = [
    ("default", [], "the scene's defaults"),
    ("mu10", ["mu", "10", "eta", "0.04"],
     "no sliding: mu = mu_wall = 10 (eta 0.04 keeps the rolling cap 2 eta mu = 0.8)"),
    ("mu10_dt0.1", ["mu", "10", "eta", "0.04", "dtfac", "0.1"], "mu 10 at a quarter of the step"),
    ("dt0.2", ["dtfac", "0.2"], "half the time step"),
    ("dt0.1", ["dtfac", "0.1"], "a quarter of the time step"),
    ("epsd2", ["rolling", "epsd2"], "rolling spring without its dashpot"),
    ("rolling_off", ["rolling", "off"], "no rolling resistance"),
    ("tdamp_off", ["tdamp", "off"], "no tangential dashpot"),
    ("zeta0.1", ["zeta", "0.1"], "contact damping ratio 0.1 (default 0.6)"),
    ("zeta0.3", ["zeta", "0.3"], "contact damping ratio 0.3"),
    ("mass1e3", ["mass_scale", "1e3"], "density scaled 1e3 (default 1e4)"),
    ("mass1e5", ["mass_scale", "1e5"], "density scaled 1e5"),
    ("linear", ["hertz", "0", "kappa", "3957"],
     "linear springs of the same secant stiffness (kappa 3957)"),
    ("local0.7", ["damping", "0.7"], "Cundall's local damping 0.7"),
    ("local0.7_dt0.1", ["damping", "0.7", "dtfac", "0.1"], "local damping 0.7, a quarter of the step"),
    ("wall_mu0", ["mu_wall", "0"], "frictionless walls and lid"),
    ("walls_mu10", ["mu_side", "10", "mu_lid", "10"],
     "no sliding on the walls and the lid (their rolling cap kept at 0.4)"),
    ("side_mu10", ["mu_side", "10"], "no sliding on the side walls and the top"),
    ("lid_mu10", ["mu_lid", "10"], "no sliding on the lid"),
    ("skin2e-4", ["skin", "2e-4"], "neighbour skin 4 times the default 5e-5 m"),
    ("hold_zero100", ["hold_zero", "100"],
     "the defaults, every velocity set to zero every 100 steps of the hold"),
    ("hold_zero10", ["hold_zero", "10"], "the same every 10 steps"),
    ("balanced", ["zeta", "0.3", "rest_tol", "0.01"],
     "rest at force balance: zeta 0.3, the ratio below 0.01"),
    ("balanced_zero100", ["zeta", "0.3", "rest_tol", "0.01", "hold_zero", "100"],
     "rest at force balance, velocities zeroed every 100 steps of the hold"),
    ("balanced_zero100_seed2", ["zeta", "0.3", "rest_tol", "0.01", "hold_zero", "100", "seed", "2"],
     "the same, seed 2"),
]

# --study rest: the rule, its tolerance and the damping (--side 7.7: seeds 1-3
# of the energy rule and of the ratio at 0.01, one seed of the others)
def rest_rows(seeds):
    rows = []
    for name, var, what, n in [
            ("energy_rule", [], "the scene's defaults: the energy rule, zeta 0.6", seeds),
            ("zeta0.3_tol1e-2", ["zeta", "0.3", "rest_tol", "0.01"],
             "rest by the ratio below 0.01, zeta 0.3", seeds),
            ("zeta0.3_tol1e-3", ["zeta", "0.3", "rest_tol", "0.001"],
             "rest by the ratio below 0.001, zeta 0.3", 1),
            ("local0.5_tol1e-2", ["zeta", "0.3", "damping", "0.5", "rest_tol", "0.01"],
             "local damping 0.5, zeta 0.3, ratio below 0.01", 1),
            ("zeta0.3_tol1e-2_zero100", ["zeta", "0.3", "rest_tol", "0.01", "hold_zero", "100"],
             "ratio below 0.01, zeta 0.3; with --hold 20000 held with velocities zeroed every 100 steps", 1)]:
        rows += [("%s_seed%d" % (name, seed), var + ["seed", str(seed)], what)
                 for seed in range(1, n + 1)]
    return rows


def kinetic_rows(seeds):
    """Kinetic damping (-var zero N, -var hold_zero N): zeroed while loading,
    against loaded at zeta 0.3 to a ratio and then relaxed with the lid held
    and the velocities zeroed every 100 steps (run with --hold N)."""
    rows = []
    base = ["zeta", "0.3"]
    relax = ["hold_zero", "100"]
    for name, var, what, n in [
            ("zeta0.3_tol1e-2", base + ["rest_tol", "0.01"],
             "zeta 0.3, rest by the ratio below 0.01", seeds),
            ("zeta0.3_tol1e-3", base + ["rest_tol", "0.001"],
             "zeta 0.3, rest by the ratio below 0.001", seeds),
            ("zero100_tol1e-2", base + ["zero", "100", "rest_tol", "0.01"],
             "zeta 0.3, velocities zeroed every 100 steps while loading, ratio below 0.01",
             seeds),
            ("relax_tol1e-1", base + ["rest_tol", "0.1"] + relax,
             "zeta 0.3, servo to a ratio below 0.1, then the lid held and the velocities "
             "zeroed every 100 steps", seeds),
            ("relax_tol3e-2", base + ["rest_tol", "0.03"] + relax,
             "the same from a ratio below 0.03", seeds),
            ("relax_tol1e-2", base + ["rest_tol", "0.01"] + relax,
             "the same from a ratio below 0.01", seeds),
            ("relax_tol1e-3", base + ["rest_tol", "0.001"] + relax,
             "the same from a ratio below 0.001", seeds),
            ("early_tol5e-2", base + ["rest_tol", "0.05", "pf_tol", "100"] + relax,
             "zeta 0.3, servo until the lid stress is on target over a block and the "
             "ratio below 0.05 (primary fraction not waited for), then relaxed", seeds),
            ("early_tol1e-2", base + ["rest_tol", "0.01", "pf_tol", "100"] + relax,
             "the same with the ratio below 0.01", seeds),
            ("balance_tol1e-4", base + ["rest_tol", "1e-4"],
             "the scene's rest by force balance: servo to load_tol 0.01, then relaxed "
             "until the ratio is below 1e-4 (the thermo has the crossing of 1e-3)", seeds),
            ("energy_rule_zeta0.6", ["zeta", "0.6", "rest_tol", "0"],
             "the former defaults: rest by the kinetic-energy limit under the servo, zeta 0.6",
             seeds),
            ("dt_gain1_tol1e-3", base + ["rest_tol", "1e-3", "dt_gain", "1"],
             "rest by force balance to 1e-3, one density", seeds),
            ("dt_gain2_tol1e-3", base + ["rest_tol", "1e-3", "dt_gain", "2"],
             "rest by force balance to 1e-3 with the finest grains made denser, "
             "the step 2 times longer", seeds),
            ("dt_gain4_tol1e-3", base + ["rest_tol", "1e-3", "dt_gain", "4"],
             "the same, the step 4 times longer", seeds),
            ("dt_gain4_every1000", base + ["rest_tol", "1e-3", "dt_gain", "4", "every", "1000"],
             "the step 4 times longer, the servo's checks every 1,000 steps", seeds),
            ("dt_gain4_tol1e-4", base + ["rest_tol", "1e-4", "dt_gain", "4", "relax_max", "20000"],
             "the step 4 times longer, relaxed until the ratio is below 1e-4 (at most "
             "20,000 steps; the thermo has the crossing of 1e-3)", seeds),
            ("dt_gain8_tol1e-3", base + ["rest_tol", "1e-3", "dt_gain", "8"],
             "the same, the step 8 times longer", seeds),
            ("dt_gain16_tol1e-3", base + ["rest_tol", "1e-3", "dt_gain", "16"],
             "the same, the step 16 times longer", seeds)]:
        rows += [("%s_seed%d" % (name, seed), var + ["seed", str(seed)], what)
                 for seed in range(1, n + 1)]
    return rows


STOP = re.compile(r"^STOP: (at rest|maximum time)[^\n]*?after (\d+) steps[^\n]*", re.M)
RATIO = re.compile(r"unbalanced-force ratio (\S+)")
FABRIC = re.compile(r"^FABRIC: .*?primary fabric (\S+) % by mass", re.M)
HOLD = re.compile(r"^HOLD: .*?lid stress (\S+) Pa before.*?, (\S+) Pa after "
                  r"\((\S+) %\); primary fabric (\S+) % by mass before, (\S+) % after", re.M)


def run_row(root, work, row, hold, side):
    name, var, _ = row
    out = os.path.join(work, name)
    os.makedirs(out, exist_ok=True)
    cmd = [root + "/build/liggghts-fabric", "-in", os.path.join(work, "in.oedometer"),
           "-log", os.path.join(out, "log.lammps"),
           "-var", "psd", root + "/input_scripts/psd/cu2.5.txt",
           "-var", "mesh", root + "/input_scripts/meshes/lid.stl",
           "-var", "parts", root + "/input_scripts/oedometer",
           "-var", "side", str(side), "-var", "hold", str(hold), "-var", "out", out]
    for i in range(0, len(var), 2):
        cmd += ["-var", var[i], var[i + 1]]
    t0 = time.perf_counter()
    with open(os.path.join(out, "screen.txt"), "w") as f:
        subprocess.run(cmd, stdout=f, stderr=subprocess.STDOUT, stdin=subprocess.DEVNULL)
    with open(os.path.join(out, "wall_s.txt"), "w") as f:
        f.write("%.1f\n" % (time.perf_counter() - t0))
    return name


def read_row(work, row):
    name, var, what = row
    text = open(os.path.join(work, name, "screen.txt"), errors="replace").read()
    s, h = STOP.search(text), HOLD.search(text)
    err = re.search(r"^ERROR: (.*)$", text, re.M)
    r = {"setting": name, "moved": " ".join(var) or "-", "tests": what,
         "stop": s.group(1) if s else ("error" if err else "not finished"),
         "steps_to_stop": s.group(2) if s else "",
         "ratio_at_stop": "",
         "stress_before_Pa": "", "stress_after_Pa": "", "change_pct": "",
         "primary_before_pct": "", "primary_after_pct": "", "primary_final_pct": "",
         "primary_volume_pct": "", "wall_s": "",
         "error": err.group(1)[:120] if err else ""}
    final = os.path.join(work, name, "final.dump")
    if os.path.exists(final):
        r["primary_volume_pct"] = "%.2f" % outputs.primary_volume_percent(
            outputs.dump_last(final))
    wall = os.path.join(work, name, "wall_s.txt")
    if os.path.exists(wall):
        r["wall_s"] = open(wall).read().strip()
    f = FABRIC.search(text)
    if f:
        r["primary_final_pct"] = "%.2f" % float(f.group(1))
    m = RATIO.search(s.group(0)) if s else None
    if m:
        r["ratio_at_stop"] = "%.3g" % float(m.group(1))
    if h:
        for k, v in zip(("stress_before_Pa", "stress_after_Pa", "change_pct",
                         "primary_before_pct", "primary_after_pct"), h.groups()):
            r[k] = "%.4g" % float(v)
    return r


def read_series(work, name):
    path = os.path.join(work, name, "hold_series.txt")
    if not os.path.exists(path):
        return []
    s = outputs.read_series(path, outputs.HOLD_SERIES_COLUMNS)
    step0 = s["step"][0]
    return [(int(st - step0), t, sig, ratio) for st, t, sig, ratio in
            zip(s["step"], s["t_hold"], s["lid_stress"], s["unbalanced_force_ratio"])]


# the two panels of the figure: what the numerics change, and what sliding does
PANELS = [("numerics: step, damping, contact law, mass, skin",
           ["default", "dt0.2", "dt0.1", "zeta0.1", "zeta0.3", "tdamp_off", "local0.7",
            "local0.7_dt0.1", "mass1e3", "mass1e5", "linear", "skin2e-4"]),
          ("kinetic energy: velocities zeroed during the hold; force balance",
           ["default", "hold_zero100", "hold_zero10", "balanced", "balanced_zero100",
            "balanced_zero100_seed2"]),
          ("sliding: friction of grains, walls and lid; rolling",
           ["default", "mu10", "mu10_dt0.1", "walls_mu10", "side_mu10", "lid_mu10",
            "wall_mu0", "epsd2", "rolling_off"])]


def plot(series, path):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(17, 5), sharey=True)
    for ax, (title, names) in zip(axes, PANELS):
        colours = plt.cm.tab20.colors
        for k, name in enumerate(names):
            pts = series.get(name)
            if not pts:
                continue
            ax.plot([p[0] for p in pts], [p[2] / 1e3 for p in pts],
                    color="black" if name == "default" else colours[(2 * k) % 20],
                    lw=2.5 if name == "default" else 1.2,
                    ls=["-", "--", ":", "-."][k % 4], marker=".", label=name)
        ax.set_xlabel("steps with the lid held")
        ax.set_title(title, fontsize=10)
        ax.legend(fontsize=7, ncol=2)
        ax.grid(alpha=0.3)
    axes[0].set_ylabel("lid stress (kPa)")
    fig.suptitle("DA Cu 2.5, side 3.3, seed 1, one rank: the lid held after the scene's rest")
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def main():
    p = argparse.ArgumentParser(description=__doc__,
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("--out", default="out/hold_diagnosis")
    p.add_argument("--rows", nargs="*", help="only these settings")
    p.add_argument("--study", choices=("hold", "rest", "kinetic"), default="hold")
    p.add_argument("--seeds", type=int, default=3, help="seeds of the rest and kinetic rows")
    p.add_argument("--side", type=float, default=3.3,
                   help="container edge in coarsest diameters (the rest study: 7.7)")
    p.add_argument("--hold", type=int, default=20000)
    p.add_argument("--report-only", action="store_true",
                   help="tabulate the runs already in OUT")
    a = p.parse_args()
    root = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
    work = os.path.abspath(a.out)
    os.makedirs(work, exist_ok=True)
    table_rows = {"hold": ROWS, "rest": rest_rows(a.seeds),
                  "kinetic": kinetic_rows(a.seeds)}[a.study]
    rows = [r for r in table_rows if not a.rows or r[0] in a.rows]
    if not a.report_only:
        shutil.copy(os.path.join(root, "input_scripts", "in.oedometer"), work)
        with ThreadPoolExecutor(2) as pool:
            for name in pool.map(lambda r: run_row(root, work, r, a.hold, a.side), rows):
                print("done", name, flush=True)
    table = [read_row(work, r) for r in table_rows if os.path.isdir(os.path.join(work, r[0]))]
    with open(os.path.join(work, a.study + "_table.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0].keys()))
        w.writeheader()
        w.writerows(table)
    if a.study == "kinetic":
        chart(table, os.path.join(work, "rest_chart.png"),
              "DA Cu 2.5, side %g, one rank: the answer against the cost of rest" % a.side)
    if a.study != "hold":
        report(table)
        return
    series = {r[0]: read_series(work, r[0]) for r in ROWS}
    with open(os.path.join(work, "hold_series.csv"), "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["setting", "steps_held", "time_held_s", "lid_stress_Pa",
                    "unbalanced_force_ratio"])
        for name, pts in series.items():
            for p in pts:
                w.writerow([name] + list(p))
    plot(series, os.path.join(work, "hold_diagnosis.png"))
    report(table)


def chart(table, path, title):
    """Speed against accuracy: the answer (primary % of the volume) against
    the steps to rest, one marker per run, one colour per setting."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    groups = {}
    for r in table:
        if r["stop"] != "at rest" or not r["primary_volume_pct"]:
            continue
        groups.setdefault(r["setting"].rsplit("_seed", 1)[0], []).append(
            (int(r["steps_to_stop"]), float(r["primary_volume_pct"]), float(r["wall_s"] or "nan")))
    fig, axes = plt.subplots(1, 2, figsize=(12, 4.8), sharey=True)
    for k, (name, pts) in enumerate(sorted(groups.items())):
        m = "os^vD<>ph*"[k % 10]
        for ax, col in zip(axes, (0, 2)):
            ax.plot([p[col] for p in pts], [p[1] for p in pts], m, ms=8, label=name)
    axes[0].set_xlabel("steps to rest")
    axes[1].set_xlabel("wall time to rest, one rank (s; two runs side by side)")
    axes[0].set_ylabel("primary fabric, % of the grains' volume")
    for ax in axes:
        ax.grid(alpha=0.3)
    axes[1].legend(fontsize=8)
    fig.suptitle(title)
    fig.tight_layout()
    fig.savefig(path, dpi=110)


def report(table):
    for r in table:
        print("%-28s %-12s %7s %9s %8s %7s %7s %7s %s" % (
            r["setting"], r["stop"], r["steps_to_stop"], r["ratio_at_stop"],
            r["change_pct"], r["primary_final_pct"], r["primary_volume_pct"],
            r["wall_s"], r["error"]))


if __name__ == "__main__":
    sys.exit(main())
