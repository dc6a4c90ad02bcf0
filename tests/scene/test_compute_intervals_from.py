#!/usr/bin/python3
"""Scene test: compute primary/fabric takes each grain's size interval from
fix sequential/pack (intervals_from FIX-ID), with the diameter as the
fallback for atoms the fix did not create (issue 8, item 3).

A small specimen is packed in 2 intervals; then every grain of interval 1 is
deleted, as when rounding the counts leaves an interval empty. Without
intervals_from the compute sees 1 distinct diameter for 2 intervals and
stops; with it, every packed grain keeps the fix's index (c_pf[3] ==
f_pack), interval 1 is an empty row and interval 2 holds them all. An atom
added with create_atoms (f_pack 0) and the diameter of interval 2 is placed
by its diameter into interval 2; one whose diameter no interval of the fix
holds stops the run naming intervals_from. An intervals setting below the
fix's stops the run naming the stored index.
"""
import os

import scene_util as su

EDGE = 4e-3

# the thermo keywords of compute pf's outputs read here, by the names of
# fabric_outputs.h: particles (global vector), and an interval's particles
# and diameter (global array, row = interval)
_ARRAY = su.outputs.index(su.outputs.fabric_array())
PARTICLES = "c_pf[%d]" % (su.outputs.index(su.outputs.fabric_vector())["particles"] + 1)


def in_interval(interval, name):
    return "c_pf[%d][%d]" % (interval, _ARRAY[name] + 1)


THERMO = "thermo_style    custom step atoms %s %s %s %s" % (
    PARTICLES, in_interval(1, "particles"), in_interval(2, "particles"),
    in_interval(1, "diameter"))


def scene(args, compute, extra_atom_diameter=None):
    psd = os.path.join(su.DATA_DIR, "psd_ok_small.txt")
    text = su.header((EDGE, EDGE, 2 * EDGE))
    text += su.block_region("container", (0, 0, 0), (EDGE, EDGE, EDGE))
    text += ("fix             pack all sequential/pack psd %s porosity 0.45 "
             "arrangement discrete region container seed 2 intervals 2 verbose no\n" % psd)
    text += su.MATERIALS
    text += ("compute         prad all property/atom radius\n"
             "compute         rmax all reduce max c_prad\n"
             "thermo_style    custom step atoms c_rmax\n"
             "thermo_modify   format float %.17g\n"
             "run             0\n"
             "variable        dbig equal $(2*c_rmax)\n"
             "variable        small atom c_prad<0.4999999*${dbig}\n"
             "group           small variable small\n"
             "delete_atoms    group small compress no\n")
    if extra_atom_diameter is not None:
        text += ("create_atoms    1 single %s %s %s units box\n"
                 % (su.num(EDGE / 2), su.num(EDGE / 2), su.num(1.6 * EDGE)))
        text += su.block_region("far", (0, 0, 1.3 * EDGE), (EDGE, EDGE, 2 * EDGE))
        text += "set             region far diameter %s density 2650\n" % extra_atom_diameter
    text += compute + "\n"
    text += (THERMO + "\n"
             "dump            d all custom 1 %s id radius f_pack c_pf[3]\n"
             "dump_modify     d sort id\n"
             "run             0\n" % os.path.join(args.work, "intervals.dump"))
    return text


def run(args, name, text):
    inp = su.write_file(os.path.join(args.work, name + ".in"), text)
    return su.run_launcher(args, inp)


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    dump = os.path.join(args.work, "intervals.dump")

    res = run(args, "by_diameter", scene(args, "compute pf all primary/fabric intervals 2"))
    err = res.errors()
    chk.check("without intervals_from: an emptied interval stops the run "
              "('1 distinct particle diameters but intervals 2')",
              err and "1 distinct particle diameters but intervals 2" in err[0],
              "\n".join(err) or res.describe())

    for what, diameter in (("packed grains only", None), ("plus a foreign atom", "${dbig}")):
        if os.path.isfile(dump):
            os.remove(dump)
        res = run(args, "from_fix", scene(args, "compute pf all primary/fabric intervals_from pack intervals 2",
                                          diameter))
        if not chk.check("intervals_from pack, %s: runs" % what,
                         res.returncode == 0 and not res.errors() and os.path.isfile(dump),
                         res.describe()):
            continue
        s = su.last_snapshot(dump)
        fix_index = s.col("f_pack", lambda v: int(float(v)))
        interval = s.col("c_pf[3]", lambda v: int(float(v)))
        packed = fix_index > 0
        chk.check("%s: every packed grain is in the fix's interval (c_pf[3] == f_pack, "
                  "all 2)" % what, packed.sum() > 10 and (interval[packed] == fix_index[packed]).all()
                  and (fix_index[packed] == 2).all(), list(zip(fix_index, interval)))
        if diameter:
            chk.check("the foreign atom (f_pack 0) is placed by its diameter into interval 2",
                      (~packed).sum() == 1 and (interval[~packed] == 2).all(),
                      list(zip(fix_index, interval)))
        rows = [r for r in su.outputs.read_thermo(res.output, THERMO) if r["step"] == 0]
        row = rows[-1] if rows else None
        chk.check("%s: particles 1, interval 1 holds 0 and interval 2 all of them, "
                  "interval 1's diameter 0" % what,
                  row is not None and row["atoms"] == s.natoms and row[PARTICLES] == s.natoms
                  and row[in_interval(1, "particles")] == 0
                  and row[in_interval(2, "particles")] == s.natoms
                  and row[in_interval(1, "diameter")] == 0,
                  row or res.describe())

    res = run(args, "foreign_misfit", scene(args, "compute pf all primary/fabric intervals_from pack intervals 2",
                                            "1.5e-3"))
    err = res.errors()
    chk.check("a foreign atom that no interval of the fix holds: ERROR naming intervals_from",
              err and "fit no size interval of the particles of fix pack (intervals_from)" in err[0],
              "\n".join(err) or res.describe())
    res = run(args, "too_few", scene(args, "compute pf all primary/fabric intervals_from pack intervals 1")
              .replace(THERMO, "thermo_style    custom step atoms " + PARTICLES))
    err = res.errors()
    chk.check("intervals 1 for a fix of 2 intervals: ERROR naming the stored index",
              err and "index 2" in err[0] and "intervals N" in err[0],
              "\n".join(err) or res.describe())
    res = run(args, "no_fix", scene(args, "compute pf all primary/fabric intervals_from nofix intervals 2"))
    err = res.errors()
    chk.check("intervals_from a fix that does not exist: ERROR",
              err and "intervals_from fix ID 'nofix' does not exist" in err[0],
              "\n".join(err) or res.describe())
    chk.finish()


if __name__ == "__main__":
    main()
