#!/usr/bin/python3
"""Scene test: fix servo/rest on the command page's scene, and its
bad-input errors.

The page's complete scene (examples/in.servo_rest_column, linked from
docs/fix_servo_rest.md): a column of three spheres between a fixed top
wall and a servo lid loaded to 40 N (2.5 MPa on its 4 mm square). It runs as written on 1 rank and on 2 (the box cut
through the column, processors 1 1 2) and on both

1. the fix prints the page's LOADED and STOP lines, the same on both rank
   counts: handed over below load_tol, at rest below rest_tol, the steps
   those of both phases, the lid stress within stress_tol of the target;
2. a column at rest carries the same force at every contact: the lid
   stress times the area is that of both grain contacts, within ten times
   the unbalanced-force ratio at rest (1.4e-5)
   (compute pair/gran/local: what a force balance means here, read
   independently of the fix);
3. the vector written whole by fix ave/time in mode vector is read by name
   (tools/outputs.read_rest) and agrees with the STOP line.

The page's output table quotes rest_outputs.h; its one-line examples run
in the scene. A held lid off the target reloads: the same scene with
`lid held` and the target lowered at the hand-over, so the relaxed stress
is off the target, sends the lid back to the servo (RELOAD) and ends at
rest on the target. Bad input stops with an ERROR
naming the value: no servo fix, a servo fix of another style, a
fix quasi/static without balance, a negative rest_tol, the energy rule
without ke_vrms, a check that does not divide every, an unknown keyword,
a lid neither held nor servo, a target stress variable that falls to 0, no
stress. With `lid servo` the page's scene
relaxes under the servo and ends at rest on the target.
"""
import os
import re

import scene_util as su

outputs = su.outputs


def page(args):
    with open(os.path.join(args.source, "docs", "fix_servo_rest.md")) as f:
        text = f.read()
    section = text[text.index("## Examples"):text.index("## Description")]
    blocks = re.findall(r"```\n(.*?)```", section, re.S)
    return text, blocks


def run(args, name, text, nprocs=None):
    inp = su.write_file(os.path.join(args.work, name + ".in"), text)
    return su.run_launcher(args, inp, nprocs=nprocs, cwd=args.source, timeout=300)


def lines(res, head):
    return [l for l in res.text.splitlines() if l.startswith(head)]


def check_scene(args, chk, scene, printed):
    fix_line = [l for l in scene.splitlines() if l.startswith("fix rest ")][0]
    # the top wall's force and the vector, written whole
    # (LIGGGHTS takes compute pair/gran/local only before the first run)
    computes = ("compute pl all pair/gran/local force\n"
                "compute fmin all reduce min c_pl[3]\ncompute fmax all reduce max c_pl[3]\n")
    extra = ("\nfix out all ave/time 1 1 1 f_rest mode vector file %s\n"
             "thermo_style custom step c_fmin c_fmax\nrun 0\n"
             "print \"CONTACTS: $(c_fmin) $(c_fmax)\"\n")
    stops = {}
    for nprocs, proc in ((None, ""), (2, "processors 1 1 2\n")):
        rest_txt = os.path.join(args.work, "rest_%s.txt" % (nprocs or 1))
        text = scene.replace("boundary f f f\n", "boundary f f f\n" + proc).replace(
            "fix nve all nve/sphere\n", computes + "fix nve all nve/sphere\n") + extra % rest_txt
        res = run(args, "page_%s" % (nprocs or 1), text, nprocs)
        ranks = "%d rank%s" % (nprocs or 1, "s" if nprocs else "")
        if not chk.check("the page's scene runs on %s (%.1f s)" % (ranks, res.seconds),
                         res.returncode == 0 and not res.errors(), res.describe()):
            continue
        loaded, stop = lines(res, "LOADED:"), lines(res, "STOP:")
        stops[ranks] = stop
        chk.check("%s: the LOADED and STOP lines the page prints" % ranks,
                  loaded and stop and loaded[0] == printed[0] and stop[0] == printed[1],
                  "\n".join(loaded + stop))
        m = re.search(r"after (\d+) steps .*: (\d+) of loading, (\d+) of relaxation .*"
                      r"ratio (\S+) \(rest_tol (\S+)\), lid stress (\S+) Pa \((\S+) % from",
                      stop[0] if stop else "")
        h = re.search(r"ratio (\S+) \(load_tol (\S+)\)", loaded[0] if loaded else "")
        chk.check("%s: handed over below load_tol, at rest below rest_tol, steps adding up, "
                  "stress within 5 %% of the target" % ranks,
                  m and h and float(h.group(1)) < float(h.group(2))
                  and float(m.group(4)) < float(m.group(5))
                  and int(m.group(1)) == int(m.group(2)) + int(m.group(3))
                  and abs(float(m.group(7))) < 5.0, stop)
        pair = re.search(r"^CONTACTS: (\S+) (\S+)", res.text, re.M)
        if m and pair:
            lid_force = float(m.group(6)) * 1.6e-5
            forces = [abs(float(pair.group(k))) for k in (1, 2)]
            ratio = float(m.group(4))
            chk.check("%s: at rest the lid's force %.7g N is that of both grain contacts "
                      "(%.7g, %.7g N), within 10 times the ratio %.2g"
                      % (ranks, lid_force, forces[0], forces[1], ratio),
                      all(abs(lid_force / f - 1) < 10 * ratio for f in forces))
        r = outputs.read_rest(rest_txt, args.source)
        chk.check("%s: rest.txt read by name: phase at rest, steps %s and stress as the "
                  "STOP line" % (ranks, r and r["steps"]),
                  r is not None and m is not None and r["phase_name"] == "at rest"
                  and r["ended"] == 1 and r["steps"] == int(m.group(1))
                  and r["steps_relaxed"] == int(m.group(3))
                  and abs(r["rest_stress"] / float(m.group(6)) - 1) < 1e-5, r)
    if len(stops) == 2:
        a, b = stops.values()
        chk.check("1 and 2 ranks: the same STOP line", a == b, (a, b))
    return fix_line


def check_reload(args, chk, scene, fix_line):
    """With the lid held (lid held), the target lowered by 10 % for good at
    the hand-over: the held lid is off the new target (the servo had it at
    40 N), so it goes back to the servo, which loads to 36 N, and the next
    relaxation ends at rest."""
    text = scene.replace(fix_line, "variable F equal 40*(1-0.1*((f_rest[1]>0)||(f_rest[5]>0)))\n"
                         "variable S equal v_F/1.6e-5\n" +
                         fix_line.replace("stress 2.5e6", "stress v_S") + " lid held")
    text = text.replace("target_val 40 ", "target_val v_F ")
    res = run(args, "reload", text)
    stop, reload = lines(res, "STOP:"), lines(res, "RELOAD:")
    off = re.search(r"Pa, (\S+) % from the target", reload[0]) if reload else None
    chk.check("a relaxed stress off a target lowered by 10 %%: one RELOAD, %s %% off"
              % (off and off.group(1)),
              res.returncode == 0 and len(set(reload)) == 1 and off
              and 5 < float(off.group(1)) < 15, reload or res.describe())
    chk.check("... then at rest within 5 % of the lowered target, the reload counted",
              bool(stop) and stop[0].startswith("STOP: at rest")
              and "taken up again 1 times" in stop[0]
              and "from the target 2250000 Pa" in stop[0], stop or res.describe())


def check_errors(args, chk, scene, fix_line):
    cases = (
        ("no servo fix", fix_line.replace("servo/rest lid", "servo/rest nolid"),
         ["servo wall fix ID 'nolid' does not exist"]),
        ("a servo fix of another style", fix_line.replace("servo/rest lid", "servo/rest top"),
         ["fix 'top' is a fix wall/gran, not a fix mesh/surface/stress/servo"]),
        ("a fix quasi/static without balance", fix_line.replace(
            "servo/rest lid qs", "servo/rest lid qs2").replace(
            "fix rest", "fix qs2 all quasi/static\nfix rest"),
         ["fix quasi/static 'qs2' has no balance compute"]),
        ("a negative rest_tol", fix_line + " rest_tol -1e-3",
         ["rest_tol -1e-3 must be a positive unbalanced-force ratio"]),
        ("the energy rule without ke_vrms", fix_line + " rest_tol 0",
         ["rest_tol 0 \\(the kinetic-energy rule\\) needs ke_vrms"]),
        ("a check that does not divide every", fix_line + " check 300",
         ["check 300: must be 1 step or more and divide every 500"]),
        ("an unknown keyword", fix_line + " rest 1e-3", ["rest"]),
        ("a lid neither held nor servo", fix_line + " lid free", ["lid 'free' is unknown: use servo or held"]),
        ("a target stress that falls to 0", "variable S0 equal 2.5e6*(step<1000)\n"
         + fix_line.replace("stress 2.5e6", "stress v_S0"),
         ["target stress v_S0 is 0.000000 Pa at step 1000", "must stay positive"]),
        ("no stress", fix_line.replace("stress 2.5e6 ", ""),
         ["needs the keywords stress"]),
    )
    for what, line, patterns in cases:
        res = run(args, "bad", scene.replace(fix_line, line))
        err = [l for l in res.text.splitlines() if l.startswith("ERROR")]
        chk.check("%s: one ERROR naming %s" % (what, patterns),
                  not res.crashed() and not res.timed_out and err
                  and "Fix servo/rest" in err[0]
                  and all(re.search(p, err[0]) for p in patterns),
                  "\n".join(err) or res.describe())


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    text, blocks = page(args)
    if not chk.check("the page has an example block, a link to examples/in.servo_rest_column "
                     "and what it prints",
                     len(blocks) == 2 and "(../examples/in.servo_rest_column)" in text,
                     len(blocks)):
        return chk.finish()
    with open(os.path.join(args.source, "examples", "in.servo_rest_column")) as f:
        scene = f.read()
    one_liners, printed = blocks[0], blocks[1].strip().splitlines()
    fix_line = check_scene(args, chk, scene, printed)

    # the output table quotes the header
    rows = re.findall(r"^\| (\d+) \| (\w+) \| (.*) \|$", text, re.M)
    table = [(int(p), n, m) for p, n, m in rows]
    want = [(e.position, e.name, e.meaning) for e in outputs.rest_vector(args.source)]
    chk.check("the page's output table is rest_outputs.h (%d entries)" % len(want),
              table == want, (table, want))

    for i, line in enumerate(one_liners.strip().splitlines()):
        t = scene.replace(fix_line, "variable A equal 1.6e-5\nvariable S_goal equal 2.5e6\n" + line)
        t = t[:t.index("run $(f_rest[2])")] + "run 1000\n"
        res = run(args, "line%d" % i, t)
        chk.check("the page's one-line example %r runs" % line,
                  res.returncode == 0 and not res.errors(), res.describe())
    check_reload(args, chk, scene, fix_line)
    res = run(args, "lid_servo", scene.replace(fix_line, fix_line + " lid servo"))
    stop = lines(res, "STOP:")
    chk.check("lid servo: the relaxation under the servo ends at rest within 1 %% of the target "
              "(%s)" % (stop[0][:150] if stop else None),
              res.returncode == 0 and bool(stop) and "of relaxation under the servo" in stop[0]
              and not lines(res, "RELOAD:")
              and abs(float(re.search(r"\((\S+) % from the target", stop[0]).group(1))) < 1.0,
              stop or res.describe())
    check_errors(args, chk, scene, fix_line)
    return chk.finish()


if __name__ == "__main__":
    main()
