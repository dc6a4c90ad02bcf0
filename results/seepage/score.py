#!/usr/bin/python3
"""The verdict scored against the seepage test: for each run, the share of
its loose mass the seepage test washed out (suffusion_report's stages.csv,
the last stage) beside the shares the verdict predicts (verdict.csv of
tools/constriction_verdict.py: loose mass finer than D_c35 by number, by
area, finer than the percolation opening) and the classical criteria.
The eroded share is split by where the grains were at rest (depth.csv of
suffusion_report): the filter's own layer (within one coarsest diameter of
the outlet, whose floor the test removes) and the bulk above it, whose
eroded share of its loose volume is what a suffusion criterion speaks of.
Writes DIR/scoring.csv and DIR/scoring.png and prints, per predictor, the
mean absolute difference from the eroded shares and the rank correlation
(Spearman) over the runs.

    /usr/bin/python3 results/seepage/score.py results/seepage
"""
import csv
import os
import sys

import numpy as np

PREDICTORS = [("loose_finer_Dc35_percent", "finer than D_c35 by number"),
              ("loose_finer_Dc35_area_percent", "finer than D_c35 by area"),
              ("loose_finer_percolation_percent", "finer than the percolation opening")]
CLASSICAL = ["kezdi", "kenney_lau", "burenkova", "wan_fell"]


def rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def spearman(a, b):
    ra, rb = np.argsort(np.argsort(a)), np.argsort(np.argsort(b))
    return float(np.corrcoef(ra, rb)[0, 1]) if len(a) > 2 else float("nan")


def split_by_depth(slices):
    """The outlet layer's share of the eroded volume, and the share of the
    bulk's loose volume (slices 1 and up) that was eroded."""
    vol = [float(r["eroded_volume_mm3"]) for r in slices]
    loose = [float(r["loose_volume_mm3"]) for r in slices]
    gone = [float(r["eroded_loose_volume_mm3"]) for r in slices]
    return {"outlet_layer_pct_of_eroded": "%.1f" % (100.0 * vol[0] / sum(vol) if sum(vol) > 0 else 0.0),
            "bulk_eroded_pct_of_bulk_loose": "%.3f" % (100.0 * sum(gone[1:]) / sum(loose[1:]))}


def main():
    d = sys.argv[1]
    verdict = {r["run"]: r for r in rows(os.path.join(d, "verdict", "verdict.csv"))}
    last = {}
    for r in rows(os.path.join(d, "stages.csv")):
        last[r["run"]] = r          # the stages in order: the last one stays
    depth = {}
    for r in rows(os.path.join(d, "depth.csv")):
        depth.setdefault(r["run"], []).append(r)
    table = []
    for run in sorted(set(verdict) & set(last)):
        v, s = verdict[run], last[run]
        row = {"run": run, "gradient": s["gradient"], "steps": int(float(s["steps"])),
               "primary_pct_at_rest": v["primary_mass_percent"],
               "eroded_pct_of_specimen": "%.3f" % float(s["eroded_pct"]),
               "eroded_pct_of_loose": "%.3f" % float(s["eroded_loose_pct"])}
        row.update(split_by_depth(depth[run]))
        row.update({k: v[k] for k, _ in PREDICTORS})
        row.update({k: v[k] for k in CLASSICAL})
        table.append(row)
    with open(os.path.join(d, "scoring.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(table[0]))
        w.writeheader()
        w.writerows(table)
    eroded = np.array([float(r["eroded_pct_of_loose"]) for r in table])
    bulk = np.array([float(r["bulk_eroded_pct_of_bulk_loose"]) for r in table])
    print("%d runs; eroded share of the loose mass: %s" % (len(table), ", ".join("%.1f" % e for e in eroded)))
    print("from the filter's layer, %% of the eroded volume: %s"
          % ", ".join(r["outlet_layer_pct_of_eroded"] for r in table))
    print("the bulk above it, eroded %% of its loose volume: %s" % ", ".join("%.2f" % b for b in bulk))
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 2, figsize=(10, 4.5), sharex=True)
    for k, label in PREDICTORS:
        p = np.array([float(r[k]) for r in table])
        print("%-36s mean |predicted - eroded| %5.1f points, Spearman %+.2f; against the bulk %5.1f points"
              % (label, np.mean(np.abs(p - eroded)), spearman(p, eroded), np.mean(np.abs(p - bulk))))
        for ax, y in zip(axes, (eroded, bulk)):
            ax.plot(p, y, "o", label=label)
    for r, e in zip(table, eroded):     # the bulk's points lie on 0: named on the left only
        axes[0].annotate(r["run"].split("_seed")[0], (float(r[PREDICTORS[0][0]]), e), fontsize=7)
    for ax in axes:
        ax.plot([0, 100], [0, 100], "k:", lw=0.8)
        ax.set_xlabel("predicted: loose mass finer than the opening, %")
    for r in table:
        print("%-28s classical: %s" % (r["run"], ", ".join("%s %s" % (k, r[k]) for k in CLASSICAL)))
    axes[0].set_ylabel("washed out, % of the whole specimen's loose mass")
    axes[1].set_ylabel("washed out of the bulk above the filter's layer,\n% of its loose volume")
    axes[0].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "scoring.png"), dpi=120)


if __name__ == "__main__":
    main()
