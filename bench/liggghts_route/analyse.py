#!/usr/bin/env python3
"""Measure a specimen written by `write_dump all custom FILE id type x y z radius`
in the cubic container [0, L]^3, the same way for both routes.

Prints one line of KEY=VALUE pairs:
  n          number of spheres
  porosity   1 - (sum of sphere volumes) / L^3 (overlaps are not subtracted;
             they are reported separately)
  central    porosity of the central eighth (the cube of edge L/2 at the
             centre), by point sampling on a regular grid
  olmax      largest pair overlap / radius of the smaller sphere of the pair
  olmean     mean of that ratio over the pairs that overlap
  nol1       number of pairs overlapping by more than 1 % of the smaller radius
  wallmax    largest wall overlap / radius
  z          mean contacts per sphere, counting pairs with a gap below
             1e-6 of the smaller radius (touching or overlapping)
The measures in pure Python (a cell list, a few seconds for 20,000
spheres); the dump is read by tools/outputs.py (Debian's python3, numpy).

usage: analyse.py DUMP L [GRID]
"""
import math
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import outputs  # noqa: E402  (the one reader of the project's outputs)


def read_dump(path):
    """(x, y, z, radius) of each sphere of the dump's last snapshot, the
    columns by name (tools/outputs.py reads the dump)."""
    snap = outputs.last_snapshot(path)
    ix, iy, iz, ir = (snap.index(c) for c in ('x', 'y', 'z', 'radius'))
    return [(float(p[ix]), float(p[iy]), float(p[iz]), float(p[ir])) for p in snap.rows]


def main():
    path, L = sys.argv[1], float(sys.argv[2])
    grid = int(sys.argv[3]) if len(sys.argv) > 3 else 64
    s = read_dump(path)
    n = len(s)
    # cell list: every sphere is registered in each cell that its bounding
    # box (grown by a tolerance) touches; cell edge about a mean diameter
    dmean = 2.0 * sum(p[3] for p in s) / n
    nc = max(1, int(L / dmean))
    h = L / nc
    tol = 1e-6 * min(p[3] for p in s)
    cells = {}
    for k, (x, y, z, r) in enumerate(s):
        rr = r + tol
        rng = [range(max(0, int((c - rr) / h)), min(nc - 1, int((c + rr) / h)) + 1)
               for c in (x, y, z)]
        for a in rng[0]:
            for b in rng[1]:
                for c in rng[2]:
                    cells.setdefault((a, b, c), []).append(k)

    solid = sum(4.0 / 3.0 * math.pi * p[3] ** 3 for p in s)
    olmax = olsum = 0.0
    nol = nol1 = 0
    seen = set()
    for members in cells.values():
        m = len(members)
        for ia in range(m):
            i = members[ia]
            xi, yi, zi, ri = s[i]
            for ib in range(ia + 1, m):
                j = members[ib]
                xj, yj, zj, rj = s[j]
                rs = ri + rj
                dx, dy, dz = xi - xj, yi - yj, zi - zj
                d2 = dx * dx + dy * dy + dz * dz
                rsmall = ri if ri < rj else rj
                if d2 >= (rs + 1e-6 * rsmall) ** 2:
                    continue
                key = (i, j) if i < j else (j, i)
                if key in seen:
                    continue
                seen.add(key)
                delta = rs - math.sqrt(d2)
                if delta > 0.0:
                    rel = delta / rsmall
                    nol += 1
                    olsum += rel
                    if rel > 0.01:
                        nol1 += 1
                    if rel > olmax:
                        olmax = rel
    ncontact = len(seen)
    wallmax = 0.0
    for x, y, z, r in s:
        for c in (x, y, z):
            w = max(r - c, r - (L - c))
            if w / r > wallmax:
                wallmax = w / r

    # central eighth: point sampling on a grid x grid x grid lattice
    lo, hi = 0.25 * L, 0.75 * L
    step = (hi - lo) / grid
    inside = 0
    for a in range(grid):
        x = lo + (a + 0.5) * step
        for b in range(grid):
            y = lo + (b + 0.5) * step
            for c in range(grid):
                z = lo + (c + 0.5) * step
                for k in cells.get((int(x / h), int(y / h), int(z / h)), ()):
                    px, py, pz, pr = s[k]
                    if (px - x) ** 2 + (py - y) ** 2 + (pz - z) ** 2 < pr * pr:
                        inside += 1
                        break
    central = 1.0 - inside / float(grid ** 3)
    print('n=%d porosity=%.5f central=%.4f olmax=%.2e olmean=%.2e nol1=%d '
          'wallmax=%.2e z=%.2f'
          % (n, 1.0 - solid / L ** 3, central, olmax, olsum / nol if nol else 0.0,
             nol1, wallmax, 2.0 * ncontact / n))


if __name__ == '__main__':
    main()
