#!/usr/bin/python3
"""Primary fabric by height: where in an oedometer specimen the primary
fabric lies, layer by layer from the floor to the lid.

    /usr/bin/python3 tools/fabric_layers.py RUN_OR_DUMP [RUN_OR_DUMP ...]

Each argument is a run folder of tools/oedometer_study.py (its final.dump
is read) or a dump file with the columns id, x, y, z, radius, mass and the
classification c_pf[2] (1 primary, 0 loose) of compute primary/fabric, as
input_scripts/in.oedometer writes them. The last complete snapshot is
used, its columns by the names of its column line (tools/outputs.py).

Heights are counted from the lowest grain's bottom, in coarsest diameters
d_N (twice the largest radius). A grain belongs to the layer of its centre.
The layers: the two half diameters on the floor, the interior (one d_N
from the floor and from the top), and the two half diameters under the
top. For each: grains, its share of the mass, the primary fabric's share
of its mass, and its mass-weighted mean diameter over d_N (a layer of
fines shows as a small value). Then the specimen without its lowest half
diameter, where a layer-wise specimen keeps its fines (docs/validation.md);
the core, the grains whose centres lie one d_N or more from every wall
(the side walls too, found from the grains' extent in x and y), away from
every wall layer; and the whole specimen.

With --slices N, the specimen is cut instead into N slices of equal height
from the floor to the top, and each slice also gives its fines: the grains
finer than the specimen's d15 by mass (the finest 15 % of the mass, three of
the paper's 20 intervals), their share of the specimen's fines and the
primary share of their mass. In a layered specimen the fines should carry
load where they form a layer of their own (docs/validation.md). --csv FILE
writes the rows of every argument to one CSV.

Each slice's anisotropies of Figs. 15-16, a_c of the contact normals and
a_n of the normal forces, are compute primary/fabric's own: with the
keyword `slices N` it reports its figures per height slice, the same N
equal slices of the grains' extent, each grain in the slice of its centre
(its loaded contacts enter the slice's tensors, half a contact per end),
and the classification the whole specimen's. They are read from the run's
fabric_global.txt (the compute's global vector, by the names of
compute_primary_fabric/fabric_outputs.h through tools/outputs.py); a run
whose compute had no `slices N` (N as asked) gives none ("-", an empty CSV
field, and a note). Where the compute's slices are there, the grains, mass
and primary shares of each slice are the compute's too (the dump's must
agree); the mean diameter and the fines are the dump's. One tensor over a
layered specimen mixes the fines' many contacts with the coarse grains'
large forces; the slices show each layer's own.
"""
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import outputs  # noqa: E402  (the one reader of the scene's outputs)


def heights(cols):
    """(radius, mass, primary mask, d_N, height of each centre and of the
    top, in d_N from the lowest grain's bottom)."""
    z, r, m = cols["z"], cols["radius"], outputs.material_mass(cols)
    dn = 2.0 * r.max()
    floor = (z - r).min()
    return (r, m, cols[outputs.PRIMARY] > 0.5, dn, (z - floor) / dn,
            ((z + r).max() - floor) / dn)


def layers(cols):
    """Rows (label, lo, hi, grains, mass %, primary % of its mass,
    mean diameter / d_N; None for a layer without grains), heights in d_N
    from the floor."""
    for need in ("z", "radius", "mass", outputs.PRIMARY):
        if need not in cols:
            raise ValueError("the dump has no column %s" % need)
    for need in ("x", "y"):
        if need not in cols:
            raise ValueError("the dump has no column %s" % need)
    r, m, primary, dn, h, top = heights(cols)
    cuts = [("floor, first half d_N", 0.0, 0.5),
            ("floor, second half d_N", 0.5, 1.0),
            ("interior", 1.0, top - 1.0),
            ("top, second half d_N", top - 1.0, top - 0.5),
            ("top, first half d_N", top - 0.5, np.inf),
            ("all but the lowest half d_N", 0.5, np.inf),
            ("core, 1 d_N from every wall", 1.0, top - 1.0),
            ("whole specimen", -np.inf, np.inf)]
    side = np.ones(len(r), dtype=bool)
    for c in (cols["x"], cols["y"]):
        lo_w, hi_w = (c - r).min(), (c + r).max()
        side &= (c - lo_w >= dn) & (hi_w - c >= dn)
    out = []
    for label, lo, hi in cuts:
        g = (h >= lo) & (h < hi)
        if label.startswith("core"):
            g &= side
        mass = m[g].sum()
        out.append((label, max(lo, 0.0), min(hi, top), int(g.sum()),
                    100.0 * mass / m.sum(),
                    100.0 * m[g & primary].sum() / mass if mass > 0 else None,
                    (m[g] * 2.0 * r[g]).sum() / mass / dn if mass > 0 else None))
    return out, top


def compute_slices(vector, n, source=outputs.ROOT):
    """The height slices of compute primary/fabric in its global vector (the
    31 entries, 2 per direction bin, then the entries of
    FABRIC_SLICE_ENTRIES per slice): a list of n {entry name: value}, the
    lowest slice first, or None unless the vector holds n slices. The
    direction bins' count follows from the length; the slices must join
    (each one's top the next one's bottom) and hold the group's grains."""
    fixed = len(outputs.fabric_vector(source))
    entries = outputs.read_table(os.path.join(source, outputs.FABRIC_HEADER),
                                 "FABRIC_SLICE_ENTRIES")
    k = len(entries)
    if vector is None:
        return None
    rest = len(vector) - fixed - k * n
    if rest < 2 or rest % 2:
        return None
    first = fixed + rest
    rows = [{e.name: float(vector[first + s * k + e.position - 1]) for e in entries}
            for s in range(n)]
    joined = all(abs(a["slice_top"] - b["slice_bottom"])
                 <= 1e-9 * max(1.0, abs(b["slice_bottom"])) for a, b in zip(rows, rows[1:]))
    whole = outputs.index(outputs.fabric_vector(source))["particles"]
    grains = sum(r["slice_particles"] for r in rows)
    if not joined or rows[0]["slice_bottom"] >= rows[-1]["slice_top"] \
            or abs(grains - vector[whole]) > 0.5:
        return None
    return rows


def share(value, form, none="-"):
    """A share as text: form, or `none` where there is nothing to share."""
    return none if value is None else form % value


def slices(cols, n, computed=None):
    """Rows (lo, hi, grains, mass %, primary %, d_mean/d_N, fines % of the
    specimen's fines mass, primary % of the slice's fines mass, a_c, a_n),
    heights in d_N from the floor, n slices of equal height. With
    `computed` (compute_slices: the compute's own slices) the grains, mass
    and primary shares and a_c, a_n are the compute's; without, a_c and a_n
    are None and the rest is the dump's. A share of nothing (a slice
    without grains, fines or loaded contacts) is None. ValueError if the
    compute's slices hold other grains than the dump's."""
    r, m, primary, dn, h, top = heights(cols)
    d = 2.0 * r
    order = np.argsort(d)
    cum = np.cumsum(m[order]) / m.sum()
    d15 = d[order][np.searchsorted(cum, 0.15)]
    fine = d <= d15
    edges = np.linspace(0.0, top, n + 1)
    out = []
    for k in range(n):
        g = (h >= edges[k]) & ((h < edges[k + 1]) if k < n - 1 else (h <= top))
        mass = m[g].sum()
        fm = m[g & fine].sum()
        grains, mass_pct = int(g.sum()), 100.0 * mass / m.sum()
        prim = 100.0 * m[g & primary].sum() / mass if mass > 0 else None
        a_c = a_n = None
        if computed is not None:
            c = computed[k]
            if int(round(c["slice_particles"])) != grains:
                raise ValueError("slice %d: the compute counts %d grains, the dump %d "
                                 "(not the same state?)" % (k + 1, c["slice_particles"], grains))
            mass_pct = c["slice_mass_percent"]
            if grains:
                prim = c["slice_primary_percent"]
            if c["slice_fabric_contacts"] > 0:
                a_c, a_n = c["slice_fabric_anisotropy"], c["slice_force_anisotropy"]
        out.append((edges[k], edges[k + 1], grains, mass_pct, prim,
                    (m[g] * d[g]).sum() / mass / dn if mass > 0 else None,
                    100.0 * fm / m[fine].sum(),
                    100.0 * m[g & fine & primary].sum() / fm if fm > 0 else None,
                    a_c, a_n))
    return out, top, d15 / dn


def main():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                formatter_class=argparse.RawDescriptionHelpFormatter)
    p.add_argument("paths", nargs="+", metavar="RUN_OR_DUMP")
    p.add_argument("--slices", type=int, metavar="N",
                   help="N slices of equal height instead of the wall layers, with the fines")
    p.add_argument("--csv", metavar="FILE", help="with --slices: write the rows to this CSV")
    args = p.parse_args()
    if args.slices is not None and args.slices < 1:
        sys.exit("fabric_layers: --slices %d: give one slice or more" % args.slices)
    if args.csv and args.slices is None:
        sys.exit("fabric_layers: --csv needs --slices")
    csv_rows = []
    for path in args.paths:
        dump = os.path.join(path, "final.dump") if os.path.isdir(path) else path
        if not os.path.isfile(dump):
            sys.exit("fabric_layers: no dump at %s (give a run folder with final.dump "
                     "or a dump file)" % dump)
        try:
            cols = outputs.dump_last(dump)
            rows, top = layers(cols)
            if args.slices:
                gpath = os.path.join(os.path.dirname(dump), "fabric_global.txt")
                computed = compute_slices(outputs.read_global(gpath), args.slices)
                srows, top, d15 = slices(cols, args.slices, computed)
        except ValueError as e:
            sys.exit("fabric_layers: %s: %s" % (dump, e))
        if args.slices:
            name = os.path.basename(os.path.normpath(path))
            print("# %s: height %.2f coarsest diameters; fines: finer than d15 = %.3f d_N"
                  % (dump, top, d15))
            if computed is None:
                print("# a_c, a_n: none; %s holds no %d height slices of compute "
                      "primary/fabric (define it with 'slices %d')"
                      % (gpath, args.slices, args.slices))
            print("%13s %8s %7s %9s %10s %9s %11s %6s %6s" % ("height/d_N", "grains", "mass%",
                  "primary%", "d_mean/d_N", "fines%", "fines_prim%", "a_c", "a_n"))
            for lo, hi, n, mass, prim, dm, fsh, fprim, a_c, a_n in srows:
                print("%6.2f-%-6.2f %8d %7.2f %9s %10s %9.2f %11s %6s %6s"
                      % (lo, hi, n, mass, share(prim, "%.2f"), share(dm, "%.3f"), fsh,
                         share(fprim, "%.2f"), share(a_c, "%.3f"), share(a_n, "%.3f")))
                csv_rows.append((name, "%.3f" % lo, "%.3f" % hi, str(n), "%.3f" % mass,
                                 share(prim, "%.3f", ""), share(dm, "%.4f", ""),
                                 "%.3f" % fsh, share(fprim, "%.3f", ""),
                                 share(a_c, "%.4f", ""), share(a_n, "%.4f", "")))
            continue
        print("# %s: height %.2f coarsest diameters" % (dump, top))
        print("%-28s %13s %8s %7s %10s %9s" % ("layer", "height/d_N", "grains",
                                             "mass%", "primary%", "d_mean/d_N"))
        for label, lo, hi, n, mass, prim, dm in rows:
            print("%-28s %6.2f-%-6.2f %8d %7.2f %10s %9s"
                  % (label, lo, hi, n, mass, share(prim, "%.2f"), share(dm, "%.3f")))
    if args.csv:
        with open(args.csv, "w") as f:
            f.write("run,height_lo_dN,height_hi_dN,grains,mass_pct,primary_pct,"
                    "d_mean_over_dN,fines_share_pct,fines_primary_pct,"
                    "fabric_anisotropy,force_anisotropy\n")
            for row in csv_rows:
                f.write(",".join(row) + "\n")


if __name__ == "__main__":
    main()
