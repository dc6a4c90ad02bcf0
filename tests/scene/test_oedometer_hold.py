#!/usr/bin/python3
"""Scene test: the oedometer's hold (-var hold N). After the stop the servo
stops in place (the same lid and its contacts) and the lid is held N steps;
the HOLD line gives the lid stress before and after, hold_series.txt the
stress every block.

A specimen brought to force balance (Cu 2.5 DA, side 3.3, one rank, contact
damping zeta 0.3, rest when the unbalanced-force ratio of fix quasi/static
is below 0.01) and held with every velocity set to zero every 100 steps
(-var hold_zero 100) is a static packing: held 10,000 steps its lid stress
must stay within 2 % (measured over 20,000 steps: 0.09 % for seed 1,
0.03 % for seed 2; held without the zeroing it loses 42 %, at the default
zeta 0.6 with it 6.9 %: results/creep_diagnosis). A hold that let the lid
move, dropped the lid contacts' tangential springs, or a ratio that called
rest off balance, would fail it. The HOLD line must agree with
hold_series.txt (first row the stress before, last row the stress after,
one row per block), and the STOP line must give a ratio below 0.01.
"""
import os
import re

import scene_util as su

HOLD = 10000
EVERY = 2000


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    out = os.path.join(args.work, "hold")
    res = su.run_launcher(
        args, os.path.join(args.source, "input_scripts", "in.oedometer"),
        variables={"out": out, "side": 3.3, "zeta": 0.3, "rest_tol": 0.01,
                   "hold": HOLD, "hold_zero": 100},
        log=out + ".log", cwd=args.source, timeout=600)
    if not chk.check("the scene runs with hold %d (%.0f s)" % (HOLD, res.seconds),
                     res.returncode == 0, res.describe()):
        return chk.finish()
    stop = re.search(r"^STOP: at rest .*unbalanced-force ratio (\S+)", res.text, re.M)
    chk.check("it stops at rest with an unbalanced-force ratio below 0.01",
              stop is not None and float(stop.group(1)) < 0.01,
              stop.group(0) if stop else res.text[-2000:])
    hold = re.search(r"^HOLD: lid held (\d+) steps: lid stress (\S+) Pa before .*?, "
                     r"(\S+) Pa after \((\S+) %\)", res.text, re.M)
    if not chk.check("a HOLD line", hold is not None, res.text[-2000:]):
        return chk.finish()
    before, after, change = (float(hold.group(k)) for k in (2, 3, 4))
    chk.check("held %s steps, the lid stress moves %.4f %% (within 2 %%)"
              % (hold.group(1), change),
              int(hold.group(1)) == HOLD and abs(change) < 2.0
              and abs(100 * (after / before - 1) - change) < 1e-6, hold.group(0))
    rows = su.outputs.data_rows(os.path.join(out, "hold_series.txt"))
    chk.check("hold_series.txt: %d rows, one per block and the start (got %d); "
              "the first is the stress before, the last the stress after"
              % (HOLD // EVERY + 1, len(rows)),
              len(rows) == HOLD // EVERY + 1
              and abs(float(rows[0][2]) / before - 1) < 1e-5
              and abs(float(rows[-1][2]) / after - 1) < 1e-5, rows[:1] + rows[-1:])
    return chk.finish()


if __name__ == "__main__":
    raise SystemExit(main())
