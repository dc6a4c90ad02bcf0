#!/usr/bin/python3
"""Where the kinetic energy of an oedometer run sits: in a creep (the mean
velocity of each height slice, the specimen still compacting) or in the
grains' motion about it; in the primary fabric or in the loose grains.

    /usr/bin/python3 tools/kinetic_energy.py DUMP [--slices 10]

DUMP is a LAMMPS text dump with the columns id, z, mass, vx, vy, vz (and
c_pf[2], the class of compute primary/fabric, for the split by class):
a run's final.dump, or a checkpoint written out by

    read_restart    RUN/checkpoint.restart
    write_dump      all custom ke.dump id type x y z radius mass vx vy vz

(in a script with the scene's atom_style granular, atom_modify map array,
communicate single vel yes and newton off). The last complete snapshot is
read, its columns by name (tools/outputs.py). The translational kinetic
energy 1/2 m v^2 is what the scene's stop compares with its limit
1/2 M ke_vrms^2; it is split exactly into the energy of each
slice's mass-weighted mean velocity and of the velocities about it. A
specimen that creeps shows a mean upward speed falling from the lid (the
floor of the container) to the fixed top wall.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import outputs  # noqa: E402  (the one reader of the scene's outputs)


def split(cols, nslices):
    """(rows per slice (lo, hi, mass share, mean vz, rms speed), total KE,
    KE of the slice means, KE about them)."""
    for need in ("z", "mass", "vx", "vy", "vz"):
        if need not in cols:
            raise ValueError("the dump has no column %s" % need)
    z, m = cols["z"], cols["mass"]
    v = np.column_stack([cols["vx"], cols["vy"], cols["vz"]])
    ke = 0.5 * m * (v ** 2).sum(axis=1)
    edges = np.linspace(z.min(), z.max(), nslices + 1)
    which = np.clip(np.searchsorted(edges, z, side="right") - 1, 0, nslices - 1)
    rows, about = [], 0.0
    for k in range(nslices):
        s = which == k
        if not s.any():
            continue
        vm = (m[s, None] * v[s]).sum(axis=0) / m[s].sum()
        about += 0.5 * (m[s] * ((v[s] - vm) ** 2).sum(axis=1)).sum()
        rows.append((edges[k], edges[k + 1], m[s].sum() / m.sum(), vm[2],
                     np.sqrt(2.0 * ke[s].sum() / m[s].sum())))
    return rows, ke.sum(), ke.sum() - about, about


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("dump")
    ap.add_argument("--slices", type=int, default=10)
    a = ap.parse_args()
    if a.slices < 1:
        sys.exit("--slices %d: use 1 or more" % a.slices)
    cols = outputs.dump_last(a.dump)
    rows, total, creep, about = split(cols, a.slices)
    m = cols["mass"]
    print("%d grains, mass %.6g, kinetic energy %.4g J (rms speed %.3g m/s)"
          % (len(m), m.sum(), total, np.sqrt(2.0 * total / m.sum())))
    print("%.4g J (%.0f %%) in the mean velocity of %d height slices, %.4g J "
          "(%.0f %%) about it" % (creep, 100.0 * creep / total, a.slices,
                                  about, 100.0 * about / total))
    print("slice (z from, to in m) | mass % | mean vz (m/s) | rms speed (m/s)")
    for lo, hi, share, vz, vrms in rows:
        print("%.6g %.6g | %.1f | %+.3g | %.3g" % (lo, hi, 100.0 * share, vz, vrms))
    if outputs.PRIMARY in cols:
        v2 = cols["vx"] ** 2 + cols["vy"] ** 2 + cols["vz"] ** 2
        mm = outputs.material_mass(cols)   # the shares of the soil's mass
        for label, s in (("primary", cols[outputs.PRIMARY] > 0.5),
                         ("loose", cols[outputs.PRIMARY] <= 0.5)):
            if s.any():
                k = 0.5 * (m[s] * v2[s]).sum()
                print("%s: %d grains, %.1f %% of the mass, %.1f %% of the kinetic "
                      "energy, rms speed %.3g m/s" % (label, s.sum(),
                                                      100.0 * mm[s].sum() / mm.sum(),
                                                      100.0 * k / total,
                                                      np.sqrt(2.0 * k / m[s].sum())))


if __name__ == "__main__":
    main()
