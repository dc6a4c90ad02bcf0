#!/usr/bin/python3
"""What does a *random* packing of a soil give for the size assortativity?

    /usr/bin/python3 bench/random_reference/run.py [--soils cu2.0 cu2.5 ...] [--side 4]
        [--seed 1] [--phi 0.73] [--steps 150000] [--out out/random_reference]
        [--packings discrete layerwise random] [--launcher build/liggghts-fabric]

The size assortativity of touching pairs (fix sequential/pack's `structure`
line, f_ID[10]) is Newman's correlation of ln r over the contacts: 0 when the
ends of the contacts are paired at random whatever the geometry. A packing of
a graded soil is not that: a coarse grain has room for many contacts, most of
them with the numerous fines, and a fine grain in a pore touches the coarse
grains around it. So the value a *random* packing of the soil gives is the
reference for "no arrangement rule" (the discrete arrangement) and for "like
sizes together" (the layer-wise one), and this program measures it.

Per soil it
  1. packs a specimen with fix sequential/pack (discrete and layer-wise,
     porosity 0.35, a cube of SIDE coarsest diameters: in.specimen);
  2. scatters the discrete specimen's grains (the same radii, the same count)
     at random without overlap in a periodic cube at packing fraction 0.25,
     largest first;
  3. compresses them in LIGGGHTS without friction or gravity to packing
     fraction PHI and lets them settle (in.random): a jammed random packing,
     reached by geometry alone;
  4. measures on all three the assortativity of the contacts, for gaps below
     0 (overlapping: the random packing's contacts), 1e-9, 1e-3 and 1e-2 of
     the smaller radius, and the mean number of contacts per grain.
The sequential specimens are measured with their walls (no pair across the
container), the random one across its periodic faces. One CSV row per soil
and packing in OUT/SOIL/assortativity.csv, gathered for every soil in OUT
into OUT/assortativity.csv. Resumable: a packing whose dump exists is
measured again, not run again (delete OUT/SOIL/*.dump to redo it).
--packings measures only those packings (the random one needs the discrete
dump); the rows of the others already in OUT/SOIL/assortativity.csv are
kept, so a change of one rule re-measures that rule alone.
"""
import argparse
import csv
import os
import subprocess
import sys
import time

import numpy as np
from scipy.spatial import cKDTree

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import outputs  # noqa: E402  (the one reader of the project's outputs)
import soils  # noqa: E402  (the shipped soils)

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
HERE = os.path.dirname(os.path.abspath(__file__))
PACKINGS = ("discrete", "layerwise", "random")
LAUNCHER = [os.path.join(ROOT, "build", "liggghts-fabric")]  # --launcher replaces it
TOLS = [None, 1e-9, 1e-3, 1e-2]     # None: overlapping pairs only (gap < 0)
FIELDS = ["soil", "packing", "grains", "porosity", "tol", "contacts", "z_mean",
          "z_contacting", "no_contact_pct", "assortativity"]


def liggghts(script, variables, log):
    cmd = [LAUNCHER[0], "-in", os.path.join(HERE, script), "-log", log + ".lammps"]
    for k, v in variables.items():
        cmd += ["-var", k, str(v)]
    with open(log, "w") as f:
        rc = subprocess.call(cmd, cwd=ROOT, stdout=f, stderr=subprocess.STDOUT)
    if rc != 0:
        with open(log) as f:
            err = [l.strip() for l in f if "ERROR" in l]
        sys.exit("LIGGGHTS failed (%d): %s (see %s)" % (rc, err[0] if err else "no ERROR line", log))


def read_dump(path):
    """(box lo, box hi, radii, positions) of the dump's last snapshot, the
    columns by name (tools/outputs.py reads the dump)."""
    snap = outputs.last_snapshot(path)
    lo = np.array([b[0] for b in snap.box])
    hi = np.array([b[1] for b in snap.box])
    return lo, hi, snap["radius"], np.stack([snap[c] for c in "xyz"], 1)


def contacts(r, p, lo, hi, periodic):
    """All pairs closer than 2 r_max with their gap / smaller radius."""
    box = hi - lo
    q = (p - lo) % box if periodic else p - lo
    tree = cKDTree(q, boxsize=box if periodic else None)
    pr = tree.query_pairs(2.0 * r.max(), output_type="ndarray")
    d = q[pr[:, 0]] - q[pr[:, 1]]
    if periodic:
        d -= box * np.round(d / box)
    gap = np.linalg.norm(d, axis=1) - r[pr[:, 0]] - r[pr[:, 1]]
    return pr, gap / np.minimum(r[pr[:, 0]], r[pr[:, 1]])


def assortativity(r, pairs):
    """Newman's assortativity of ln r: each pair in both orders."""
    x = np.log(r)
    u = np.concatenate([x[pairs[:, 0]], x[pairs[:, 1]]])
    v = np.concatenate([x[pairs[:, 1]], x[pairs[:, 0]]])
    return float(np.corrcoef(u, v)[0, 1])


def measure(soil, packing, r, p, lo, hi, periodic):
    pr, rel = contacts(r, p, lo, hi, periodic)
    porosity = 1.0 - (4.0 / 3.0 * np.pi * r ** 3).sum() / np.prod(hi - lo)
    rows = []
    for tol in TOLS:
        sel = pr[rel < (0.0 if tol is None else tol)]
        z = np.bincount(sel.ravel(), minlength=len(r))
        rows.append({"soil": soil, "packing": packing, "grains": len(r),
                     "porosity": "%.4f" % porosity,
                     "tol": "overlap" if tol is None else "%g" % tol,
                     "contacts": len(sel), "z_mean": "%.2f" % (2.0 * len(sel) / len(r)),
                     "z_contacting": "%.2f" % (2.0 * len(sel) / max(1, (z > 0).sum())),
                     "no_contact_pct": "%.1f" % (100.0 * (z == 0).mean()),
                     "assortativity": "%+.3f" % assortativity(r, sel) if len(sel) else "nan"})
    return rows


def scatter(r, phi0, seed):
    """Random positions without overlap in a periodic cube of packing fraction
    phi0, largest grains first (random sequential addition)."""
    rng = np.random.default_rng(seed)
    edge = ((4.0 / 3.0 * np.pi * r ** 3).sum() / phi0) ** (1.0 / 3.0)
    order = np.argsort(-r, kind="stable")
    pos = np.empty((len(r), 3))
    placed_r = np.empty(len(r))
    n = 0
    for i in order:
        for attempt in range(100000):
            c = rng.random(3) * edge
            if n:
                d = pos[:n] - c
                d -= edge * np.round(d / edge)
                if np.any((d * d).sum(1) < (placed_r[:n] + r[i]) ** 2):
                    continue
            break
        else:
            sys.exit("no room for grain %d at packing fraction %g" % (i, phi0))
        pos[n] = c
        placed_r[n] = r[i]
        n += 1
    return edge, placed_r, pos


def write_data(path, edge, r, pos, density=2650.0):
    with open(path, "w") as f:
        f.write("random reference: grains scattered by bench/random_reference/run.py\n\n")
        f.write("%d atoms\n1 atom types\n\n" % len(r))
        for ax in "xyz":
            f.write("0 %.17g %slo %shi\n" % (edge, ax, ax))
        f.write("\nAtoms\n\n")
        for i in range(len(r)):
            f.write("%d 1 %.17g %g %.17g %.17g %.17g\n" % (i + 1, 2.0 * r[i], density, *pos[i]))


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--soils", nargs="*", default=soils.SOILS[:3],
                    help="shipped soils (default the three narrowest: %s)" % " ".join(soils.SOILS[:3]))
    ap.add_argument("--side", type=float, default=4.0)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--phi", type=float, default=0.73,
                    help="packing fraction the random packing is compressed to: it must jam there "
                         "(0.73 for Cu 2.0-2.5; Cu 3.0 needs 0.76)")
    ap.add_argument("--steps", type=int, default=150000)
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "random_reference"))
    ap.add_argument("--packings", nargs="+", default=list(PACKINGS), choices=PACKINGS,
                    help="the packings to make and measure (default all three)")
    ap.add_argument("--launcher", default=LAUNCHER[0], help="the liggghts-fabric executable")
    return ap.parse_args()


def pack_specimens(a, d, psd):
    """The sequential specimens (the discrete one also when the random
    packing is to be made from it) that have no dump yet."""
    for rule in ("discrete", "layerwise"):
        if rule not in a.packings and not (rule == "discrete" and "random" in a.packings):
            continue
        dump = os.path.join(d, rule + ".dump")
        if not os.path.exists(dump):
            liggghts("in.specimen", {"psd": psd, "side": a.side, "seed": a.seed,
                                     "arrangement": rule, "dump": dump + ".part"},
                     os.path.join(d, rule + ".log"))
            os.replace(dump + ".part", dump)


def random_packing(a, soil, d):
    """The discrete specimen's grains scattered and compressed to --phi
    (in.random), unless its dump exists."""
    dump = os.path.join(d, "random.dump")
    if "random" not in a.packings or os.path.exists(dump):
        return
    grains = read_dump(os.path.join(d, "discrete.dump"))[2]
    edge0, r0, p0 = scatter(grains, 0.25, a.seed)
    data = os.path.join(d, "scattered.data")
    write_data(data, edge0, r0, p0)
    edge = ((4.0 / 3.0 * np.pi * r0 ** 3).sum() / a.phi) ** (1.0 / 3.0)
    rmin = r0.min()
    # Hertz, E 5e6 Pa, nu 0.3, 2650 kg/m3: a tenth of the finest grain's Rayleigh time
    g = 5e6 / (2.0 * 1.3)
    dt = 0.1 * np.pi * rmin * np.sqrt(2650.0 / g) / (0.1631 * 0.3 + 0.8766)
    print("%s: %d grains scattered, compressing to packing fraction %.2f (%d steps)"
          % (soil, len(r0), a.phi, a.steps), flush=True)
    liggghts("in.random", {"data": data, "L": "%.17g" % edge, "skin": "%.3g" % (0.25 * rmin),
                           "dt": "%.3g" % dt, "steps": a.steps, "relax": a.steps // 3,
                           "dump": dump + ".part"}, os.path.join(d, "random.log"))
    os.replace(dump + ".part", dump)


def measure_soil(a, soil, d):
    """Measures the packings of --packings into d/assortativity.csv (the
    other packings' rows kept) and returns all its rows."""
    rows = []
    table = os.path.join(d, "assortativity.csv")
    if os.path.exists(table):
        with open(table) as f:
            rows = [r for r in csv.DictReader(f) if r["packing"] not in a.packings]
    for packing in PACKINGS:
        if packing in a.packings:
            lo, hi, r, p = read_dump(os.path.join(d, packing + ".dump"))
            rows += measure(soil, packing, r, p, lo, hi, periodic=(packing == "random"))
    rows.sort(key=lambda r: PACKINGS.index(r["packing"]))
    write_csv(table, rows)
    return rows


def report(soil, d, rows, t0):
    jam = next((r for r in rows if r["packing"] == "random" and r["tol"] == "overlap"), None)
    if jam is not None and float(jam["z_contacting"]) < 6.0:
        print("%s: WARNING: the random packing is not jammed (%s overlapping contacts per "
              "grain with contacts, below 6): delete %s and raise --phi"
              % (soil, jam["z_contacting"], os.path.join(d, "random.dump")), flush=True)
    print("%s: %.0f s" % (soil, time.time() - t0), flush=True)
    for row in rows:
        print("  %-10s %-8s grains %6s porosity %s contacts %6s z %5s (%5s with contacts) "
              "no contact %5s%% assortativity %s"
              % (row["packing"], row["tol"], row["grains"], row["porosity"], row["contacts"],
                 row["z_mean"], row["z_contacting"], row["no_contact_pct"],
                 row["assortativity"]), flush=True)


def main():
    a = parse_args()
    LAUNCHER[0] = os.path.abspath(a.launcher)
    a.out = os.path.abspath(a.out)
    os.makedirs(a.out, exist_ok=True)
    for soil in a.soils:
        psd = soils.psd_path(soil)
        if soil not in soils.SOILS:
            sys.exit("unknown soil '%s': no %s (the shipped soils: %s)"
                     % (soil, psd, ", ".join(soils.SOILS)))
        d = os.path.join(a.out, soil)
        os.makedirs(d, exist_ok=True)
        t0 = time.time()
        pack_specimens(a, d, psd)
        random_packing(a, soil, d)
        report(soil, d, measure_soil(a, soil, d), t0)
    # the table of every soil measured in OUT so far
    rows = []
    for soil in sorted(os.listdir(a.out)):
        path = os.path.join(a.out, soil, "assortativity.csv")
        if os.path.exists(path):
            with open(path) as f:
                rows += list(csv.DictReader(f))
    write_csv(os.path.join(a.out, "assortativity.csv"), rows)


def write_csv(path, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=FIELDS)
        w.writeheader()
        w.writerows(rows)

if __name__ == "__main__":
    main()
