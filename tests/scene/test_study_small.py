#!/usr/bin/python3
"""Scene test, label `study`: the physics regression test of the small
study (tools/oedometer_study.py --small: both arrangements x Cu 2.0 and
2.5, seed 1, side 3.3, 1,100-4,200 grains, two runs at a time). Each run is
checked against the paper's qualitative findings that our model reproduces
(docs/validation.md lists them, and the ones it does not), so a regression
in the packer, the scene or the compute shows. What the study's tools make
of the runs (the driver's resume, tools/validation_report.py,
tools/fabric_layers.py) is tests/scene/test_study_tools.py, on runs too
short to be at rest.

1. The driver writes one CSV row per run, and every run ends at rest (the
   scene's stop rule) with the lid stress within 5 % of 100 kPa.
2. Before loading, under 20 % of the grains are loose (the paper, Sec.
   3.1: "initially under 20 %"; the packer's geometric contacts).
3. Under load most grains carry nothing: more than half are loose by
   number (the paper: "only a few particles transferring the load"). The
   bound is what every model of the study meets, not this size's figure:
   side 3.3 gives 84-99.6 % loose, but the converged Cu 2.0 models (side
   7.7, docs/validation.md) sit at 63-67 %, so a tighter bound would test
   the small specimen, not the finding.
4. The loose grains are the fine ones: the primary fabric's share of the
   mass is at least 1.5 times its share of the number of grains.
5. Fig. 19: the primary % of an interval's own mass grows with size - the
   coarsest quarter of the non-empty intervals holds on average at least
   20 points more of its mass in the primary fabric than the finest
   quarter.
6. Fines in the primary fabric (the paper: "regardless of the PSD and
   structural arrangement, particles of the fines fraction have always been
   included in the primary fabric"): some of the finest quarter's mass is
   primary.
7. An overlapping zone exists (Table 2): r1 < r2, and the OZ holds at least
   half of the mass.

Not checked because our model does not reproduce them at this size and
these seeds (docs/validation.md): LA above DA, primary mass falling with Cu
(the latter is reproduced at side 5.5 at one stiffness number and checked
by tests/scene/test_study_trend.py).
"""
import csv
import os
import subprocess

import numpy as np

import scene_util as su
outputs = su.outputs


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    driver = os.path.join(args.source, "tools", "oedometer_study.py")
    cmd = ["/usr/bin/python3", driver, "--small", "--jobs", "2", "--out", args.work]
    p = subprocess.run(cmd, cwd=args.source, capture_output=True, text=True, timeout=800)
    print(p.stdout[-3000:], p.stderr[-3000:])
    chk.check("the driver exits 0 (got %d)" % p.returncode,
                  p.returncode == 0)
    csv_path = os.path.join(args.work, "study.csv")
    rows = list(csv.DictReader(open(csv_path))) if os.path.exists(csv_path) else []
    chk.check("4 CSV rows (both rules x Cu 2.0, 2.5), got %d" % len(rows),
                  len(rows) == 4)
    for row in rows:
        name = row["name"]
        rundir = os.path.join(args.work, "runs", name)
        chk.check("%s ends at rest" % name,
                  row["at_rest"] == "yes")
        stress = float(row["lid_stress_Pa"])
        chk.check("%s: lid stress %.0f Pa within 5 %% of 100 kPa"
                  % (name, stress),
                  abs(stress - 1e5) <= 5e3)
        series = su.outputs.read_series(os.path.join(rundir, "fabric_series.txt"))
        loose0 = series["loose_number_pct"][0]
        chk.check("%s: %.1f %% loose before loading (< 20 %%)" % (name, loose0),
                  series["step"][0] == 0 and loose0 < 20)
        loose = float(row["loose_number_pct"])
        primary_mass = float(row["primary_mass_pct"])
        chk.check("%s: %.1f %% loose by number under load (> 50 %%)" % (name, loose),
                  loose > 50)
        chk.check("%s: primary %.1f %% by mass >= 1.5 x %.1f %% by number"
                  % (name, primary_mass, 100 - loose),
                  primary_mass >= 1.5 * (100 - loose))
        iv = outputs.read_intervals(os.path.join(rundir, "fabric_intervals.txt"), args.source)
        share = iv["primary_percent_of_interval"][iv["particles"] > 0]   # fine to coarse
        q = max(1, len(share) // 4)
        fine, coarse = share[:q].mean(), share[-q:].mean()
        chk.check("%s: primary %% of own mass, coarsest quarter %.1f vs finest quarter %.1f "
                  "(>= 20 points more)" % (name, coarse, fine),
                  coarse >= fine + 20)
        chk.check("%s: fines in the primary fabric (finest quarter %.2f %% primary)"
                  % (name, fine),
                  fine > 0)
        v = outputs.read_global(os.path.join(rundir, "fabric_global.txt"), args.source)
        at = outputs.index(outputs.fabric_vector(args.source))
        if not chk.check("%s: fabric_global.txt holds the compute's vector" % name, v is not None):
            continue
        r1, r2, oz = (v[at[k]] for k in ("r1", "r2", "overlapping_zone_percent"))
        chk.check("%s: overlapping zone r1 %.3g < r2 %.3g m holding %.1f %% (>= 50 %%)"
                  % (name, r1, r2, oz),
                  r1 < r2 and oz >= 50)
    chk.finish()


if __name__ == "__main__":
    main()
