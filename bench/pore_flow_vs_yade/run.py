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
sys.path.insert(0, os.path.join(ROOT, "tools"))
import outputs  # noqa: E402  (the layouts of pore_flow_bench's and yade_flow.py's files)

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
    box, spheres = outputs.read_bench_spheres(src)
    with open(dst, "w") as f:
        f.write(" ".join(repr(box[c] * k) for c in outputs.BENCH_BOX_COLUMNS) + "\n")
        np.savetxt(f, np.column_stack([spheres[c] * k for c in outputs.BENCH_SPHERE_COLUMNS]),
                   fmt="%.17g")


def centres(cells):
    return np.column_stack([cells["x"], cells["y"], cells["z"]])


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
    a = outputs.read_bench_table(prefix_ours + "_cells.txt", outputs.BENCH_CELL_COLUMNS)
    b = outputs.read_bench_table(prefix_yade + "_cells.txt", outputs.YADE_CELL_COLUMNS)
    own = ((a["kind"] == outputs.BENCH_PORE_KINDS.index("unknown"))
           & (a["pore"] == np.arange(len(a["pore"]))))
    dist, idx = cKDTree(centres(b)).query(centres(a)[own])
    hit = dist < 1e-6 * size
    d = np.abs(b["pressure"][idx[hit]] - a["pressure"][own][hit]) / DP
    return hit.mean(), np.median(d), np.percentile(d, 90), d.max()


def force_z(prefix, area):
    f = outputs.read_bench_table(prefix + "_forces.txt", outputs.BENCH_FORCE_COLUMNS)
    return f["fz"].sum() / (DP * area)


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
            box, _ = outputs.read_bench_spheres(sph)
            size = box["xhi"] - box["xlo"]
            area = size * (box["yhi"] - box["ylo"])
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
