#!/usr/bin/python3
"""Scene test: fix pore/flow on a small fixed packing, and its bad input.

The page's complete scene (examples/in.pore_flow, linked from
docs/fix_pore_flow.md: about 700 grains of the Cu 2.5 soil packed by fix
sequential/pack in a cube of 3 mm, no integration, run 0) is the specimen:

1. the flow balances: inflow = outflow to 1e-8 of either (the solver stops
   at a residual of 1e-12 of its right-hand side);
2. the fluid force on the grains along the flow axis is the pressure drop
   times the cross-section within 1 % (fix vector); the grains' forces
   (compute reduce sum fz, the pair forces summing to zero) and the
   per-atom output (f_ID[3]) sum to that total: each grain gets its force
   once, on whatever rank owns it; the same along x with direction x;
3. the permeability lies within a factor 1.3 of Kozeny-Carman with the
   Sauter diameter and the box's porosity (the unit tests' factor for equal
   spheres), and, when bench/pore_flow_bench is built beside the launcher,
   equals the core's on the dumped spheres to 1e-9;
4. 1 and 2 MPI ranks give the same vector (entries 1..6) and the same
   force per grain to 1e-9 relative;
5. every N: between solves the vector keeps the last solve's step;
   a grain whose centre lies past the outflow face is left out of the
   solve (entry left_out counts it, it feels no force), one past another
   face is an error (7.);
6. the page's examples run (examples/in.pore_flow prints what the page's
   sentence after its link says; each one-line fix runs in it) and its
   output table quotes fix_pore_flow/pore_flow_outputs.h;
7. bad input stops with an ERROR naming the value and what is allowed,
   never a crash.
"""
import os
import re
import subprocess

import numpy as np

import scene_util as su

THERMO = "thermo_style    custom step atoms f_flow[1] f_flow[2] f_flow[3] f_flow[4] f_flow[6]"


# the dump's columns (measured()): the grain, and the fix's per-atom fluid
# force x, y, z (f_ID[1..3], docs/fix_pore_flow.md)
GRAIN = ["id", "x", "y", "z", "radius"]
FLOW_FORCE = ["f_flow[1]", "f_flow[2]", "f_flow[3]"]
# what measured()'s compute fsum sums (c_fsum[1..6]): the grains' forces
# (pair and fluid), then the fix's per-atom fluid force
SUMMED = ["fx", "fy", "fz"] + FLOW_FORCE


def page_blocks(args):
    with open(os.path.join(args.source, "docs", "fix_pore_flow.md")) as f:
        text = f.read()
    section = text[text.index("## Examples"):text.index("## Description")]
    return text, [b.strip("\n") for b in re.findall(r"```\n(.*?)```", section, re.S)]


def example_scene(args):
    with open(os.path.join(args.source, "examples", "in.pore_flow")) as f:
        return f.read()


def fix_line(scene):
    return [l for l in scene.splitlines() if l.startswith("fix             flow ")][0]


def thermo_line(scene):
    """The scene's thermo_style line: the keywords its thermo rows are read by."""
    return [l for l in scene.splitlines() if l.startswith("thermo_style")][0]


def flow_entries(row, source):
    """{entry name: value} of the fix's vector entries f_flow[I] that a
    thermo row (outputs.read_thermo) holds, named by pore_flow_outputs.h."""
    return {e.name: row["f_flow[%d]" % e.position] for e in su.outputs.pore_flow_vector(source)
            if "f_flow[%d]" % e.position in row}


def measured_thermo(source):
    """measured()'s thermo_style line: the whole vector, then c_fsum[1..6]."""
    n = len(su.outputs.pore_flow_vector(source))
    return ("thermo_style    custom step %s %s"
            % (" ".join("f_flow[%d]" % i for i in range(1, n + 1)),
               " ".join("c_fsum[%d]" % i for i in range(1, len(SUMMED) + 1))))


def measured(scene, dump, source, extra_fix=""):
    """The scene with the whole vector, the sums of the forces and a
    full-precision dump of the grains and their fluid forces."""
    line = fix_line(scene)
    out = scene.replace(line, line + extra_fix)
    out = out.replace(THERMO, (
        "compute         fsum all reduce sum %s\n%s\n"
        "thermo_modify   format float %%.17g\n"
        "dump            d all custom 1 %s id x y z radius f_flow[1] f_flow[2] f_flow[3] f_flow[4]\n"
        "dump_modify     d sort id format \"%%d %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g %%.17g\""
        % (" ".join(SUMMED), measured_thermo(source), dump)))
    return out


def run_measured(args, chk, root, scene, name, nprocs=None, extra_fix=""):
    """(vector by name, the sums of SUMMED by name: fx fy fz f_flow[1..3],
    the dump's snapshot: columns by name, outputs.Snapshot) or None."""
    dump = os.path.join(root, name + ".dump")
    inp = su.write_file(os.path.join(root, name + ".in"),
                        measured(scene, dump, args.source, extra_fix))
    res = su.run_launcher(args, inp, nprocs=nprocs, cwd=root)
    row = su.outputs.thermo_row(res.text, measured_thermo(args.source), 0)
    if not chk.check("%s runs and prints the vector" % name,
                     res.returncode == 0 and not res.errors() and row is not None
                     and os.path.isfile(dump), res.describe()):
        return None
    sums = {q: row["c_fsum[%d]" % k] for k, q in enumerate(SUMMED, 1)}
    return flow_entries(row, args.source), sums, su.outputs.last_snapshot(dump)


def rel(a, b):
    return abs(a - b) / max(abs(a), abs(b), 1e-300)


def check_balance(chk, vec, sums, grains, what, axis, area):
    chk.check("%s: inflow %.12g = outflow %.12g to 1e-8 (%.2g)"
              % (what, vec["inflow"], vec["outflow"], rel(vec["inflow"], vec["outflow"])),
              vec["inflow"] > 0 and rel(vec["inflow"], vec["outflow"]) < 1e-8)
    want = vec["pressure_drop"] * area
    chk.check("%s: fluid force %.9g N = dp A = %.9g N within 1 %% (%.2g)"
              % (what, vec["fluid_force"], want, rel(vec["fluid_force"], want)),
              rel(vec["fluid_force"], want) < 0.01)
    grain, flow = sums["f" + "xyz"[axis]], sums[FLOW_FORCE[axis]]
    chk.check("%s: the grains' forces (%.12g) and %s (%.12g) sum to the fix's total"
              % (what, grain, FLOW_FORCE[axis], flow),
              rel(grain, vec["fluid_force"]) < 1e-6 and rel(flow, vec["fluid_force"]) < 1e-9)
    chk.check("%s: the dump's per-grain forces sum to the total too" % what,
              rel(grains[FLOW_FORCE[axis]].sum(), vec["fluid_force"]) < 1e-9)


def check_pressure(chk, grains, p_in, p_out):
    """f_ID[4], the pressure each grain sees: between the faces' pressures
    and falling with height as the flow goes up. (On this graded packing a
    fine grain in a pore open to the inflow sees up to a third of the drop
    more than the linear drop at its height; the linear drop itself is the
    unit test's, on equal spheres.)"""
    p, z = grains["f_flow[4]"], grains["z"]
    corr = float(np.corrcoef(p, z)[0, 1])
    chk.check("f_flow[4]: every grain's pressure within [%g, %g] Pa (%.4g to %.4g), "
              "correlated with height by %.3f (below -0.9)" % (p_out, p_in, p.min(), p.max(), corr),
              p.min() >= p_out - 1e-9 and p.max() <= p_in + 1e-9 and corr < -0.9)


def check_reversed(args, chk, root, scene, one):
    """direction -z: the same network with the flow from the top down. A
    linear network passes the same flow either way (reciprocity), so the
    figures are z's; the grains' forces sum to the total along -z."""
    down = run_measured(args, chk, root, scene, "down", extra_fix=" direction -z")
    if not (down and one):
        return
    vec, sums = down[0], down[1]
    same = all(rel(vec[k], one[0][k]) < 1e-9 for k in ("inflow", "outflow", "permeability", "fluid_force"))
    chk.check("direction -z: inflow %.12g, permeability %.12g, fluid force %.9g N as along z"
              % (vec["inflow"], vec["permeability"], vec["fluid_force"]), same)
    chk.check("direction -z: the grains' forces sum to %.9g N along z, minus the total %.9g N"
              % (sums["fz"], vec["fluid_force"]),
              rel(-sums["fz"], vec["fluid_force"]) < 1e-6
              and rel(-sums[FLOW_FORCE[2]], vec["fluid_force"]) < 1e-9)


def check_permeability(args, chk, root, vec, grains, side):
    r = grains["radius"]
    n = 1.0 - (4.0 / 3.0 * np.pi * r ** 3).sum() / side ** 3
    d = 2.0 * (r ** 3).sum() / (r ** 2).sum()
    kc = d ** 2 * n ** 3 / (180.0 * (1.0 - n) ** 2)
    ratio = vec["permeability"] / kc
    chk.check("K %.4g m^2 within a factor 1.3 of Kozeny-Carman %.4g (Sauter d %.4g m, "
              "porosity %.4f): ratio %.3f" % (vec["permeability"], kc, d, n, ratio),
              1 / 1.3 < ratio < 1.3)
    bench = os.path.join(os.path.dirname(args.launcher), "bench", "pore_flow_bench")
    if not os.path.isfile(bench):
        chk.note("no %s: K against the core not compared" % bench)
        return
    spheres = os.path.join(root, "spheres.txt")
    with open(spheres, "w") as f:
        f.write("0 0 0 %r %r %r\n" % (side, side, side))
        for g in zip(*(grains[c] for c in ("x", "y", "z", "radius"))):
            f.write("%.17g %.17g %.17g %.17g\n" % g)
    out = subprocess.run([bench, "solve", spheres, "1000", "0", "1e-3",
                          os.path.join(root, "cells.txt"), os.path.join(root, "forces.txt")],
                         stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=120)
    m = re.search(r"permeability (\S+)", out.stdout.decode())
    k = float(m.group(1)) if m else None
    chk.check("K of the fix %.10g = K of the core on the dumped spheres %s (to 1e-9, "
              "as printed)" % (vec["permeability"], k),
              k is not None and rel(k, vec["permeability"]) < 1e-9, out.stdout.decode())


def check_ranks(args, chk, root, scene, one):
    two = run_measured(args, chk, root, scene, "two_ranks", nprocs=2)
    if not two or not one:
        return
    names = ["inflow", "outflow", "permeability", "fluid_force", "pressure_drop", "pores"]
    worst = max(rel(one[0][k], two[0][k]) for k in names)
    chk.check("1 and 2 ranks: %s agree to 1e-9 (worst %.2g; iterations %d and %d)"
              % (", ".join(names), worst, one[0]["iterations"], two[0]["iterations"]),
              worst < 1e-9)
    a, b = (np.column_stack([s[c] for c in GRAIN + FLOW_FORCE]) for s in (one[2], two[2]))
    n = len(GRAIN)
    scale = np.abs(a[:, n:]).max()
    diff = np.abs(a[:, n:] - b[:, n:]).max() / scale if a.shape == b.shape else np.inf
    chk.check("1 and 2 ranks: the same grains (%d) and force per grain to 1e-9 of the "
              "largest (%.2g)" % (len(a), diff),
              a.shape == b.shape and np.array_equal(a[:, :n], b[:, :n]) and diff < 1e-9)


def check_every(args, chk, root, scene):
    text = scene.replace(fix_line(scene), fix_line(scene).replace("every 100", "every 5"))
    solve_step = "f_flow[%d]" % (su.outputs.index(su.outputs.pore_flow_vector(args.source))
                                 ["solve_step"] + 1)
    thermo = "thermo_style    custom step %s" % solve_step
    text = text.replace(THERMO, thermo + "\nthermo 1").replace(
        "run             0", "run             7")
    res = su.run_launcher(args, su.write_file(os.path.join(root, "every.in"), text), cwd=root)
    rows = {r["step"]: r[solve_step] for r in su.outputs.read_thermo(res.text, thermo)}
    got = [rows.get(s) for s in range(8)]
    chk.check("every 5 over 7 steps: the solve step reads 0 0 0 0 0 5 5 5 (%s)" % got,
              got == [0, 0, 0, 0, 0, 5, 5, 5], res.describe())


def check_left_out(args, chk, root, scene):
    """The box's outflow face lowered to z 2.5 mm, as an outlet's grains
    wait for their deletion below it: the grains whose centres lie above
    it are left out (entry left_out) and feel no force; the flow still
    balances."""
    cut = 0.0025
    line = fix_line(scene)
    got = run_measured(args, chk, root, scene.replace(line, line.replace(
        "box 0 0.003 0 0.003 0 0.003", "box 0 0.003 0 0.003 0 %g" % cut)), "left_out")
    if not got:
        return
    vec, grains = got[0], got[2]
    past = grains["z"] >= cut
    force = np.abs(np.column_stack([grains[c] for c in FLOW_FORCE])).sum(axis=1)
    chk.check("outflow face at z %g: left_out %g = the %d grains centred past it, "
              "none of them with a fluid force, every other grain with one"
              % (cut, vec["left_out"], past.sum()),
              0 < past.sum() == vec["left_out"] and not force[past].any()
              and force[~past].all())
    chk.check("outflow face at z %g: inflow %.6g = outflow %.6g to 1e-8"
              % (cut, vec["inflow"], vec["outflow"]),
              vec["inflow"] > 0 and rel(vec["inflow"], vec["outflow"]) < 1e-8)


def check_page(args, chk, root, text, blocks, scene):
    want = [e for e in su.outputs.pore_flow_vector(args.source)]
    missing = ["| %d | %s | %s |" % e for e in want if "| %d | %s | %s |" % e not in text]
    chk.check("the page quotes pore_flow_outputs.h: %d entries, position, name and "
              "meaning" % len(want),
              not missing and "global vector of %d entries" % len(want) in text,
              "\n".join(missing))
    res = su.run_launcher(args, su.write_file(os.path.join(root, "page.in"), scene), cwd=root)
    row = su.outputs.thermo_row(res.text, thermo_line(scene), 0)
    v = flow_entries(row, args.source) if row else {}

    def near(name, want, tol):
        return name in v and abs(v[name] - want) < tol
    chk.check("examples/in.pore_flow prints 703 grains, inflow = outflow 9.627e-7 m^3/s, "
              "K 3.21e-10 m^2, force 0.0090 N, 3680 pores",
              res.returncode == 0 and row is not None and row.get("atoms") == 703
              and near("inflow", 9.627e-7, 5e-11) and near("outflow", 9.627e-7, 5e-11)
              and near("permeability", 3.21e-10, 5e-13) and near("fluid_force", 0.009, 5e-5)
              and v.get("pores") == 3680, row or res.describe())
    for i, line in enumerate(blocks[0].splitlines()):
        res = su.run_launcher(args, su.write_file(
            os.path.join(root, "page_line%d.in" % i), scene.replace(fix_line(scene), line)),
            cwd=root)
        chk.check("the page's one-line example %r runs" % line,
                  res.returncode == 0 and not res.errors(), res.describe())


# (what, the scene's fix line edited, patterns the ERROR must match)
BAD = (
    ("viscosity -1e-3", " viscosity -1e-3", [r"viscosity -1e-3", r"must be positive"]),
    ("viscosity abc", " viscosity abc", [r"viscosity 'abc'", r"not a number"]),
    ("every 0", "every 0", [r"every 0\b", r"at least 1"]),
    ("P_in < P_out", "pressure 0 1000", [r"P_in 0 must exceed P_out 1000"]),
    ("P_in = P_out", "pressure 1000 1000", [r"P_in 1000 must exceed P_out 1000"]),
    ("box lo >= hi", "box 0 0.003 0.003 0 0 0.003", [r"box y from 0.003 to 0", r"lo must be below hi"]),
    ("pressure with one value", "pressure 1000", [r"'pressure' needs 2 values: P_in P_out"]),
    ("no box", "", [r"'box' is required"]),
    ("no pressure", "", [r"'pressure' is required"]),
    ("no every", "", [r"'every' is required"]),
    ("unknown keyword", " speed 3", [r"speed", r"every box pressure viscosity direction"]),
    ("direction w", " direction w", [r"direction 'w'", r"x, y, z, -x, -y or -z"]),
    ("grains outside the box", "box 0 0.002 0 0.003 0 0.003",
     [r"sphere \d+ \(atom ID \d+\) has its centre outside the box"]),
)


def bad_line(line, what, edit):
    if what.startswith("no "):
        kw = what[3:]
        return re.sub(r" %s [^ ]+(?: [0-9.e-]+)*" % kw if kw != "every" else r" every \d+",
                      "", line)
    if what in ("every 0",):
        return re.sub(r"every \d+", edit, line)
    if what.startswith("P_in") or what.startswith("pressure"):
        return re.sub(r"pressure \S+ \S+", edit, line)
    if what.startswith("box") or what.startswith("grains"):
        return re.sub(r"box( \S+){6}", edit, line)
    return line + edit


def check_bad(args, chk, root, scene):
    line = fix_line(scene)
    for what, edit, patterns in BAD:
        new = bad_line(line, what, edit)
        res = su.run_launcher(args, su.write_file(os.path.join(root, "bad.in"),
                                                  scene.replace(line, new)),
                              cwd=root, timeout=60)
        err = res.errors()
        ok = not res.crashed() and not res.timed_out and bool(err)
        ok = ok and all(re.search(p, err[0]) for p in patterns)
        chk.check("%s (%s): ERROR matching %s" % (what, new.split("pore/flow")[1].strip(), patterns),
                  ok, "\n".join(err) or res.describe())
    # an atom style without a radius
    text = (su.preamble(atom_style="atomic") +
            "region box block 0 1 0 1 0 1 units box\ncreate_box 1 box\n"
            "fix flow all pore/flow every 1 box 0 1 0 1 0 1 pressure 1 0\n")
    res = su.run_launcher(args, su.write_file(os.path.join(root, "bad_atomic.in"), text),
                          cwd=root, timeout=60)
    err = res.errors()
    chk.check("atom_style atomic: ERROR naming the radius the fix needs",
              not res.crashed() and bool(err) and "radius" in err[0],
              "\n".join(err) or res.describe())


def main():
    args = su.parse_args(__doc__)
    root = su.fresh_dir(args.work)
    os.symlink(os.path.join(args.source, "input_scripts"), os.path.join(root, "input_scripts"))
    chk = su.Checker()
    text, blocks = page_blocks(args)
    if not chk.check("the page has a one-line block and links to examples/in.pore_flow",
                     len(blocks) == 1 and "(../examples/in.pore_flow)" in text):
        return chk.finish()
    scene = example_scene(args)
    side = 0.003

    one = run_measured(args, chk, root, scene, "one_rank")
    if one:
        check_balance(chk, one[0], one[1], one[2], "z", 2, side * side)
        check_permeability(args, chk, root, one[0], one[2], side)
        check_pressure(chk, one[2], 1000.0, 0.0)
    along_x = run_measured(args, chk, root, scene, "along_x", extra_fix=" direction x")
    if along_x:
        check_balance(chk, along_x[0], along_x[1], along_x[2], "direction x", 0, side * side)
    check_reversed(args, chk, root, scene, one)
    check_ranks(args, chk, root, scene, one)
    check_every(args, chk, root, scene)
    check_left_out(args, chk, root, scene)
    check_page(args, chk, root, text, blocks, scene)
    check_bad(args, chk, root, scene)
    return chk.finish()


if __name__ == "__main__":
    raise SystemExit(main())
