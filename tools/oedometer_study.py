#!/usr/bin/python3
"""The paper's eight models: layer-wise and discrete arrangement x Cu 2.0,
2.5, 3.0, 3.5 at porosity 0.35 in the zero-gravity oedometer, with seeds.

    /usr/bin/python3 tools/oedometer_study.py [--small | --trend | --convergence]
        [--sides 7.7] [--seeds 1 2 3] [--soils cu2.0 ...] [--rules discrete layerwise]
        [--ranks 1] [--var NAME=VALUE ...] [--jobs 2] [--out out/study]

One run of input_scripts/in.oedometer per (rule, soil, side, seed), one run
per core (--jobs), each written to OUT/runs/NAME; one CSV row per run in
OUT/study.csv as it ends (rule, soil, side, seed, then the result fields of
tools/oedometer_runs.py). Resumable: a run whose name is in the CSV is not
run again, and with --var checkpoint=N (blocks per job) a run cut off
mid-way (the session's or the queue's time limit, a kill) goes on from its
last checkpoint when the same command is given again. Progress: one line
per finished run, with the count and the elapsed time.

  (default)      the full matrix: 2 rules x 4 soils x seeds 1-3 at the
                 scene's defaults (Hertz quartz, 100 kPa, side 7.7: 53,237
                 grains of Cu 2.5, 163,210 of Cu 3.0; an hour or more per
                 Cu 3.5 run on two ranks, see docs/validation.md, Cost)
  --small        a quick look: both rules x Cu 2.0 and 2.5, seed 1, side 3.3
                 (1,100-4,200 grains, about 3 minutes on 2 cores; the test
                 tests/scene/test_study_small.py checks its findings)
  --trend        the paper's "the smaller Cu, the more primary mass" at one
                 stiffness number: DA Cu 2.0 and 2.5, seed 1, side 5.5,
                 -var kappa 1963 overlap_max 0.2 (5,300 and 19,400 grains,
                 about 2 minutes on 2 cores; out/trend; the test
                 tests/scene/test_study_trend.py checks it)
  --convergence  the size study: Cu 2.5 DA at sides 3.3, 4.4, 5.5 x seeds 1-3
  --var N=V      further -var settings of the scene for every run (e.g.
                 t_max=0.1); give each such setting its own --out folder,
                 since the run names do not carry them
  --ranks N      run each scene on N MPI ranks (names get a _ranksN suffix):
                 the rank-count check, e.g. --rules discrete --soils cu2.5
                 --sides 3.3 --seeds 1 --ranks 4, or a large soil on both
                 cores (Cu 3.5 at side 7.7: --ranks 2 --jobs 1); the summary
                 keeps each rank count a series of its own

At the end it prints, per (rule, soil, side), the mean and the range over
the seeds of primary % by mass and loose % by number.
"""
import argparse
import os
import sys
import time

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import oedometer_runs  # noqa: E402
from soils import RULES, SOILS, TAG, psd_path  # noqa: E402

ARRANGEMENTS = [rule for rule, _ in RULES]
FIELDS = ["name", "rule", "soil", "side", "seed", "ranks"] + oedometer_runs.RESULT_FIELDS


def name_of(rule, soil, side, seed, ranks=1):
    return "%s_%s_side%s_seed%s%s" % (TAG[rule], soil, side, seed,
                                      "_ranks%d" % ranks if ranks > 1 else "")


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--small", action="store_true")
    ap.add_argument("--trend", action="store_true")
    ap.add_argument("--convergence", action="store_true")
    ap.add_argument("--sides", nargs="*")
    ap.add_argument("--seeds", nargs="*")
    ap.add_argument("--soils", nargs="*")
    ap.add_argument("--rules", nargs="*", choices=ARRANGEMENTS)
    ap.add_argument("--ranks", type=int, default=1)
    ap.add_argument("--var", nargs="*", default=[], metavar="NAME=VALUE")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--out")
    return ap, ap.parse_args()


def plan(ap, a):
    """(rules, soils, sides, seeds, extra scene variables) of the chosen
    study, narrowed by --rules/--soils/--sides/--seeds, with --var added."""
    extra = {}
    if a.small + a.trend + a.convergence > 1:
        ap.error("give one of --small, --trend, --convergence")
    if a.small:
        rules, soils, sides, seeds = ARRANGEMENTS, SOILS[:2], ["3.3"], ["1"]
    elif a.trend:
        # kappa fixed for both soils (K_n = kappa stress d_N); the default's
        # fixed K_n is 1.6 times softer, relative to the load, for Cu 2.5
        rules, soils, sides, seeds = ["discrete"], SOILS[:2], ["5.5"], ["1"]
        extra = {"kappa": "1963", "overlap_max": "0.2"}
    elif a.convergence:
        rules, soils, sides, seeds = ["discrete"], ["cu2.5"], ["3.3", "4.4", "5.5"], ["1", "2", "3"]
    else:
        rules, soils, sides, seeds = ARRANGEMENTS, SOILS, ["7.7"], ["1", "2", "3"]
    rules, soils = a.rules or rules, a.soils or soils
    sides, seeds = a.sides or sides, a.seeds or seeds
    for s in soils:
        if not os.path.exists(psd_path(s, ROOT)):
            ap.error("no PSD file %s" % psd_path(s))
    os.makedirs(a.out, exist_ok=True)
    for nv in a.var:
        if "=" not in nv:
            ap.error("--var %s: give NAME=VALUE" % nv)
        k, v = nv.split("=", 1)
        extra[k] = v
    if a.ranks < 1:
        ap.error("--ranks %d: must be at least 1" % a.ranks)
    return rules, soils, sides, seeds, extra


def runner(out, extra, ntodo, t0):
    """The function that runs one cell (rule, soil, side, seed, ranks) of
    the matrix and prints its line: its study.csv row, or None."""
    count = [0]

    def one(m):
        rule, soil, side, seed, ranks = m
        name = name_of(*m)
        row = oedometer_runs.run_scene(
            os.path.join(out, "runs", name),
            {"psd": psd_path(soil), "arrangement": rule,
             "side": side, "seed": seed, **extra}, ranks)
        count[0] += 1
        if row is None:
            print("[%d/%d] %s FAILED (see its screen.txt)" % (count[0], ntodo, name), flush=True)
            return None
        row.update({"name": name, "rule": rule, "soil": soil, "side": side, "seed": seed,
                    "ranks": str(ranks)})
        print("[%d/%d, %.0f s] %-28s %8s grains  primary %6s %% by mass  loose %6s %% by number  "
              "%s s%s" % (count[0], ntodo, time.time() - t0, name, row["grains"],
                          row["primary_mass_pct"], row["loose_number_pct"], row["wall_s"],
                          "" if row["at_rest"] == "yes" else "  (NOT at rest: t_max)"), flush=True)
        return row
    return one


def print_summary(rows, rules, soils, sides):
    """Per model and rank count: seeds, primary % by mass and loose % by
    number (mean, range)."""
    print("\nrule      soil   side  ranks  seeds  primary % by mass (mean, range)  loose % by number (mean, range)")
    for r in rules:
        for s in soils:
            for d in sides:
                for n in sorted({x.get("ranks") or "1" for x in rows}, key=int):
                    # runs on another rank count are another series (rank
                    # count acts as a seed in DEM), not more seeds of this one
                    got = [x for x in rows if x["rule"] == r and x["soil"] == s and x["side"] == d
                           and (x.get("ranks") or "1") == n]
                    if not got:
                        continue
                    p = [float(x["primary_mass_pct"]) for x in got]
                    lo = [float(x["loose_number_pct"]) for x in got]
                    print("%-9s %-6s %-5s %5s %6d  %6.1f  %5.1f-%5.1f                %6.1f  %5.1f-%5.1f"
                          % (r, s, d, n, len(got), sum(p) / len(p), min(p), max(p),
                             sum(lo) / len(lo), min(lo), max(lo)))


def main():
    ap, a = parse_args()
    if a.out is None:
        a.out = os.path.join(ROOT, "out", "trend" if a.trend else "study")
    rules, soils, sides, seeds, extra = plan(ap, a)
    csv_path = os.path.join(a.out, "study.csv")
    matrix = [(r, s, d, e, a.ranks) for r in rules for s in soils for d in sides for e in seeds]
    order = [name_of(*m) for m in matrix]
    done = {row["name"] for row in oedometer_runs.read_rows(csv_path)}
    todo = [m for m in matrix if name_of(*m) not in done]
    print("%d runs in the matrix, %d done, %d to run, %d at a time; rows go to %s"
          % (len(matrix), len(matrix) - len(todo), len(todo), a.jobs, csv_path), flush=True)
    if todo:
        one = runner(a.out, extra, len(todo), time.time())
        oedometer_runs.run_all(todo, a.jobs, one, csv_path, FIELDS, order)
    print_summary(oedometer_runs.read_rows(csv_path), rules, soils, sides)


if __name__ == "__main__":
    main()
