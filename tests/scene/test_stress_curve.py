#!/usr/bin/python3
"""Tool test: tools/stress_curve.py on study CSVs written here (no
simulation), against numbers worked out by hand:

1. per rule, soil and stress, the mean, smallest and largest primary % by
   mass and loose % by number of the seeds, and the secant stiffness number
   of quartz there, (2 Y*/(3 stress))^(2/3): 3,957 at 100 kPa;
2. --linear rows at --kappa 1963 are drawn at the stress where quartz has
   that stiffness number, 2 Y*/(3 kappa^1.5) = 286.2 kPa;
3. a study folder given the wrong stress (its lid stress more than 5 % off)
   is refused with a message naming it, as is STRESS=DIR without a number;
4. --runs extends a curve from its kept stress_runs.csv: with a new study at
   300 kPa the earlier rows come back unchanged beside the new ones, a run
   given twice (the kept file and its study again) is refused, and a
   STRESS=DIR given after --runs (which takes every name after it) is
   refused with a message saying so.
"""
import csv
import os
import subprocess

import scene_util as su

HEADER = ("name,rule,soil,side,seed,ranks,wall_s,steps,at_rest,lid_stress_Pa,"
          "primary_mass_pct,loose_number_pct\n")


def study(path, rows):
    os.makedirs(path, exist_ok=True)
    with open(os.path.join(path, "study.csv"), "w") as f:
        f.write(HEADER)
        for r in rows:
            f.write(r + "\n")
    return path


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    tool = os.path.join(args.source, "tools", "stress_curve.py")
    a = study(os.path.join(args.work, "s1e5"), [
        "DA_cu2.0_side7.7_seed1,discrete,cu2.0,7.7,1,1,1,1000,yes,100200,60.0,70.0",
        "DA_cu2.0_side7.7_seed2,discrete,cu2.0,7.7,2,1,1,1000,yes,99900,64.0,66.0",
        "DA_cu2.0_side7.7_seed3,discrete,cu2.0,7.7,3,1,1,1000,yes,100000,62.5,68.5"])
    b = study(os.path.join(args.work, "s1e4"), [
        "DA_cu2.0_side7.7_seed1,discrete,cu2.0,7.7,1,1,1,1000,yes,10010,50.0,75.0"])
    lin = study(os.path.join(args.work, "linear"), [
        "DA_cu2.0_side7.7_seed1,discrete,cu2.0,7.7,1,1,1,1000,yes,100000,66.0,63.0"])
    out = os.path.join(args.work, "out")
    p = subprocess.run(["/usr/bin/python3", tool, "1e5=" + a, "1e4=" + b, "--linear",
                        os.path.join(lin, "study.csv"), "--kappa", "1963", "--out", out],
                       capture_output=True, text=True, timeout=120)
    chk.check("exit 0 (%s)" % p.stderr.strip()[-300:], p.returncode == 0)
    rows = list(csv.DictReader(open(os.path.join(out, "stress_curve.csv")))) \
        if p.returncode == 0 else []
    got = {(r["source"], float(r["stress_Pa"])): r for r in rows}
    r = got.get(("hertz", 1e5))
    chk.check("100 kPa: mean 62.17, range 60-64 %% primary, loose 68.17 (66-70), kappa 3957 (%s)"
              % (r and [r["primary_mean"], r["primary_min"], r["primary_max"],
                        r["loose_mean"], r["kappa"]]),
              r is not None and abs(float(r["primary_mean"]) - 62.1667) < 1e-3
              and float(r["primary_min"]) == 60.0 and float(r["primary_max"]) == 64.0
              and abs(float(r["loose_mean"]) - 68.1667) < 1e-3
              and abs(float(r["kappa"]) - 3957) < 1 and r["seeds"] == "3")
    r = got.get(("hertz", 1e4))
    chk.check("10 kPa: kappa 3957 times 10^(2/3) = 18366 (%s)" % (r and r["kappa"]),
              r is not None and abs(float(r["kappa"]) - 18366) < 2)
    lin_rows = [k for k in got if k[0] == "linear"]
    chk.check("kappa 1963 drawn at 286.2 kPa (%s)" % lin_rows,
              len(lin_rows) == 1 and abs(lin_rows[0][1] - 286.2e3) < 100)
    chk.check("the figure written", os.path.isfile(os.path.join(out, "stress_curve.png")))
    c = study(os.path.join(args.work, "s3e5"), [
        "LA_cu2.5_side7.7_seed1,layerwise,cu2.5,7.7,1,1,1,1000,yes,300500,55.0,64.0"])
    out2 = os.path.join(args.work, "out2")
    p = subprocess.run(["/usr/bin/python3", tool, "3e5=" + c, "--runs",
                        os.path.join(out, "stress_runs.csv"), "--out", out2],
                       capture_output=True, text=True, timeout=120)
    rows2 = list(csv.DictReader(open(os.path.join(out2, "stress_curve.csv")))) \
        if p.returncode == 0 else []
    keep = lambda rs: sorted(tuple(sorted(r.items())) for r in rs)
    chk.check("--runs: the kept rows come back unchanged beside the new study (%d rows, %s)"
              % (len(rows2), p.stderr.strip()[-200:]),
              p.returncode == 0 and len(rows2) == len(rows) + 1
              and keep(r for r in rows2 if r["soil"] == "cu2.0") == keep(rows)
              and any(r["soil"] == "cu2.5" and r["primary_mean"] == "55" for r in rows2))
    p = subprocess.run(["/usr/bin/python3", tool, "1e5=" + a, "--runs",
                        os.path.join(out, "stress_runs.csv"), "--out", out2],
                       capture_output=True, text=True, timeout=120)
    chk.check("--runs: a run given twice is refused (%s)" % p.stderr.strip()[:200],
              p.returncode != 0 and "is given twice" in p.stderr)
    p = subprocess.run(["/usr/bin/python3", tool, "--runs", os.path.join(out, "stress_runs.csv"),
                        "3e5=" + c, "--out", out2], capture_output=True, text=True, timeout=120)
    chk.check("--runs before a STRESS=DIR: refused, saying to give the studies first (%s)"
              % p.stderr.strip()[:200],
              p.returncode != 0 and "before --runs" in p.stderr)
    p = subprocess.run(["/usr/bin/python3", tool, "1e6=" + a, "--out", out],
                       capture_output=True, text=True, timeout=120)
    chk.check("a folder given the wrong stress is refused, naming it (%s)" % p.stderr.strip()[:200],
              p.returncode != 0 and "not 1e+06 Pa" in p.stderr and "DA_cu2.0_side7.7_seed1" in p.stderr)
    p = subprocess.run(["/usr/bin/python3", tool, "abc=" + a, "--out", out],
                       capture_output=True, text=True, timeout=120)
    chk.check("STRESS=DIR without a number is refused (%s)" % p.stderr.strip()[:200],
              p.returncode != 0 and "give STRESS=DIR" in p.stderr)
    return chk.finish()


if __name__ == "__main__":
    raise SystemExit(main())
