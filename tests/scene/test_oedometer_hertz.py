#!/usr/bin/python3
"""Scene test: the oedometer's default contacts are LIGGGHTS' Hertz-Mindlin
law of the grain material (quartz by default: youngs 70e9 Pa, poisson
0.25), on short runs (Cu 2.5, side 3.3, t_max 0.01 s, about 3,000 steps:
the grains are loaded, not yet at rest): the 100 kPa run gives no contact
setting at all, the 10 kPa run `hertz 1`.

1. The STIFFNESS line's stiffness number is the secant one of two coarsest
   grains pressed with stress d_N^2: (2 Y* / (3 stress))^(2/3) with
   Y* = E / (2 (1 - nu^2)), whatever the soil (3,957 for quartz at 100 kPa);
   and it follows the stress as stress^(-2/3) (a second run at 10 kPa).
2. The DAMPING line's restitution coefficient gives back the damping ratio
   asked for: sqrt(5/6) |ln e| / sqrt(ln^2 e + pi^2) = zeta (0.3 by default).
3. The contacts LIGGGHTS forms follow Hertz's law of that material: for the
   grain pairs of the final contact dump, the normal force F.n against
   (4/3) Y* sqrt(R*) delta^(3/2), delta from the two positions and radii
   (17 digits): the median ratio within 3 % of 1 over the pairs overlapping
   by more than 1e-3 of the coarser radius (the damping part of F.n is the
   rest; a scene that handed LIGGGHTS another modulus, or linear springs,
   fails by far).
"""
import math
import os
import re

import numpy as np

import scene_util as su


def hertz_run(args, work, stress, default):
    out = os.path.join(work, "hertz_%g" % stress)
    v = {"out": out, "side": 3.3, "t_max": 0.01, "stress": stress}
    if not default:
        v["hertz"] = 1
    res = su.run_launcher(args, os.path.join(args.source, "input_scripts", "in.oedometer"),
                          variables=v,
                          log=out + ".log", cwd=args.source, timeout=600)
    return out, res


def contact_ratios(out, ystar):
    grains = su.last_snapshot(os.path.join(out, "final.dump"))
    ids = grains.col("id", int)
    pos = {i: k for k, i in enumerate(ids)}
    x = np.column_stack([grains.col(c) for c in "xyz"])
    r = grains.col("radius")
    rows = []
    c = su.outputs.read_contacts(os.path.join(out, "final_contacts.txt"))
    force = np.column_stack([c["fx"], c["fy"], c["fz"]])
    for k in range(len(c["id1"])):
        if c["periodic"][k] != 0:     # grain pairs only
            continue
        a, b = pos.get(int(c["id1"][k])), pos.get(int(c["id2"][k]))
        if a is None or b is None:
            continue
        d = x[a] - x[b]
        dist = np.linalg.norm(d)
        delta = r[a] + r[b] - dist
        if delta <= 1e-3 * max(r[a], r[b]):
            continue
        n = d / dist
        fn = abs(np.dot(force[k], n))
        rstar = r[a] * r[b] / (r[a] + r[b])
        rows.append(fn / (4.0 / 3.0 * ystar * math.sqrt(rstar) * delta ** 1.5))
    return np.array(rows)


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    E, nu = 70e9, 0.25
    ystar = E / (2.0 * (1.0 - nu * nu))
    kappas = {}
    for stress in (1e5, 1e4):
        out, res = hertz_run(args, args.work, stress, default=(stress == 1e5))
        chk.check("%s at %g Pa: runs to its FABRIC line without an ERROR (exit %s), "
                  "with the MATERIAL line of Hertz-Mindlin quartz"
                  % ("the defaults" if stress == 1e5 else "hertz 1", stress, res.returncode),
                  res.returncode == 0 and not res.errors() and "FABRIC:" in res.text
                  and "MATERIAL: Young modulus 70e9 Pa, Poisson ratio 0.25" in res.text, res.describe())
        m = re.search(r"^STIFFNESS: stiffness number \(secant\) .* = (\S+) ", res.text, re.M)
        kappa = float(m.group(1)) if m else float("nan")
        kappas[stress] = kappa
        expected = (2.0 * ystar / (3.0 * stress)) ** (2.0 / 3.0)
        chk.check("stiffness number at %g Pa is (2 Y*/(3 stress))^(2/3) = %.1f (printed %s)"
                  % (stress, expected, kappa), abs(kappa / expected - 1) < 1e-6)
        if stress != 1e5:
            continue
        m = re.search(r"^DAMPING: zeta (\S+) for every grain pair.*restitution coefficients (\S+) and",
                      res.text, re.M)
        zeta, e = (float(m.group(1)), float(m.group(2))) if m else (float("nan"),) * 2
        le = abs(math.log(e)) if e > 0 else float("nan")
        back = math.sqrt(5.0 / 6.0) * le / math.sqrt(le * le + math.pi ** 2)
        chk.check("restitution %s gives back the damping ratio %s (%.6f)" % (e, zeta, back),
                  zeta == 0.3 and abs(back - zeta) < 1e-9)
        ratios = contact_ratios(out, ystar)
        med = float(np.median(ratios)) if len(ratios) else float("nan")
        chk.check("%d loaded grain pairs: F.n / ((4/3) Y* sqrt(R*) delta^1.5) median %.4f "
                  "(quartiles %s), within 3 %% of 1" % (
                      len(ratios), med, np.percentile(ratios, [25, 75]) if len(ratios) else "-"),
                  len(ratios) >= 50 and abs(med - 1) < 0.03)
    ratio = kappas[1e4] / kappas[1e5]
    chk.check("tenfold less stress, stiffness number times 10^(2/3) = 4.642 (%.4f)" % ratio,
              abs(ratio / 10 ** (2.0 / 3.0) - 1) < 1e-6)
    return chk.finish()


if __name__ == "__main__":
    raise SystemExit(main())
