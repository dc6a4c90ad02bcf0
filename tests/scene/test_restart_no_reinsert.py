#!/usr/bin/python3
"""Scene test: after read_restart, redefining fix sequential/pack with the
same ID neither packs again nor loses the interval indices.

Step 1 packs a small specimen (about 1,000 particles), runs 1 step and
writes a restart file. Step 2 reads it (serially, and again on 2 MPI
ranks), defines the region and the same fix with the same ID, and runs 1
step. The fix restores its state (specimen inserted) and its per-atom
interval index from the restart file, so:
  * the atom count stays the same and no packing happens (no 'packing'
    message, no summary);
  * IDs, positions and radii are those written (no time integration);
  * f_ID is an interval index 1..20 for every atom, in step 1 and after
    the restart, equal per ID.
"""

import os

import numpy as np

import scene_util as su

EDGE = 3.5e-3      # container edge (m): 2 x 1.75 mm
INTERVALS = 20     # the fix's default
FIX = "pack"


def fix_line(psd):
    return ("fix             %s all sequential/pack psd %s porosity 0.4 "
            "arrangement layerwise region container seed 3 verbose no\n"
            % (FIX, psd))


def write_input(psd, dump, restart):
    text = su.header(EDGE)
    text += su.block_region("container", (0, 0, 0), (EDGE, EDGE, EDGE))
    text += fix_line(psd) + su.MATERIALS
    text += su.dump_lines("d1", dump, FIX)
    text += "run             1\nundump          d1\n"
    text += "write_restart   %s\n" % restart
    return text


def read_input(psd, dump, restart):
    # Regions are not in a LIGGGHTS restart file: define the container again.
    text = ("atom_modify     map array\n"
            "read_restart    %s\n"
            "newton          off\n"
            "communicate     single vel yes\n" % restart)
    text += su.block_region("container", (0, 0, 0), (EDGE, EDGE, EDGE))
    text += fix_line(psd) + su.MATERIALS
    text += su.dump_lines("d1", dump, FIX)
    text += "run             1\n"
    return text


def check_intervals(chk, what, snap):
    k = snap.col("f_" + FIX)
    ok = bool(len(k)) and np.all((k == np.round(k)) & (k >= 1)
                                 & (k <= INTERVALS))
    u = np.unique(k)
    chk.check("%s: f_%s is an interval index 1..%d for every atom (values "
              "%s)" % (what, FIX, INTERVALS, ", ".join("%g" % v
                                                       for v in u[:6])
                       + (", ..." if len(u) > 6 else "")), ok)


def main():
    args = su.parse_args(__doc__)
    chk = su.Checker()
    psd = os.path.join(args.source, "input_scripts", "psd", "cu2.5.txt")
    root = su.fresh_dir(os.path.join(args.work, "restart_no_reinsert"))
    restart = os.path.join(root, "specimen.restart")

    dump1 = os.path.join(root, "written.dump")
    inp = su.write_file(os.path.join(root, "in.write"),
                        write_input(psd, dump1, restart))
    res = su.run_launcher(args, inp)
    ok = chk.check("step 1: pack, run 1, write_restart (%.1f s)"
                   % res.seconds, res.returncode == 0 and not res.errors()
                   and os.path.isfile(restart) and os.path.isfile(dump1),
                   res.describe())
    if not ok:
        chk.finish()
    written = su.last_snapshot(dump1)
    summary = su.pack_summary(res.text)
    chk.check("step 1: packed %s, dump has %d atoms"
              % (summary and "%d particles" % summary[1], written.natoms),
              summary is not None and summary[1] == written.natoms > 100)
    check_intervals(chk, "step 1", written)

    for nprocs in (None, 2):
        tag = "serial" if nprocs is None else "%d ranks" % nprocs
        d = su.fresh_dir(os.path.join(root, "read_" + tag.replace(" ", "")))
        dump2 = os.path.join(d, "restarted.dump")
        inp = su.write_file(os.path.join(d, "in.read"),
                            read_input(psd, dump2, restart))
        res = su.run_launcher(args, inp, nprocs=nprocs)
        ok = chk.check("step 2 (%s): read_restart, same fix ID, run 1 "
                       "(%.1f s)" % (tag, res.seconds),
                       res.returncode == 0 and not res.errors()
                       and os.path.isfile(dump2), res.describe())
        if not ok:
            continue
        chk.check("step 2 (%s): the fix restored its state from the restart "
                  "file" % tag,
                  "Resetting global state of Fix %s" % FIX in res.text
                  and "Resetting per-atom state of Fix %s" % FIX in res.text)
        chk.check("step 2 (%s): no packing (no 'packing' message, no "
                  "summary)" % tag,
                  "sequential/pack: packing" not in res.text
                  and su.pack_summary(res.text) is None)
        after = su.last_snapshot(dump2)
        chk.check("step 2 (%s): same atom count (%d written, %d after)"
                  % (tag, written.natoms, after.natoms),
                  after.natoms == written.natoms)
        a, b = written.by_id(), after.by_id()
        chk.check("step 2 (%s): same IDs" % tag, set(a) == set(b))
        common = sorted(set(a) & set(b))
        for name in ("x", "y", "z", "radius", "f_" + FIX):
            ka, kb = written.columns.index(name), after.columns.index(name)
            differ = [i for i in common
                      if float(a[i][ka]) != float(b[i][kb])]
            chk.check("step 2 (%s): %s per ID as written" % (tag, name),
                      common and not differ,
                      differ and "%d differ, first id %d: %s -> %s" % (
                          len(differ), differ[0], a[differ[0]][ka],
                          b[differ[0]][kb]))
        check_intervals(chk, "step 2 (%s)" % tag, after)
    chk.finish()


if __name__ == "__main__":
    main()
