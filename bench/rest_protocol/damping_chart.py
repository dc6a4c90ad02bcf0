#!/usr/bin/python3
"""The chart of damping_table.csv (bench/rest_protocol/run.py --tables
damping): Cundall's local damping while loading, and a four times slower
servo, against the steps to rest and the answer at rest.

    /usr/bin/python3 bench/rest_protocol/damping_chart.py results/rest/force_balance/damping_table.csv

Writes damping_chart.png beside the table and prints one line per setting
(mean and range over the seeds).
"""
import argparse
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import oedometer_runs  # noqa: E402


def settings(rows):
    """{label: [(steps, primary %, at rest), ...]} in the table's order."""
    out = {}
    for r in rows:
        out.setdefault(r["relaxation"], []).append(
            (int(r["steps"]), float(r["primary_volume_pct"]), r["at_rest"] == "yes"))
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("table")
    a = ap.parse_args()
    by = settings(oedometer_runs.read_rows(a.table))
    fig, ax = plt.subplots(figsize=(6.4, 4.4))
    for i, (label, runs) in enumerate(by.items()):
        steps = [s for s, _, _ in runs]
        pf = [p for _, p, _ in runs]
        rest = [ok for _, _, ok in runs]
        for ok, marker in ((True, "o"), (False, "x")):
            pts = [(s, p) for s, p, r in runs if r == ok]
            if pts:
                ax.scatter(*zip(*pts), marker=marker, color="C%d" % i,
                           label=label + ("" if ok else ", not at rest"))
        print("%-36s steps %6d-%6d  primary %.2f (range %.2f)  at rest %d of %d" % (
            label, min(steps), max(steps), sum(pf) / len(pf), max(pf) - min(pf), sum(rest), len(rest)))
    ax.set_xlabel("steps to rest (x: to the end of the run, not at rest)")
    ax.set_ylabel("primary fabric, % of the volume")
    ax.set_title("DA Cu 2.5, side 7.7, seeds 1-3: damping while loading")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    fig.tight_layout()
    png = os.path.join(os.path.dirname(os.path.abspath(a.table)), "damping_chart.png")
    fig.savefig(png, dpi=120)
    print("wrote", png)


if __name__ == "__main__":
    main()
