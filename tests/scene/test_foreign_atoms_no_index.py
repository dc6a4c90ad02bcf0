#!/usr/bin/python3
"""Scene test: atoms that fix sequential/pack did not insert have f_ID 0.

The fix's per-atom interval index is 1..N for its own spheres and 0 for any
other atom. This scene packs a small specimen, deletes the spheres of a top
slab (so per-atom slots are freed), adds spheres with create_atoms into the
slab (they take freed slots) and dumps: the new atoms must show 0, not an
index left behind by a deleted sphere, and the remaining packed spheres keep
their indices.
"""

import os

import numpy as np

import scene_util as su

EDGE = 3.5e-3      # container edge (m)
SLAB = 3.0e-3      # spheres with centres above this z are deleted
INTERVALS = 20
FIX = "pack"
NEW = [(0.8e-3, 0.8e-3, 3.3e-3), (1.75e-3, 1.75e-3, 3.3e-3),
       (2.7e-3, 2.7e-3, 3.3e-3)]   # the added spheres (radius 0.1 mm)


def scene(psd, before, after):
    text = su.header(EDGE)
    text += su.block_region("container", (0, 0, 0), (EDGE, EDGE, EDGE))
    text += ("fix             %s all sequential/pack psd %s porosity 0.4 "
             "arrangement layerwise region container seed 3 verbose no\n"
             % (FIX, psd))
    text += su.MATERIALS
    text += su.dump_lines("d0", before, FIX)
    text += "run             0\nundump          d0\n"
    text += su.block_region("slab", (0, 0, SLAB), (EDGE, EDGE, EDGE))
    text += "delete_atoms    region slab compress no\n"   # keep the IDs
    for x, y, z in NEW:
        text += "create_atoms    1 single %s %s %s units box\n" % (
            su.num(x), su.num(y), su.num(z))
    text += "set             region slab diameter 2e-4 density 2650\n"
    text += su.dump_lines("d1", after, FIX)
    text += "run             0\n"
    return text


def main():
    args = su.parse_args(__doc__)
    chk = su.Checker()
    psd = os.path.join(args.source, "input_scripts", "psd", "cu2.5.txt")
    root = su.fresh_dir(os.path.join(args.work, "foreign_atoms"))
    before = os.path.join(root, "packed.dump")
    after = os.path.join(root, "edited.dump")
    inp = su.write_file(os.path.join(root, "in.foreign"),
                        scene(psd, before, after))
    res = su.run_launcher(args, inp)
    ok = chk.check("pack, delete a slab, create_atoms, run 0 (%.1f s)"
                   % res.seconds, res.returncode == 0 and not res.errors()
                   and os.path.isfile(after), res.describe())
    if not ok:
        chk.finish()
    packed, edited = su.last_snapshot(before), su.last_snapshot(after)
    col = "f_" + FIX
    z = edited.col("z")
    k = edited.col(col)
    new = z > SLAB
    chk.check("the %d created atoms are in the slab (found %d)"
              % (len(NEW), int(new.sum())), int(new.sum()) == len(NEW))
    chk.check("created atoms have %s = 0 (found %s)"
              % (col, ", ".join("%g" % v for v in k[new])),
              new.any() and np.all(k[new] == 0))
    old = packed.by_id()
    kcol = packed.columns.index(col)
    ids = edited.col("id", int)[~new]
    kept = np.array([float(old[i][kcol]) for i in ids if i in old])
    chk.check("the remaining packed spheres keep their index 1..%d"
              % INTERVALS, len(kept) == len(ids) and len(kept) > 0
              and np.array_equal(kept, k[~new])
              and np.all((kept >= 1) & (kept <= INTERVALS)))
    chk.finish()


if __name__ == "__main__":
    main()
