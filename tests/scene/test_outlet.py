#!/usr/bin/python3
"""Scene test: the suffusion test's outlet (examples/in.outlet), built from
LIGGGHTS' own commands: a sieve plate (fix wall/gran on the group of grains
coarser than the opening) and behind it fix massflow/mesh, which counts,
deletes and writes every grain that crosses.

Eight grains of 0.8-3 mm drift towards a plate of opening 2 mm:
1. the four finer than the opening leave and are written to left.txt (their
   IDs and diameters), the four coarser stay; nothing else is lost: the
   mass in equals the mass left plus the mass that stays (to 1e-12), and
   the mass left is that of the diameters written (rho pi d^3 / 6);
2. on 2 ranks (one file per rank) the same grains leave, with the same mass;
3. with an opening of 2.5 mm the 2.1 and 2.4 mm grains leave too;
4. an opening of 0 or below stops with an ERROR naming it.
"""
import math
import os
import re

import scene_util as su

DIAMETERS = {1: 0.0008, 2: 0.0012, 3: 0.0016, 4: 0.0019,
             5: 0.0021, 6: 0.0024, 7: 0.0027, 8: 0.003}
RHO = 2650.0


def run(args, name, nprocs=None, opening=None):
    out = os.path.join(args.work, name)
    v = {"out": out}
    if opening is not None:
        v["opening"] = opening
    res = su.run_launcher(args, os.path.join(args.source, "examples", "in.outlet"),
                          nprocs=nprocs, variables=v, log=out + ".log",
                          cwd=args.source, timeout=300)
    m = re.search(r"^OUTLET: (\d+) grains \((\S+) kg\) in; (\S+) left \((\S+) kg\), "
                  r"(\d+) stay \((\S+) kg\)", res.text, re.M)
    left = su.outputs.read_outlet(os.path.join(out, "left.txt"))
    return res, m, left


def mass(ids):
    return sum(RHO * math.pi * DIAMETERS[i] ** 3 / 6 for i in ids)


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    want = [i for i, d in DIAMETERS.items() if d < 0.002]
    got = {}
    for name, nprocs in (("one", None), ("two", 2)):
        res, m, left = run(args, name, nprocs)
        ranks = "2 ranks" if nprocs else "1 rank"
        if not chk.check("examples/in.outlet runs on %s (%.1f s)" % (ranks, res.seconds),
                         res.returncode == 0 and not res.errors() and m, res.describe()):
            continue
        ids = list(left["id"])
        got[ranks] = (ids, float(m.group(4)))
        chk.check("%s: the grains finer than 2 mm left (%s), each written with its diameter; "
                  "the coarser stay" % (ranks, ids),
                  ids == want and int(float(m.group(3))) == len(want)
                  and int(m.group(5)) == len(DIAMETERS) - len(want)
                  and all(abs(d - DIAMETERS[i]) < 1e-12 for i, d in zip(ids, left["diameter"])))
        m_in, m_left, m_stay = float(m.group(2)), float(m.group(4)), float(m.group(6))
        chk.check("%s: mass in %.9g kg = left %.9g + staying %.9g (to 1e-12), the mass left "
                  "that of the diameters written (%.9g)" % (ranks, m_in, m_left, m_stay, mass(ids)),
                  abs(m_in - m_left - m_stay) <= 1e-12 * m_in
                  and abs(m_left / mass(ids) - 1) < 1e-9)
    if len(got) == 2:
        a, b = got.values()
        chk.check("1 and 2 ranks: the same grains and the same mass left", a == b, (a, b))
    res, m, left = run(args, "wider", opening=0.0025)
    chk.check("opening 2.5 mm: the grains finer than it leave (%s)" % list(left["id"]),
              res.returncode == 0 and list(left["id"]) == [1, 2, 3, 4, 5, 6], res.describe())
    for bad in ("0", "-0.001"):
        res, m, left = run(args, "bad", opening=bad)
        err = [l for l in res.text.splitlines() if l.startswith("ERROR")]
        chk.check("opening %s: one ERROR naming it" % bad,
                  res.returncode not in (0, None) and not res.crashed() and err
                  and ("opening %s: use a positive sieve opening" % bad) in err[0], err or res.describe())
    return chk.finish()


if __name__ == "__main__":
    main()
