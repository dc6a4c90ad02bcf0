#!/usr/bin/python3
"""Scene test: `ramp` raises the lid's target stress linearly over a loading
time instead of asking for the full stress at the first step (Cu 2.5,
side 3.3, Hertz quartz at 1 MPa, ramp 0.02 s, a check every 500 steps:
about 4,000 steps at the default dt_gain 4).

1. The run comes to rest, and not before the ramp's end: its STOP line says
   "at rest" at a loading time t >= ramp.
2. The lid follows the ramp, not the full stress: the lid stress averaged
   over the first block (500 steps of 4 times the one-density step, 0.0041
   s: the target rising from 1 % to 21 % of the stress) is below a tenth of
   the stress (38 kPa); over the block ending after the
   ramp it is within 25 % of the stress. (A scene that ignored ramp would
   push for the full stress from the first step; one that stopped on the
   error against the full stress during the ramp would swing-error.)
3. At rest the lid stress is within `stress_tol` (0.05) of the stress: the
   error of the stop is measured against the full target once the ramp is
   over.
"""
import os
import re

import scene_util as su

RAMP = 0.02
STRESS = 1e6
EVERY = 500


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    out = os.path.join(args.work, "ramp")
    res = su.run_launcher(args, os.path.join(args.source, "input_scripts", "in.oedometer"),
                          variables={"out": out, "side": 3.3, "stress": STRESS, "ramp": RAMP, "every": EVERY,
                                     "t_max": 0.1},
                          log=out + ".log", cwd=args.source, timeout=800)
    chk.check("ramp %g s: runs to its FABRIC line without an ERROR (exit %s)" % (RAMP, res.returncode),
              res.returncode == 0 and not res.errors() and "FABRIC:" in res.text, res.describe())
    m = re.search(r"^STOP: at rest after (\d+) steps \(t = (\S+) s\).*lid stress (\S+) Pa", res.text, re.M)
    t_stop = float(m.group(2)) if m else float("nan")
    sigma_stop = float(m.group(3)) if m else float("nan")
    chk.check("STOP at rest at t = %s s, not before the ramp's end %g s" % (t_stop, RAMP),
              m is not None and t_stop >= RAMP)
    chk.check("at rest the lid stress %s Pa is within 0.05 of %g Pa" % (sigma_stop, STRESS),
              abs(sigma_stop / STRESS - 1) < 0.05)
    path = os.path.join(out, "fabric_series.txt")
    lid = list(su.outputs.read_series(path)["lid_stress"]) if os.path.exists(path) else []
    # the lid stress's block means; the first row is before loading
    dt_block = None
    m = re.search(r"^TIMESTEP: .* dt = (\S+) s", res.text, re.M)
    if m:
        dt_block = float(m.group(1)) * EVERY
    loaded = lid[1:]
    chk.check("the series has a row per block (%d rows) and the time step is printed" % len(lid),
              len(loaded) >= 3 and dt_block is not None)
    if len(loaded) >= 3 and dt_block is not None:
        first = loaded[0]
        chk.check("first block (t up to %.4f s, target up to %.0f %% of the stress): lid stress "
                  "%.0f Pa, below a tenth of %g Pa" % (dt_block, 100 * (0.01 + dt_block / RAMP), first, STRESS),
                  0 < first < 0.1 * STRESS)
        k_after = next((k for k in range(len(loaded)) if (k + 1) * dt_block >= RAMP + dt_block), None)
        after = loaded[k_after] if k_after is not None else float("nan")
        chk.check("block %s, the first wholly after the ramp: lid stress %.0f Pa, within 25 %% of %g Pa"
                  % (k_after, after, STRESS), abs(after / STRESS - 1) < 0.25)
    return chk.finish()


if __name__ == "__main__":
    raise SystemExit(main())
