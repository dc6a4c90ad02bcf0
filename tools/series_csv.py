#!/usr/bin/python3
"""Rows of the scene's fabric_series.txt, read by name (tools/outputs.py),
as one CSV on stdout: case, step, kinetic energy, block-mean lid stress,
its rms error, loose % by number, primary % by mass.

    /usr/bin/python3 tools/series_csv.py whole=out/a/fabric_series.txt jobs=out/b/fabric_series.txt [--from 4000]
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import outputs  # noqa: E402

COLUMNS = [("step", "step"), ("ke_translation", "ke_translation_J"),
           ("lid_stress", "lid_stress_block_mean_Pa"), ("stress_error_rms", "stress_error_block_rms"),
           ("loose_number_pct", "loose_number_pct"), ("primary_mass_pct", "primary_mass_pct")]


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("cases", nargs="+", metavar="CASE=SERIES")
    ap.add_argument("--from", dest="first", type=int, default=0, help="rows from this step on")
    a = ap.parse_args()
    w = csv.writer(sys.stdout, lineterminator="\n")
    w.writerow(["case"] + [out for _, out in COLUMNS])
    for case in a.cases:
        name, path = case.split("=", 1)
        s = outputs.read_series(path)
        for k in range(len(s["step"])):
            if s["step"][k] >= a.first:
                w.writerow([name, "%d" % s["step"][k]] + ["%g" % s[n][k] for n, _ in COLUMNS[1:]])


if __name__ == "__main__":
    main()
