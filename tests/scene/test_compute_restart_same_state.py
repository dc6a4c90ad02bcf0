#!/usr/bin/python3
"""Scene test: the same state classifies identically at the end of a run and
at `run 0` after `read_restart` (issue 8, item 1).

Two spheres are pushed along the bottom and top walls by fix addforce and
slide (the friction caps their tangential wall forces); a third rests between
the walls. Every contact's normal force is 200 N. After read_restart the
walls' tangential history is gone (see below), so LIGGGHTS' first force
evaluation gives each sliding wall contact a tangential damping force
without the friction cap, several times the normal force. The compute must
not care: a contact's normal force is F.n with the true contact normal
(store_force_contact_stress), for walls as for particles. With |F| standing
for the wall's normal force (the old definition) the mean normal force
went from 210 to 619 N and two of the three spheres changed class under
`force_threshold absolute 250`.

Checked: global vector entries 1-14 of two computes (relative and absolute
threshold) and the per-atom loaded contacts and classes, end of run vs run 0
after read_restart, on 1 rank and on 2 ranks.

The writing run unfixes the walls before write_restart: LIGGGHTS 3.8 cannot
read back the per-atom restart data of a primitive wall's
store_force_contact_stress storage (it stops with "Contact history overflow"
or corrupts the heap); input_scripts/in.oedometer does the same.
"""
import os

import scene_util as su

MATERIAL = """\
neigh_modify    delay 0
fix m1 all property/global kn peratomtypepair 2 2e7 2e7 2e7 2e7
fix m2 all property/global kt peratomtypepair 2 2e7 2e7 2e7 2e7
fix m3 all property/global gamman peratomtypepair 2 1e3 1e3 1e3 1e3
fix m4 all property/global gammat peratomtypepair 2 1e3 1e6 1e6 1e6
fix m5 all property/global coefficientFriction peratomtypepair 2 0.4 0.4 0.4 0.4
pair_style      gran model hooke/stiffness tangential history
pair_coeff      * *
"""

ANALYSIS = """\
fix wb all wall/gran model hooke/stiffness tangential history primitive type 2 zplane 0.0 store_force_contact_stress yes
fix wt all wall/gran model hooke/stiffness tangential history primitive type 2 zplane 0.00198 store_force_contact_stress yes
compute pf all primary/fabric min_contacts 2 intervals 1
compute pfa all primary/fabric min_contacts 2 intervals 1 force_threshold absolute 250
fix nve all nve/sphere
timestep 1e-8
thermo_style custom step {fields}
thermo_modify format float %.17g
thermo {every}
dump d all custom {every} {dump} id c_pf[1] c_pf[2] c_pfa[1] c_pfa[2]
dump_modify d sort id
"""

FIELDS = ["c_%s[%d]" % (c, i) for c in ("pf", "pfa") for i in range(1, 15)]
_AT = su.outputs.index(su.outputs.fabric_vector())


def entry(compute, name):
    """The thermo keyword of entry `name` (fabric_outputs.h) of a compute."""
    return "c_%s[%d]" % (compute, _AT[name] + 1)

WRITE = """\
{preamble}region box block -0.02 0.02 -0.01 0.01 -0.001 0.004 units box
create_box 2 box
{material}create_atoms 1 single -0.01 0 0.00099 units box
create_atoms 1 single -0.01 0.005 0.00099 units box
create_atoms 1 single 0.005 0 0.00099 units box
set atom * diameter 0.002 density 2650
group sliding id 1 2
fix push sliding addforce 200 0 0
{analysis}run 2000
unfix wb
unfix wt
write_restart {restart}
"""

READ = """\
{preamble}read_restart {restart}
{material}{analysis}run 0
"""


def last_thermo(output):
    """The last thermo row of `step FIELDS`, by keyword, or None."""
    rows = su.outputs.read_thermo(output, ["step"] + FIELDS)
    return rows[-1] if rows else None


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    restart = os.path.join(args.work, "state.restart")
    dump_w = os.path.join(args.work, "end_of_run.dump")
    text = WRITE.format(preamble=su.preamble(), material=MATERIAL,
                        analysis=ANALYSIS.format(fields=" ".join(FIELDS),
                                                 every=2000, dump=dump_w),
                        restart=restart)
    res = su.run_launcher(args, su.write_file(os.path.join(args.work, "in.write"), text))
    if not chk.check("two spheres slide along the walls for 2000 steps; restart written",
                     res.returncode == 0 and os.path.isfile(restart), res.describe()):
        chk.finish()
    end = last_thermo(res.output)
    end_atoms = su.last_snapshot(dump_w)
    chk.check("end of run: every contact loaded under the relative threshold "
              "(6 of 6), all 3 spheres loose under absolute 250 N",
              end and end[entry("pf", "loaded_contacts")] == 6
              and end[entry("pfa", "loose_particles")] == 3, end)

    for nprocs, proc in ((None, ""), (2, "2 1 1")):
        ranks = nprocs or 1
        dump_r = os.path.join(args.work, "after_restart_%d.dump" % ranks)
        text = READ.format(preamble=su.preamble(processors=proc or None),
                           restart=restart, material=MATERIAL,
                           analysis=ANALYSIS.format(fields=" ".join(FIELDS),
                                                    every=1, dump=dump_r))
        r2 = su.run_launcher(args, su.write_file(
            os.path.join(args.work, "in.read_%d" % ranks), text), nprocs=nprocs)
        if not chk.check("read_restart and run 0 on %d rank(s)" % ranks,
                         r2.returncode == 0 and os.path.isfile(dump_r), r2.describe()):
            continue
        after = last_thermo(r2.output)
        diff = []
        for name in FIELDS:
            a, b = end[name], after[name]
            if abs(a - b) > 1e-9 * max(1.0, abs(a)):
                diff.append("%s: end of run %r, after read_restart %r" % (name, a, b))
        chk.check("%d rank(s): global vector entries 1-14 of both computes "
                  "equal at the end of the run and after read_restart" % ranks,
                  not diff, "\n".join(diff))
        s = su.last_snapshot(dump_r)
        same = end_atoms.by_id() == s.by_id()
        chk.check("%d rank(s): per-atom loaded contacts and classes equal, "
                  "both computes" % ranks, same,
                  "end of run %s\nafter read_restart %s" % (end_atoms.by_id(), s.by_id()))
    chk.finish()


if __name__ == "__main__":
    main()
