#!/usr/bin/python3
"""The seepage test's result (in.oedometer -var gradients ...): for each run
folder, the eroded volume per stage, of the specimen and of its loose
grains, and per size interval; which eroded grains were loose at rest.

    /usr/bin/python3 tools/suffusion_report.py RUN [RUN ...] --out DIR

writes DIR/stages.csv (one row per run and stage), DIR/intervals.csv (one
row per run, stage and size interval: the interval's volume eroded so far,
% of the interval), DIR/depth.csv (one row per run and height slice one
coarsest diameter thick, counted from the outlet: where the grains eroded
by the end of the last stage were at rest, as % of the slice's loose
volume) and DIR/suffusion.png (eroded % against the gradient; eroded % of
each interval after the last stage), and prints the table.
Shares are by volume (the grains are of one material). It reads the run's
suffusion.txt, its eroded_i<gradient>.txt files and final.dump (each grain's
class and interval at rest) through tools/outputs.py.
"""
import argparse
import csv
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import outputs  # noqa: E402


def at_rest(run):
    """{id: (volume, interval, primary)} of the grains at rest."""
    snap = outputs.last_snapshot(os.path.join(run, "final.dump"))
    ids = snap.col("id", int)
    vol = 4.0 / 3.0 * np.pi * snap["radius"] ** 3
    interval = snap.col(outputs.peratom_name("interval"), lambda t: int(float(t)))
    primary = snap[outputs.PRIMARY] > 0.5
    return {i: (v, k, p) for i, v, k, p in zip(ids, vol, interval, primary)}, snap


def run_report(run):
    """The stages of one run with their eroded grains, and its intervals."""
    grains, snap = at_rest(run)
    stages = outputs.read_suffusion(os.path.join(run, "suffusion.txt"))
    intervals = sorted({k for _, k, _ in grains.values()})
    vol_of = {k: sum(v for v, kk, _ in grains.values() if kk == k) for k in intervals}
    loose_of = {k: sum(v for v, kk, p in grains.values() if kk == k and not p) for k in intervals}
    diam_of = {k: 2e3 * np.median(snap["radius"][snap.col(outputs.peratom_name("interval"),
                                                          lambda t: int(float(t))) == k])
               for k in intervals}
    eroded = {k: 0.0 for k in intervals}
    rows, irows, left_all = [], [], set()
    for s, g in enumerate(stages["gradient_text"]):
        left = outputs.read_outlet(outputs.eroded_file(run, g))["id"]
        left_all.update(left)
        was_primary = sum(grains[i][0] for i in left if grains[i][2])
        for i in left:
            eroded[grains[i][1]] += grains[i][0]
        row = {name: stages[name][s] for _, name in outputs.SUFFUSION_COLUMNS}
        row.update(run=os.path.basename(os.path.normpath(run)), gradient=g,
                   stage_grains=len(left),
                   stage_primary_at_rest_pct=100.0 * was_primary / max(sum(grains[i][0] for i in left), 1e-300))
        rows.append(row)
        for k in intervals:
            irows.append({"run": row["run"], "gradient": g, "interval": k,
                          "diameter_mm": "%.4f" % diam_of[k],
                          "loose_pct_of_interval_at_rest": "%.2f" % (100.0 * loose_of[k] / vol_of[k]),
                          "eroded_pct_of_interval": "%.3f" % (100.0 * eroded[k] / vol_of[k])})
    return rows, irows, depth_profile(run, snap, left_all)


def depth_profile(run, snap, left):
    """Per slice one coarsest diameter thick, counted from the outlet (the
    lowest grain bottom at rest; the flow runs down; a grain in the slice of
    its centre): the slice's grains and loose volume at rest, the volume
    eroded from it (loose and all) and the loose share eroded."""
    ids = snap.col("id", int)
    z, r = snap["z"], snap["radius"]
    vol = 4.0 / 3.0 * np.pi * r ** 3 * 1e9                      # mm^3
    loose = ~(snap[outputs.PRIMARY] > 0.5)
    gone = np.isin(ids, list(left))
    k = np.floor((z - (z - r).min()) / (2.0 * r.max())).astype(int)
    name = os.path.basename(os.path.normpath(run))
    out = []
    for s in range(k.max() + 1):
        in_s = k == s
        lv, gl = vol[in_s & loose].sum(), vol[in_s & loose & gone].sum()
        out.append({"run": name, "slice_from_outlet": s, "grains": int(in_s.sum()),
                    "loose_volume_mm3": "%.6e" % lv, "eroded_loose_volume_mm3": "%.6e" % gl,
                    "eroded_loose_pct_of_slice_loose": "%.2f" % (100.0 * gl / lv if lv > 0 else 0.0),
                    "eroded_volume_mm3": "%.6e" % vol[in_s & gone].sum()})
    return out


DEPTH_FIELDS = ["run", "slice_from_outlet", "grains", "loose_volume_mm3", "eroded_loose_volume_mm3",
                "eroded_loose_pct_of_slice_loose", "eroded_volume_mm3"]
STAGE_FIELDS = ["run", "gradient", "pressure_drop", "steps", "eroded_pct", "eroded_loose_pct",
                "stage_eroded_pct", "grains_eroded", "stage_grains", "stage_primary_at_rest_pct",
                "primary_pct", "porosity", "lid_stress", "permeability"]
INTERVAL_FIELDS = ["run", "gradient", "interval", "diameter_mm", "loose_pct_of_interval_at_rest",
                   "eroded_pct_of_interval"]


def write_csv(path, fields, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        w.writeheader()
        w.writerows(rows)


def plot(path, rows, irows):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
    for run in dict.fromkeys(r["run"] for r in rows):
        rr = [r for r in rows if r["run"] == run]
        a.plot([max(float(r["gradient"]), 0.1) for r in rr], [r["eroded_pct"] for r in rr], "o-", label=run)
        last = rr[-1]["gradient"]
        ii = [r for r in irows if r["run"] == run and r["gradient"] == last]
        b.plot([float(r["diameter_mm"]) for r in ii], [float(r["eroded_pct_of_interval"]) for r in ii],
               "o-", label=run)
    a.set_xscale("log")
    a.set_xlabel("hydraulic gradient (0 drawn at 0.1)")
    a.set_ylabel("eroded, % of the specimen's volume (cumulative)")
    b.set_xscale("log")
    b.set_xlabel("grain diameter (mm)")
    b.set_ylabel("eroded after the last stage, % of the interval")
    a.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=120)


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("runs", nargs="+", metavar="RUN")
    ap.add_argument("--out", required=True)
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    rows, irows, drows = [], [], []
    for run in a.runs:
        r, i, d = run_report(run)
        rows += r
        irows += i
        drows += d
    write_csv(os.path.join(a.out, "stages.csv"), STAGE_FIELDS, rows)
    write_csv(os.path.join(a.out, "intervals.csv"), INTERVAL_FIELDS, irows)
    write_csv(os.path.join(a.out, "depth.csv"), DEPTH_FIELDS, drows)
    plot(os.path.join(a.out, "suffusion.png"), rows, irows)
    print("%-34s %8s %7s %9s %9s %7s %9s" % ("run", "gradient", "steps", "eroded%", "loose%", "grains",
                                              "primary%"))
    for r in rows:
        print("%-34s %8s %7d %9.3f %9.3f %7d %9.2f" % (r["run"], r["gradient"], r["steps"], r["eroded_pct"],
                                                      r["eroded_loose_pct"], r["grains_eroded"],
                                                      r["primary_pct"]))


if __name__ == "__main__":
    main()
