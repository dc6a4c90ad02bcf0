#!/usr/bin/python3
"""Scene test: compute primary/fabric on hand-built scenes whose answer is
known, and its bad-input errors.

A column of three spheres is squeezed between two walls (each sphere has
two loaded contacts, particles and walls), and a free sphere lies beside
it. With min_contacts 2 the column is primary fabric and the free sphere
loose; with the default min_contacts 3 all four are loose. The same state
on 2 ranks, cut through the column (processors 1 1 2), must classify alike.
"""
import os

import scene_util as su

COLUMN = """\
{preamble}region box block -0.01 0.01 -0.01 0.01 -0.001 0.008 units box
create_box 2 box
neigh_modify delay 0
fix m1 all property/global kn peratomtypepair 2 2e7 2e7 2e7 2e7
fix m2 all property/global kt peratomtypepair 2 2e7 2e7 2e7 2e7
fix m3 all property/global gamman peratomtypepair 2 1e3 1e3 1e3 1e3
fix m4 all property/global gammat peratomtypepair 2 1e3 1e3 1e3 1e3
fix m5 all property/global coefficientFriction peratomtypepair 2 0.4 0.4 0.4 0.4
pair_style gran model hooke/stiffness tangential history
pair_coeff * *
create_atoms 1 single 0 0 0.00099 units box
create_atoms 1 single 0 0 0.00297 units box
create_atoms 1 single 0 0 0.00495 units box
{free}
set atom * diameter 0.002 density 2650
fix wb all wall/gran model hooke/stiffness tangential history primitive type 2 zplane 0.0 store_force_contact_stress yes
fix wt all wall/gran model hooke/stiffness tangential history primitive type 2 zplane 0.00593 store_force_contact_stress yes
{compute}
fix nve all nve/sphere
timestep 1e-8
thermo_style custom step c_pf[1] c_pf[2] c_pf[3] c_pf[4] c_pf[10] c_pf[11]
thermo_modify format float %.10g
dump d all custom 1 {dump} id z c_pf[1] c_pf[2] c_pf[3]
dump_modify d sort id
run 0
"""


FREE = "create_atoms 1 single 0.005 0 0.003 units box"
# A on the bottom wall with B resting on it: B has one loaded contact, A two.
DANGLING = ("create_atoms 1 single 0.005 0 0.00099 units box\n"
            "create_atoms 1 single 0.005 0 0.00297 units box")


def run_column(args, chk, name, compute, nprocs=None, processors="", free=FREE):
    work = args.work
    dump = os.path.join(work, name + ".dump")
    inp = su.write_file(os.path.join(work, "in." + name), COLUMN.format(
        preamble=su.preamble(processors=processors or None), compute=compute, dump=dump, free=free))
    res = su.run_launcher(args, inp, nprocs=nprocs)
    ok = chk.check("%s runs" % name, res.returncode == 0 and os.path.isfile(dump),
                   res.describe())
    if not ok:
        return None
    s = su.last_snapshot(dump)
    return {int(r[0]): (int(float(r[2])), int(float(r[3]))) for r in s.rows}


def expect_error(args, chk, what, text, expect):
    """Runs `text`; it must end with an ERROR (containing `expect`, if given),
    without a crash or a hang."""
    inp = su.write_file(os.path.join(args.work, "in.bad"), text)
    res = su.run_launcher(args, inp, timeout=60)
    err = [l for l in res.text.splitlines() if "ERROR" in l]
    ok = not res.crashed() and not res.timed_out and bool(err)
    if expect:
        ok = ok and expect in err[0]
    chk.check("%s: ERROR%s" % (what, " containing %r" % expect if expect else ""),
              ok, "\n".join(err) or res.describe())


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()

    want = {1: (2, 1), 2: (2, 1), 3: (2, 1), 4: (0, 0)}  # id: (contacts, class)
    one = run_column(args, chk, "column", "compute pf all primary/fabric min_contacts 2 intervals 1")
    if one is not None:
        chk.check("column spheres have 2 loaded contacts and are primary; the "
                  "free sphere has none and is loose", one == want, one)
    three = run_column(args, chk, "column_min3", "compute pf all primary/fabric intervals 1")
    if three is not None:
        chk.check("with min_contacts 3 (the paper's rule) all four are loose",
                  all(c == 0 for (_, c) in three.values()), three)
    two = run_column(args, chk, "column_2ranks",
                     "compute pf all primary/fabric min_contacts 2 intervals 1",
                     nprocs=2, processors="1 1 2")
    if two is not None:
        chk.check("2 ranks cut through the column: same contacts and classes",
                  two == want, two)
    it = run_column(args, chk, "column_iterate_2ranks",
                    "compute pf all primary/fabric min_contacts 2 prune iterate intervals 1",
                    nprocs=2, processors="1 1 2")
    if it is not None:
        chk.check("prune iterate on 2 ranks: the column stays primary (walls hold it)",
                  it == want, it)

    # prune once vs iterate: a dangling pair on the bottom wall (ids 4, 5).
    once = run_column(args, chk, "dangling_once",
                      "compute pf all primary/fabric min_contacts 2 intervals 1",
                      free=DANGLING)
    if once is not None:
        chk.check("prune once: A (wall + B) is primary, B (A only) is loose",
                  once.get(4) == (2, 1) and once.get(5) == (1, 0), once)
    for nprocs, proc in ((None, ""), (2, "1 1 2")):
        itr = run_column(args, chk, "dangling_iterate_%s" % (nprocs or 1),
                         "compute pf all primary/fabric min_contacts 2 prune iterate intervals 1",
                         nprocs=nprocs, processors=proc, free=DANGLING)
        if itr is not None:
            chk.check("prune iterate on %s rank(s): B loose, then A loose too; "
                      "the column stays primary" % (nprocs or 1),
                      itr.get(4, (0, 9))[1] == 0 and itr.get(5, (0, 9))[1] == 0
                      and all(itr[i][1] == 1 for i in (1, 2, 3)), itr)

    # Bad input: each gives an ERROR naming the value or what is allowed.
    base = "compute pf all primary/fabric min_contacts 2 intervals 1"
    cases = [
        ("min_contacts 0", base.replace("min_contacts 2", "min_contacts 0"), "at least 1"),
        ("negative threshold", base + " force_threshold absolute -1", "must not be negative"),
        ("negative relative threshold", base + " force_threshold relative -0.1", "must not be negative"),
        ("unknown threshold mode", base + " force_threshold mean 1", "absolute or relative"),
        ("unknown prune", base + " prune twice", "use once or iterate"),
        ("unknown keyword", base + " colour red", "unknown keyword 'colour'"),
        ("wall fix that does not exist", base + " walls wb nowall", "'nowall' does not exist"),
        ("wall fix that is not a granular wall", base + " walls wb nve", "not a granular wall"),
        ("intervals that do not match the specimen", base.replace("intervals 1", "intervals 3"),
         "1 distinct particle diameters but intervals 3"),
        ("a PSD that does not match the specimen",
         base.replace("intervals 1", "psd %s intervals 5" % os.path.join(su.DATA_DIR, "psd_ok_small.txt")),
         "fit no size interval"),
        ("intervals 0", base.replace("intervals 1", "intervals 0"), "1..100"),
    ]
    dump = os.path.join(args.work, "bad.dump")
    for what, compute, expect in cases:
        expect_error(args, chk, what, COLUMN.format(
            preamble=su.preamble(), compute=compute, dump=dump, free=FREE), expect)

    # A wall without stored contacts, a non-granular style, no pair style.
    variants = [
        ("granular wall without store_force_contact_stress",
         lambda t: t.replace("zplane 0.0 store_force_contact_stress yes", "zplane 0.0"),
         "store_force_contact_stress yes"),
        ("non-granular atom style (checked before the pair style)",
         lambda t: t.replace("atom_style      granular", "atom_style      atomic")
                    .replace("set atom * diameter 0.002 density 2650", "mass * 1")
                    .replace("pair_style gran model hooke/stiffness tangential history\npair_coeff * *\n", "")
                    .split("fix wb")[0] + "{compute}\n".format(compute=base) + "run 0\n",
         "requires atom_style granular"),
        ("no granular pair style before the compute",
         lambda t: t.replace("pair_style gran model hooke/stiffness tangential history\npair_coeff * *\n", "")
                    .replace("fix nve all nve/sphere", "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\nfix nve all nve/sphere"),
         "granular pair style"),
    ]
    for what, change, expect in variants:
        expect_error(args, chk, what, change(COLUMN.format(
            preamble=su.preamble(), compute=base, dump=dump, free=FREE)), expect)
    chk.finish()


if __name__ == "__main__":
    main()
