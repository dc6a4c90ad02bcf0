"""Our pore flow (core/pore_flow.h) against YADE's FlowEngine on the same
packings: permeability, pore pressures cell by cell, the fluid force on the
grains. See README.md for the answer.

    /usr/bin/python3 bench/pore_flow_vs_yade/run.py [--bench build/bench/pore_flow_bench]

Needs Debian's yade (apt-get install yade); without it, it says so and
stops. Writes its files into --work (default out/pore_flow_vs_yade).
"""
import argparse
import os
import shutil
import subprocess
import sys

import numpy as np
from scipy.spatial import cKDTree

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))

# (name, pore_flow_bench export arguments, length scales to run at)
SPECIMENS = [
    ("graded", ["6", "0.35", "1", "SPHERES", os.path.join(ROOT, "input_scripts/psd/cu2.5.txt")],
     [1.0, 1e3, 1e6]),
    ("equal", ["10", "0.40", "1", "SPHERES"], [1.0, 1e3]),
]
DP, MU = 1.0, 1e-3


def run(cmd, env=None):
    out = subprocess.run(cmd, capture_output=True, text=True, env=env)
    if out.returncode != 0:
        sys.exit("failed: %s\n%s%s" % (" ".join(cmd), out.stdout[-2000:], out.stderr[-2000:]))
    return out.stdout


def scaled(src, dst, k):
    rows = np.loadtxt(src, skiprows=1)
    box = np.loadtxt(src, max_rows=1)
    with open(dst, "w") as f:
        f.write(" ".join(repr(v * k) for v in box) + "\n")
        np.savetxt(f, rows * k, fmt="%.17g")


def field(text, key):
    words = text.split()
    return float(words[words.index(key) + 1])


def ours(bench, spheres, prefix):
    out = run([bench, "solve", spheres, str(DP), "0", str(MU),
               prefix + "_cells.txt", prefix + "_forces.txt"])
    return field(out, "permeability")


def yade(spheres, prefix, clamp):
    env = dict(os.environ, CLAMP="1" if clamp else "0")
    out = run(["yade", "-n", "-x", os.path.join(HERE, "yade_flow.py"), spheres,
               str(DP), "0", str(MU), prefix], env)
    line = [l for l in out.splitlines() if l.startswith("YADE")][-1]
    return field(line, "permeability"), field(line, "inflow"), field(line, "outflow")


def pressures(prefix_ours, prefix_yade, size):
    """|p_yade - p_ours| / dp over the cells both have (centres within 1e-6
    of the box), the pores we solve for (not imposed, not merged)."""
    a = np.loadtxt(prefix_ours + "_cells.txt")
    b = np.loadtxt(prefix_yade + "_cells.txt")
    own = a[(a[:, 4] == 0) & (a[:, 5] == np.arange(len(a)))]
    dist, idx = cKDTree(b[:, :3]).query(own[:, :3])
    hit = dist < 1e-6 * size
    d = np.abs(b[idx[hit], 3] - own[hit, 3]) / DP
    return hit.mean(), np.median(d), np.percentile(d, 90), d.max()


def force_z(prefix, area):
    f = np.loadtxt(prefix + "_forces.txt")
    return f[:, 2].sum() / (DP * area)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--bench", default=os.path.join(ROOT, "build/bench/pore_flow_bench"))
    ap.add_argument("--work", default=os.path.join(ROOT, "out/pore_flow_vs_yade"))
    a = ap.parse_args()
    if shutil.which("yade") is None:
        print("yade is not installed (apt-get install yade): no comparison")
        return 0
    os.makedirs(a.work, exist_ok=True)
    print("%-7s %6s %10s %10s %10s %7s %7s %8s %8s %8s %7s %7s" % (
        "packing", "scale", "K_ours/s2", "K_yade", "K_noclamp", "yade/us", "nocl/us",
        "matched", "dp_med", "dp_p90", "Fz_us", "Fz_yade"))
    for name, args, scales in SPECIMENS:
        base = os.path.join(a.work, name + ".txt")
        run([a.bench, "export"] + [base if x == "SPHERES" else x for x in args])
        for k in scales:
            sph = os.path.join(a.work, "%s_x%g.txt" % (name, k))
            scaled(base, sph, k)
            box = np.loadtxt(sph, max_rows=1)
            size, area = box[3] - box[0], (box[3] - box[0]) * (box[4] - box[1])
            p_o, p_y = sph[:-4] + "_ours", sph[:-4] + "_yade"
            k_o = ours(a.bench, sph, p_o)
            k_y, _, _ = yade(sph, p_y, True)
            k_n, q_in, q_out = yade(sph, sph[:-4] + "_noclamp", False)
            m, med, p90, _ = pressures(p_o, p_y, size)
            print("%-7s %6g %10.4g %10.4g %10.4g %7.3f %7.3f %8.3f %8.4f %8.4f %7.4f %7.4f" % (
                name, k, k_o / k**2, k_y / k**2, k_n / k**2, k_y / k_o, k_n / k_o,
                m, med, p90, force_z(p_o, area), force_z(p_y, area)))
            if abs(q_in + q_out) > 1e-3 * abs(q_out):
                print("        (no clamp: YADE's inflow %.4g and outflow %.4g differ)" % (-q_in, q_out))
    return 0


if __name__ == "__main__":
    sys.exit(main())
