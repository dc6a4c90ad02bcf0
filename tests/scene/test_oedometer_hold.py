#!/usr/bin/python3
"""Scene test: the oedometer's hold (-var hold N). After the stop the servo
stops in place (the same lid and its contacts) and the lid is held N steps;
the HOLD line gives the lid stress before and after, hold_series.txt the
stress every block.

At the scene's defaults (Hertz quartz, zeta 0.3; rest by force balance:
the servo loads until the lid stress is on target and the unbalanced-force
ratio of fix quasi/static is below load_tol 0.01, then the lid is held and
every velocity and spin zeroed every 100 steps until the ratio is below
rest_tol 1e-3) a Cu 2.5 DA specimen at side 3.3, one rank, is a static
packing: held another 20,000 steps (with the relaxation's zeroing, the
hold's default) its lid stress must stay within 2 % (results/rest/force_balance).
Held without the zeroing, or at zeta 0.6, such a specimen loses 7-42 %
(results/rest/creep_diagnosis). A hold that let the lid move, dropped the lid
contacts' tangential springs, or a ratio that called rest off balance,
would fail it. The HOLD line must agree with hold_series.txt (first row the
stress before, last row the stress after, one row every relax_every
500 steps); the LOADED
line gives the hand-over below load_tol and the STOP line a ratio below
rest_tol after the relaxation.
"""
import os
import re

import scene_util as su

HOLD = 20000
EVERY = 500    # hold_series.txt: a row every relax_every steps


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    out = os.path.join(args.work, "hold")
    res = su.run_launcher(
        args, os.path.join(args.source, "input_scripts", "in.oedometer"),
        variables={"out": out, "side": 3.3, "hold": HOLD},
        log=out + ".log", cwd=args.source, timeout=600)
    if not chk.check("the scene runs with hold %d (%.0f s)" % (HOLD, res.seconds),
                     res.returncode == 0, res.describe()):
        return chk.finish()
    loaded = re.search(r"^LOADED: .*unbalanced-force ratio (\S+) \(load_tol 0.01\)", res.text, re.M)
    stop = re.search(r"^STOP: at rest after (\d+) steps .*: (\d+) of loading, (\d+) of "
                     r"relaxation (?:with the lid held|under the servo); unbalanced-force ratio (\S+) \(rest_tol (\S+)\)",
                     res.text, re.M)
    chk.check("the servo hands over below load_tol 0.01 (LOADED) and the relaxation "
              "ends below rest_tol 1e-3 (STOP), its steps those of both phases",
              loaded and stop and float(loaded.group(1)) < 0.01
              and float(stop.group(4)) < 1e-3 and float(stop.group(5)) == 1e-3
              and int(stop.group(1)) == int(stop.group(2)) + int(stop.group(3)),
              (stop.group(0) if stop else res.text[-2000:]))
    hold = re.search(r"^HOLD: lid held (\d+) steps: lid stress (\S+) Pa before .*?, "
                     r"(\S+) Pa after \((\S+) %\)", res.text, re.M)
    if not chk.check("a HOLD line", hold is not None, res.text[-2000:]):
        return chk.finish()
    before, after, change = (float(hold.group(k)) for k in (2, 3, 4))
    chk.check("held %s steps, the lid stress moves %.4f %% (within 2 %%)"
              % (hold.group(1), change),
              int(hold.group(1)) == HOLD and abs(change) < 2.0
              and abs(100 * (after / before - 1) - change) < 1e-6, hold.group(0))
    lid = list(su.outputs.read_series(os.path.join(out, "hold_series.txt"),
                                      su.outputs.HOLD_SERIES_COLUMNS)["lid_stress"])
    chk.check("hold_series.txt (read by name): %d rows, one every 500 steps and the start "
              "(got %d); the first is the stress before, the last the stress after"
              % (HOLD // EVERY + 1, len(lid)),
              len(lid) == HOLD // EVERY + 1
              and abs(lid[0] / before - 1) < 1e-5
              and abs(lid[-1] / after - 1) < 1e-5, lid[:1] + lid[-1:])
    return chk.finish()


if __name__ == "__main__":
    raise SystemExit(main())
