#!/usr/bin/python3
"""Scene test: where the oedometer scene cannot work, it stops with an ERROR
that names the value and what is allowed, and a non-zero exit status (never
a run that goes on and prints numbers):

The cases about linear springs (the stress 1e9 Pa at kn, the dashpots, the
swing, the overlap during the run, the grains thrown out) run with the kn
2e7 N/m they were measured with; the others with the scene's default, Hertz
quartz.

1. a time step at or above the critical one (dtfac 1.2): stopped before the
   first step, naming dt, the critical step and dtfac;
2. a lid that could cross half the neighbour skin in one step (vmax 100 m/s):
   stopped before the first step, naming the lid's step and the skin;
3. a target stress the contacts cannot carry as small overlaps (1e9 Pa at
   kn 2e7 N/m): stopped before the first step, naming the stress, the
   estimated overlap and overlap_max;
4. a container too small for the coarsest interval (side 1.8 coarsest
   diameters: 0.36 grains, rounded to none): stopped before packing;
5. a value of the `hertz` switch other than 1, 0 or -1, a negative stiffness
   number `kappa`, a stiffness number or a `kn` given with Hertz contacts
   (whose stiffness comes from the material), linear springs (hertz 0, or
   kt alone, which asks for them) without a normal stiffness or with two
   (kn and kappa), and a Hertz damping ratio LIGGGHTS
   cannot set (its restitution coefficient must exceed 0.05): stopped before
   packing; a stress of 1e9 Pa on quartz Hertz contacts: stopped before the
   first step, naming youngs as the setting to raise;
   and contact dashpots too strong for the time step (zeta 2: G_n dt 0.62,
   measured to throw grains out of the container): stopped before the first
   step, naming G_n, dt and zeta;
6. a lid servo that swings: with mass_scale 1e6 (the SERVO bound 88, where
   1e4 gives 0.88) the lid stress swings between none and twice the target
   (rms error 1.1-1.4 over a block, spread 0.66 about its mean); the run stops after the fourth block,
   naming the servo's kp and vel_max (fix servo/rest), instead of running on to t_max (runs
   that settle stay below rms 0.5 or spread 0.15 from the third block on);
7. the same overlap limit met during the run: with overlap_max 2e-4 (the a-priori
   estimate at 100 kPa is 1.7e-4 of the finest radius, the loaded chains
   overlap more) the run stops after its first block, naming the overlap;
8. grains that leave the container: a copy of the scene (the fault is
   injected there, the scene itself has no such switch) throws every grain
   at the lid at 50 m/s after packing, with overlap_max out of the way; most
   go through it and out of the simulation box, where LIGGGHTS deletes them
   silently. The run stops after its first block, counting them against
   the grains at the start of loading (a count of atoms outside the
   container region alone would find none: they no longer exist);
9. and where it must not stop: a layer-wise Cu 2.0 specimen at 0.35 whose
   packing leaves a whole interval unplaced (the packed-full porosity is
   above the target) is still classified, by the packer's interval index
   (intervals_from), with the packer's warning and no ERROR; the same run
   sets its contacts by the stiffness number (kappa 2000): K_n = K_t =
   2000 stress d_N, as its STIFFNESS line prints;
10. a stress too low to come to rest within t_max: quartz (hertz 1) at
   1 kPa on side 3.3 is still settling at the default t_max 0.3 s (the
   servo's lid speed and the kinetic-energy limit shrink with the stress):
   the run ends with a STOP that says "not at rest" and a WARNING naming
   t_max as the setting to raise, never with "at rest" (with t_max 1.5 s it
   comes to rest after 0.74 s, 114,000 steps);
11. the `error` command itself: the message with its ${variables}
   substituted, exit status 1, and a usage message when it has none.
"""
import os
import re

import scene_util as su

CASES = [
    ("time step above the critical one", {"dtfac": 1.2},
     ["the time step", "is not below the critical step", "dtfac 1.2 must be below 1"]),
    ("lid too fast for the neighbour skin", {"vmax": 100},
     ["the lid may move", "more than half the neighbour skin 5e-5 m", "lower vmax or raise skin"]),
    ("target stress the contacts cannot carry", {"kn": "2e7", "stress": "1e9"},
     ["the target stress 1e9 Pa", "above overlap_max 0.05", "lower stress or raise kn"]),
    ("a container too small for the coarsest interval", {"side": 1.8},
     ["side 1.8 holds", "grains of the coarsest interval", "it would be empty; use side 2.00"]),
    ("overlap beyond the limit during the run", {"kn": "2e7", "overlap_max": "2e-4"},
     ["two grains overlap by", "of the smallest radius", "above overlap_max 2e-4", "over a loading time (ramp 0 s)"]),
    ("a contact law the scene does not have", {"hertz": 2},
     ["hertz 2: use 1 (Hertz-Mindlin", "0 (linear springs of kn or kappa) or -1"]),
    ("a linear stiffness with Hertz contacts", {"hertz": 1, "kn": "2e7"},
     ["kn 2e7, kt 0 N/m set linear springs", "leave kn, kt 0, or use hertz 0"]),
    ("linear springs without a stiffness", {"hertz": 0},
     ["hertz 0 (linear springs) needs a stiffness: kn (N/m) or kappa"]),
    ("a tangential spring alone", {"kt": "1e7"},
     ["hertz 0 (linear springs) needs a stiffness: kn (N/m) or kappa"]),
    ("two stiffnesses for the linear springs", {"kn": "2e7", "kappa": 1963},
     ["kn 2e7 N/m and kappa 1963: give one stiffness of the linear springs, not both"]),
    ("a stiffness number with Hertz contacts", {"hertz": 1, "kappa": 1963},
     ["kappa 1963 sets linear springs", "leave kappa 0"]),
    ("Hertz damping beyond LIGGGHTS' restitution range", {"hertz": 1, "zeta": 0.7},
     ["zeta 0.7:", "restitution coefficient above 0.05", "below 0.63"]),
    ("a servo that swings with grains too heavy", {"kn": "2e7", "mass_scale": "1e6", "t_max": 0.1},
     ["Fix servo/rest: the lid servo swings: over the last block", "two blocks running", "lower the servo's kp or vel_max", "over a loading time (ramp)"]),
    ("a stress quartz grains cannot carry as small overlaps", {"hertz": 1, "stress": "1e9"},
     ["the target stress 1e9 Pa", "above overlap_max 0.05", "lower stress or raise youngs"]),
    ("a negative stress ramp", {"ramp": -1},
     ["ramp -1: use a loading time in s over which the target stress rises, or 0"]),
    ("a ramp as long as the run", {"ramp": 0.3},
     ["ramp 0.3 s is not shorter than t_max 0.01 s", "shorten ramp or raise t_max"]),
    ("a negative stiffness number", {"kappa": -1},
     ["kappa -1: use 0 (K_n, K_t from kn, kt) or a positive stiffness number"]),
    ("contact dashpots too strong for the time step", {"kn": "2e7", "zeta": 2},
     ["the contact damping G_n", "at or above 0.5", "lower zeta (2;", "or dtfac (0.4)"]),
]

ERROR_SCRIPT = """\
variable limit equal 2
variable x equal 3
if "${x} > ${limit}" then "error 'x is ${x}, above ${limit}'"
print "NOT REACHED"
"""


def scene_path(args):
    return os.path.join(args.source, "input_scripts", "in.oedometer")


def run_scene(args, name, variables, scene=None, timeout=600):
    """The scene (or a copy of it) with `variables` and out = WORK/name."""
    out = os.path.join(args.work, name)
    res = su.run_launcher(args, scene or scene_path(args), variables=dict(variables, out=out),
                          log=out + ".log", cwd=args.source, timeout=timeout)
    return res, out


def error_lines(res):
    return [l for l in res.text.splitlines() if l.startswith("ERROR")]


def check_cases(args, chk):
    """1-8 (CASES): each stops with a non-zero exit status and one ERROR
    naming its phrases, and prints no result."""
    for name, variables, phrases in CASES:
        v = {"t_max": 0.01, "side": 3.3}
        v.update(variables)
        res, _ = run_scene(args, name.replace(" ", "_"), v)
        errors = error_lines(res)
        chk.check("%s: exit status %s is not 0" % (name, res.returncode),
                  res.returncode not in (0, None), res.describe())
        chk.check("%s: one ERROR (screen and log) naming %s" % (name, phrases),
                  len(set(errors)) == 1 and all(p in errors[0] for p in phrases), errors or res.describe())
        chk.check("%s: no result printed" % name, "FABRIC:" not in res.text)


def check_grains_leave(args, chk):
    """8. Grains thrown out of the container by a copy of the scene."""
    kicked = os.path.join(args.work, "in.oedometer_kicked")
    with open(scene_path(args)) as f:
        text = f.read()
    marker = "run $(f_rest[2]) post no\n"
    chk.check("the scene has the first loading block the fault goes before", marker in text)
    su.write_file(kicked, text.replace(marker, "velocity all set 0 0 -50\n" + marker, 1))
    res, _ = run_scene(args, "grains_leave", {
        "t_max": 0.01, "side": 3.3, "overlap_max": "1e9", "kn": "2e7",
        "psd": os.path.join(args.source, "input_scripts", "psd", "cu2.0.txt")}, scene=kicked)
    errors = error_lines(res)
    chk.check("grains leaving the container: exit status %s is not 0, one ERROR counting them "
              "against the grains at the start, no result" % res.returncode,
              res.returncode not in (0, None) and len(set(errors)) == 1
              and "grains have left the container (step 2000 of the loading" in errors[0]
              and "FABRIC:" not in res.text,
              errors or res.describe())


def check_empty_interval(args, chk):
    """9. An interval the packer leaves empty is classified anyway; kappa
    sets the linear springs."""
    res, _ = run_scene(args, "empty_interval", {
        "t_max": 0.002, "side": 3.3, "arrangement": "layerwise", "kappa": 2000,
        "psd": os.path.join(args.source, "input_scripts", "psd", "cu2.0.txt")})
    chk.check("an interval left empty by the packer: classified anyway (exit %s, no ERROR, FABRIC line)"
              % res.returncode, res.returncode == 0 and not res.errors() and "FABRIC:" in res.text
              and "particles not placed" in res.text, res.describe())
    stop = [l for l in res.text.splitlines() if l.startswith("STOP:")]
    chk.check("stopped by t_max before the third block: the STOP line says the steadiness is not "
              "known yet, never a change of the primary fabric against the start values",
              len(set(stop)) == 1 and "steadiness not known yet" in stop[0] and "moved" not in stop[0],
              stop or res.describe())
    m = re.search(r"^STIFFNESS: K_n (\S+) N/m, K_t (\S+) N/m; stiffness number "
                  r"K_n / \(stress d_N\) = (\S+) ", res.text, re.M)
    dn = re.search(r"^psd_info .*d_N = (\S+) ", res.text, re.M)   # 6 digits
    chk.check("kappa 2000 sets K_n = K_t = 2000 stress d_N (STIFFNESS line %s, d_N %s)"
              % (m and m.groups(), dn and dn.group(1)),
              m is not None and dn is not None and m.group(1) == m.group(2)
              and abs(float(m.group(1)) / (2000 * 1e5 * float(dn.group(1))) - 1) < 1e-5
              and abs(float(m.group(3)) - 2000) < 1e-6, res.text[-1500:])


def check_stress_too_low(args, chk):
    """10. A stress too low to come to rest within t_max: STOP not at rest,
    a WARNING naming t_max, the primary fabric's change as the series has
    it."""
    res, out = run_scene(args, "stress_too_low", {"side": 3.3, "hertz": 1, "stress": "1e3"},
                         timeout=900)
    warnings = [l for l in res.text.splitlines() if l.startswith("WARNING: not at rest")]
    chk.check("a stress too low for t_max: exit %s, STOP not at rest at t_max 0.3 s, a WARNING "
              "naming t_max and the stress, never 'at rest'" % res.returncode,
              res.returncode == 0 and "STOP: maximum time 0.3 s reached" in res.text
              and "STOP: at rest" not in res.text and len(set(warnings)) == 1
              and "raise t_max" in warnings[0] and "stress 1000 Pa" in warnings[0],
              warnings or res.describe())
    moved = re.search(r"^STOP: maximum time .* primary fabric moved (\S+) points over the last "
                      r"two blocks", res.text, re.M)
    # the change as the series file has it: the primary % by mass of the
    # last three checks
    path = os.path.join(out, "fabric_series.txt")
    rows = list(su.outputs.read_series(path)["primary_mass_pct"]) if os.path.exists(path) else []
    last3 = rows[-3:]
    want = abs(last3[2] - last3[1]) + abs(last3[1] - last3[0]) if len(last3) == 3 else None
    chk.check("stopped by t_max after many blocks: the STOP line gives the primary fabric's "
              "change over the last two blocks (%s points), as the series file's last three "
              "checks give it (%s)" % (moved and moved.group(1), want),
              moved is not None and want is not None and len(rows) > 4
              and abs(float(moved.group(1)) - want) < 1e-3, res.text[-1500:])


def check_error_command(args, chk):
    """11. The `error` command, with a message and without."""
    inp = su.write_file(os.path.join(args.work, "in.error"), ERROR_SCRIPT)
    res = su.run_launcher(args, inp, timeout=60)
    chk.check("error: exit status %s" % res.returncode, res.returncode == 1, res.describe())
    chk.check("error: the message with its variables substituted",
              "ERROR: x is 3, above 2" in res.text and "NOT REACHED" not in res.text, res.text[-500:])
    inp = su.write_file(os.path.join(args.work, "in.error_bare"), "error\n")
    res = su.run_launcher(args, inp, timeout=60)
    chk.check("error without a message: a usage error",
              res.returncode == 1 and "give the message to stop with" in res.text, res.text[-500:])


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    check_cases(args, chk)
    check_grains_leave(args, chk)
    check_empty_interval(args, chk)
    check_stress_too_low(args, chk)
    check_error_command(args, chk)
    chk.finish()


if __name__ == "__main__":
    main()
