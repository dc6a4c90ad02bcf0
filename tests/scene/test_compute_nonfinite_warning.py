#!/usr/bin/python3
"""Scene test: compute primary/fabric warns when the state holds non-finite
positions or forces instead of silently reporting every particle loose.

Two coincident spheres (what a specimen inserted twice gives) make the
granular pair force NaN; the compute then classed all particles as loose
without a word. Checked:
  * a column of spheres with one sphere duplicated at the same centre: the
    run (run 0, then 2 steps) prints a WARNING from the compute that names
    the non-finite positions or forces, once per run, and does not crash;
  * the same column without the duplicate: no such warning (and the column
    is classified as before: particles 3, none loose (each overlaps a
    neighbour by 0.02 mm and min_contacts is 1), the thermo line finite).
"""
import math
import os

import scene_util as su

# the thermo keywords of compute pf's global vector printed, by the names of
# fabric_outputs.h
_AT = su.outputs.index(su.outputs.fabric_vector())
PF = {name: "c_pf[%d]" % (_AT[name] + 1)
      for name in ("particles", "loose_particles", "contacts", "mean_normal_force")}
THERMO = "thermo_style custom step " + " ".join(PF.values())

SCENE = """\
{preamble}region box block -0.01 0.01 -0.01 0.01 -0.001 0.008 units box
create_box 1 box
neigh_modify delay 0
fix m1 all property/global kn peratomtypepair 1 2e7
fix m2 all property/global kt peratomtypepair 1 2e7
fix m3 all property/global gamman peratomtypepair 1 1e3
fix m4 all property/global gammat peratomtypepair 1 1e3
fix m5 all property/global coefficientFriction peratomtypepair 1 0.4
pair_style gran model hooke/stiffness tangential history
pair_coeff * *
create_atoms 1 single 0 0 0.00099 units box
create_atoms 1 single 0 0 0.00297 units box
create_atoms 1 single 0 0 0.00495 units box
{duplicate}
set atom * diameter 0.002 density 2650
compute pf all primary/fabric intervals 1 min_contacts 1
fix nve all nve/sphere
timestep 1e-8
{thermo}
run 0
run 2
print "RUN COMPLETED"
"""

DUPLICATE = "create_atoms 1 single 0 0 0.00297 units box"


def main():
    args = su.parse_args(__doc__)
    chk = su.Checker()
    for name, dup in (("duplicate", DUPLICATE), ("clean", "")):
        d = su.fresh_dir(os.path.join(args.work, name))
        inp = su.write_file(os.path.join(d, "in.scene"), SCENE.format(
            preamble=su.preamble(), duplicate=dup, thermo=THERMO))
        res = su.run_launcher(args, inp)
        chk.check("%s: runs to the end (%.1f s)" % (name, res.seconds),
                  res.returncode == 0 and not res.errors() and not
                  res.crashed() and "RUN COMPLETED" in res.output,
                  res.describe())
        warnings = [l for l in res.output.splitlines()
                    if l.startswith("WARNING: Compute primary/fabric")
                    and "non-finite" in l]
        if dup:
            chk.check("%s: a WARNING about non-finite positions or forces, "
                      "once per run (2 runs, %d warnings)"
                      % (name, len(warnings)), len(warnings) == 2 and
                      "positions or forces" in warnings[0], res.describe())
            if warnings:
                chk.note(warnings[0].strip())
        else:
            chk.check("%s: no non-finite warning" % name, not warnings,
                      "\n".join(warnings))
            row = su.outputs.thermo_row(res.output, THERMO, 0)
            chk.check("%s: step 0 thermo: 3 particles, none loose, finite values (%s)"
                      % (name, row), row is not None and row[PF["particles"]] == 3
                      and row[PF["loose_particles"]] == 0
                      and all(math.isfinite(v) for v in row.values()),
                      res.describe())
    chk.finish()


if __name__ == "__main__":
    main()
