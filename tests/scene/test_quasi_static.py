#!/usr/bin/python3
"""Scene test: fix quasi/static on hand-built scenes whose answer is known,
and its bad-input errors.

A column of three spheres (d 2 mm, linear springs kn 2e7 N/m) stands between
two walls with every overlap 2e-5 m: each contact carries 400 N and every
sphere's resultant is 0, so the unbalanced-force ratio is 0; a free sphere
beside it has no contact and is not counted. With the top wall lowered by
1e-5 m the top contact carries 600 N: the top sphere's resultant is 200 N,
the mean over the three 200/3 N, the mean contact force 450 N, the ratio
0.148148... The ratio counts the forces before the local damping, so a
damping of 0.5 reads the same. The same state on 2 ranks cut through the
column (processors 1 1 2) reads the same. The damping itself: the free
sphere pushed by fix addforce with 1 N for 100 steps gains (1 - alpha)
of the work done on it.

The command page's examples (docs/fix_quasi_static.md) run as written: its
complete scene, examples/in.quasi_static_column, prints what the page's
sentence after its link says, and each one-line fix runs in it. The kinetic
damping (zero N, fix_modify ID zero N) leaves no kinetic energy at a step
that is a multiple of N and leaves it at others (check_zero).
"""
import os
import re

import scene_util as su

COLUMN = """\
{preamble}region box block -0.01 0.01 -0.01 0.01 -0.001 0.008 units box
create_box 2 box
neigh_modify delay 0
fix m1 all property/global kn peratomtypepair 2 2e7 2e7 2e7 2e7
fix m2 all property/global kt peratomtypepair 2 2e7 2e7 2e7 2e7
fix m3 all property/global gamman peratomtypepair 2 0 0 0 0
fix m4 all property/global gammat peratomtypepair 2 0 0 0 0
fix m5 all property/global coefficientFriction peratomtypepair 2 0.4 0.4 0.4 0.4
pair_style gran model hooke/stiffness tangential history
pair_coeff * *
create_atoms 1 single 0 0 0.00098 units box
create_atoms 1 single 0 0 0.00296 units box
create_atoms 1 single 0 0 0.00494 units box
create_atoms 1 single 0.005 0 0.003 units box
set atom * diameter 0.002 density 2650
fix wb all wall/gran model hooke/stiffness tangential history primitive type 2 zplane 0.0 store_force_contact_stress yes
fix wt all wall/gran model hooke/stiffness tangential history primitive type 2 zplane {top} store_force_contact_stress yes
compute pf all primary/fabric min_contacts 2 intervals 1
fix qs all quasi/static damping {alpha} balance pf
fix nve all nve/sphere
timestep 1e-8
thermo_style custom step f_qs f_qs[2] f_qs[3] f_qs[4] c_pf[10]
thermo_modify format float %.12g
run 0
"""

PUSH = """\
{preamble}region box block -0.01 0.01 -0.01 0.01 -0.01 0.01 units box
create_box 1 box
fix m1 all property/global kn peratomtypepair 1 2e7
fix m2 all property/global kt peratomtypepair 1 2e7
fix m3 all property/global gamman peratomtypepair 1 0
fix m4 all property/global gammat peratomtypepair 1 0
fix m5 all property/global coefficientFriction peratomtypepair 1 0.4
pair_style gran model hooke/stiffness tangential history
pair_coeff * *
create_atoms 1 single 0 0 0 units box
set atom * diameter 0.002 density 2650
fix push all addforce 1.0 0 0
fix qs all quasi/static damping {alpha}
fix nve all nve/sphere
timestep 1e-6
variable x equal x[1]
variable ke equal 0.5*mass[1]*vx[1]^2
thermo_style custom step v_x v_ke
thermo_modify format float %.15g
run 100
print "PUSHED: $(v_x) $(v_ke)"
"""


# the thermo keywords of fix quasi/static qs's outputs (the table of
# docs/fix_quasi_static.md: the scalar is entry 1, the ratio)
RATIO, RESULTANT, CONTACT, GRAINS = "f_qs", "f_qs[2]", "f_qs[3]", "f_qs[4]"


def thermo_line(script):
    """The last thermo_style line of an input script: its thermo rows are
    read by that line's keywords (outputs.read_thermo)."""
    return [l for l in script.splitlines() if l.startswith("thermo_style")][-1]


def near(row, key, want, tol):
    """Whether the thermo row holds `key` within `tol` of `want`."""
    return row is not None and key in row and abs(row[key] - want) < tol


def run_column(args, chk, name, top, alpha, nprocs=None, processors=None):
    text = COLUMN.format(preamble=su.preamble(processors=processors), top=su.num(top),
                         alpha=alpha)
    inp = su.write_file(os.path.join(args.work, name + ".in"), text)
    res = su.run_launcher(args, inp, nprocs=nprocs)
    row = su.outputs.thermo_row(res.text, thermo_line(text), 0)
    chk.check("%s runs and prints the ratio" % name,
              res.returncode == 0 and row is not None, res.describe())
    return row


def expect_error(args, chk, what, text, patterns):
    inp = su.write_file(os.path.join(args.work, "bad.in"), text)
    res = su.run_launcher(args, inp, timeout=60)
    err = [l for l in res.text.splitlines() if "ERROR" in l]
    ok = not res.crashed() and not res.timed_out and bool(err)
    ok = ok and all(re.search(p, err[0]) for p in patterns)
    chk.check("%s: ERROR matching %s" % (what, patterns), ok,
              "\n".join(err) or res.describe())


def check_zero(args, chk, scene):
    """Kinetic damping on the page's scene (examples/in.quasi_static_column),
    every sphere set moving at 1 m/s
    along the walls (whose friction sets the pressed spheres spinning) and
    run 10 steps of 1e-8 s: with `zero 10` (or `zero 5`)
    the last step zeroes every velocity and spin, so the kinetic energy
    printed after it is 0; with `zero 0` and `zero 3` (last zeroing at step
    9) it is not; `fix_modify qs zero 10` after a fix without zeroing
    zeroes as the keyword does."""
    fix_line = [l for l in scene.splitlines() if l.startswith("fix qs ")][0]
    cases = (("zero 10", fix_line + " zero 10", True),
             ("zero 5", fix_line + " zero 5", True),
             ("zero 0", fix_line + " zero 0", False),
             ("zero 3", fix_line + " zero 3", False),
             ("fix_modify qs zero 10", fix_line + "\nfix_modify qs zero 10", True))
    for what, line, still in cases:
        text = scene.replace(fix_line, line).replace(
            "thermo_style custom step f_qs f_qs[2] f_qs[3] f_qs[4]\nrun 0",
            "velocity all set 1 0 0\n"
            "compute kt all ke\n"
            "compute kr all erotate/sphere\n"
            "thermo_style custom step c_kt c_kr\nthermo 10\nrun 10")
        res = su.run_launcher(args, su.write_file(
            os.path.join(args.work, "zero_%s.in" % what.replace(" ", "_")), text))
        row = su.outputs.thermo_row(res.text, thermo_line(text), 10)
        ok = row is not None and list(row) == ["step", "c_kt", "c_kr"] and (
            (row["c_kt"] == 0 and row["c_kr"] == 0) if still
            else (row["c_kt"] > 0 and row["c_kr"] > 0))
        chk.check("%s: after 10 steps the translational and rotational kinetic energy "
                  "%s (%s)" % (what, "are 0" if still else "are not", row),
                  ok, res.describe())


def check_page(args, chk):
    with open(os.path.join(args.source, "docs", "fix_quasi_static.md")) as f:
        text = f.read()
    section = text[text.index("## Examples"):text.index("## Description")]
    blocks = re.findall(r"```\n(.*?)```", section, re.S)
    if not chk.check("the page has one example block and links to "
                     "examples/in.quasi_static_column",
                     len(blocks) == 1 and "(../examples/in.quasi_static_column)" in section,
                     len(blocks)):
        return
    with open(os.path.join(args.source, "examples", "in.quasi_static_column")) as f:
        scene = f.read()
    res = su.run_launcher(args, su.write_file(
        os.path.join(args.work, "page.in"), scene))
    row = su.outputs.thermo_row(res.text, thermo_line(scene), 0)
    chk.check("examples/in.quasi_static_column runs and prints ratio 0.148, mean "
              "resultant 66.7 N, mean contact 450 N, 3 grains",
              row is not None and list(row) == ["step", RATIO, RESULTANT, CONTACT, GRAINS]
              and near(row, RATIO, 0.148, 5e-4) and near(row, RESULTANT, 66.7, 0.05)
              and near(row, CONTACT, 450, 1e-6) and row[GRAINS] == 3, row or res.describe())
    fix_line = [l for l in scene.splitlines() if l.startswith("fix qs ")][0]
    for i, line in enumerate(blocks[0].strip().splitlines()):
        # (a fix_modify line goes after the scene's own fix)
        new = fix_line + "\n" + line if line.startswith("fix_modify") else line
        res = su.run_launcher(args, su.write_file(
            os.path.join(args.work, "page_line%d.in" % i),
            scene.replace(fix_line, new).replace(" f_qs f_qs[2] f_qs[3] f_qs[4]", "")))
        chk.check("the page's one-line example %r runs" % line,
                  res.returncode == 0 and not res.errors(), res.describe())
    check_zero(args, chk, scene)


def scene_errors(args, name, variables):
    """The ERROR lines of in.oedometer run with `variables` (it must stop
    with one at once, without a crash)."""
    v = dict(variables, out=os.path.join(args.work, name),
             psd=os.path.join(args.source, "input_scripts", "psd", "cu2.5.txt"),
             mesh=os.path.join(args.source, "input_scripts", "meshes", "lid.stl"),
             parts=os.path.join(args.source, "input_scripts", "oedometer"))
    res = su.run_launcher(args, os.path.join(args.source, "input_scripts", "in.oedometer"),
                          log=os.path.join(args.work, name + ".log"), cwd=args.work,
                          timeout=60, variables=v)
    if res.crashed():
        return []
    return [l for l in res.text.splitlines() if l.startswith("ERROR")]


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()

    balanced = run_column(args, chk, "balanced", 0.00592, 0)
    if balanced:
        chk.check("static column: ratio 0 (resultants below 1e-9 of the "
                  "contact force), 3 grains counted, 400 N contacts",
                  abs(balanced[RATIO]) < 1e-9 and balanced[GRAINS] == 3 and
                  abs(balanced[CONTACT] - 400.0) < 1e-6, balanced)
    want = (200.0 / 3.0) / 450.0
    for name, alpha, nprocs, proc in (("off", 0, None, None),
                                      ("off_damped", 0.5, None, None),
                                      ("off_2ranks", 0.5, 2, "1 1 2")):
        row = run_column(args, chk, name, 0.00591, alpha, nprocs, proc)
        if row:
            chk.check("%s: top sphere 200 N off balance: ratio %.12g (hand: "
                      "%.12g), mean contact 450 N" % (name, row[RATIO], want),
                      abs(row[RATIO] - want) < 1e-9 and abs(row[CONTACT] - 450.0) < 1e-6,
                      row)

    # the damping's work on a free sphere: KE = (1 - alpha) F x
    for alpha in (0.0, 0.7):
        inp = su.write_file(os.path.join(args.work, "push%g.in" % alpha),
                            PUSH.format(preamble=su.preamble(), alpha=alpha))
        res = su.run_launcher(args, inp)
        m = re.search(r"^PUSHED: (\S+) (\S+)", res.text, re.M)
        ok = res.returncode == 0 and m is not None
        if ok:
            x, ke = float(m.group(1)), float(m.group(2))
            ok = x > 0 and abs(ke / (1.0 * x) - (1.0 - alpha)) < 0.02
        chk.check("a free sphere pushed with 1 N, damping %g: it keeps "
                  "(1 - alpha) of the work (first half step undamped: 1 of "
                  "200 half kicks)" % alpha, ok,
                  m.group(0) if m else res.describe())

    check_page(args, chk)

    base = COLUMN.format(preamble=su.preamble(), top="0.00592", alpha="0.5")
    # bad input: (what, the scene edited, patterns the ERROR must match)
    for what, text, patterns in (
            ("damping 1", base.replace("damping 0.5", "damping 1"),
             [r"damping 1\b", r"0 <= alpha < 1"]),
            ("damping -0.1", base.replace("damping 0.5", "damping -0.1"),
             [r"damping -0.1", r"0 <= alpha < 1"]),
            ("damping abc", base.replace("damping 0.5", "damping abc"),
             [r"abc", r"not a number"]),
            ("unknown keyword", base.replace("damping 0.5", "damping 0.5 speed 3"),
             [r"speed", r"damping zero balance"]),
            ("zero -1", base.replace("damping 0.5", "damping 0.5 zero -1"),
             [r"zero -1", r"every N steps"]),
            ("zero 2.5", base.replace("damping 0.5", "damping 0.5 zero 2.5"),
             [r"zero '2.5'", r"not an integer"]),
            ("balance of a missing compute", base.replace("balance pf", "balance nope"),
             [r"nope", r"does not exist"]),
            ("balance of another compute",
             base.replace("balance pf", "balance k").replace("fix qs", "compute k all ke\nfix qs"),
             [r"compute ke", r"primary/fabric"]),
            ("ratio without balance", base.replace(" balance pf", ""),
             [r"needs the keyword balance"])):
        expect_error(args, chk, what, text, patterns)
    # the scene's own checks of the new variables: an ERROR naming them
    for name, variables, words in (
            ("rest_tol", {"rest_tol": "-0.01", "side": "3.3"}, ["rest_tol -0.01", "positive"]),
            ("hold_zero", {"hold": 1000, "hold_zero": -5, "side": "3.3"}, ["hold_zero -5", "number of steps"])):
        err = scene_errors(args, name, variables)
        chk.check("in.oedometer %s: ERROR containing %s" % (variables, words),
                  bool(err) and all(w in err[0] for w in words), "\n".join(err))
    return chk.finish()


if __name__ == "__main__":
    raise SystemExit(main())
