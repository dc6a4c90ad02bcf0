#!/usr/bin/python3
"""The oedometer's stop rule replayed on finished runs: what a looser rule
would have saved, and what it would have changed in the answer.

    /usr/bin/python3 bench/stop_rule/replay.py STUDY [STUDY ...] [--csv FILE]

Each STUDY is a folder of tools/oedometer_study.py (its runs/NAME folders,
each with fabric_series.txt and screen.txt). in.oedometer checks every
`every` steps that (1) the translational kinetic energy is below
1/2 M ke_vrms^2, (2) the rms of the lid stress error over the last block is
below stress_tol and (3) the primary % by mass moved less than pf_tol points
over the last two blocks. The series holds those three numbers at every
check, so a rule with a larger ke_vrms or pf_tol (one that stops no later
than the run did) can be replayed without running anything: its stop is the
first check that passes it, its answer the primary % by mass at that check,
its cost the steps to it. The reference is the run's own stop, replayed the
same way (the series' values, not the FABRIC line of the final analysis
with the lid held still). A run that did not stop at rest is skipped.

Prints, per rule: the steps as a share of the reference's (summed over the
runs, each weighted by its grain count: particle-steps) and the largest and
mean change of the primary % by mass; --csv writes a row per run and rule.
"""
import argparse
import csv
import glob
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import outputs  # noqa: E402

RULES = [  # (name, ke_vrms factor over the run's, pf_tol, stress_tol)
    ("reference", 1.0, 1.0, 0.05),
    ("ke x1.5", 1.5, 1.0, 0.05),
    ("ke x2", 2.0, 1.0, 0.05),
    ("ke x3", 3.0, 1.0, 0.05),
    ("ke x4", 4.0, 1.0, 0.05),
    ("ke x2, pf 2", 2.0, 2.0, 0.05),
    ("pf only (1 point)", float("inf"), 1.0, 0.05),
]


def read_run(rundir):
    """(grains, ke_limit, rows [(step, ke, err_rms, primary)]) or None."""
    screen = os.path.join(rundir, "screen.txt")
    series = os.path.join(rundir, "fabric_series.txt")
    if not (os.path.isfile(screen) and os.path.isfile(series)):
        return None
    text = open(screen, errors="replace").read()
    if "STOP: at rest" not in text:
        return None
    ke = re.search(r"^KE LIMIT: (\S+) J", text, re.M)
    grains = re.search(r"^FABRIC: .*", text, re.M)
    atoms = re.findall(r"with (\d+) atoms", text)
    s = outputs.read_series(series)
    rows = [(int(st), ke, err, pf) for st, ke, err, pf in
            zip(s["step"], s["ke_translation"], s["stress_error_rms"], s["primary_mass_pct"])
            if st > 0]
    if not ke or not rows or not grains or not atoms:
        return None
    return int(atoms[-1]), float(ke.group(1)), rows


def replay(rows, ke_limit, pf_tol, stress_tol):
    """(steps, primary) at the first check passing the rule (the series'
    first loading row is the first block), or the last row."""
    for k in range(len(rows)):
        step, ke, err, _ = rows[k]
        steady = (abs(rows[k][3] - rows[k - 1][3]) + abs(rows[k - 1][3] - rows[k - 2][3])
                  if k >= 2 else float("inf"))
        if ke < ke_limit and err < stress_tol and steady < pf_tol:
            return step, rows[k][3]
    return rows[-1][0], rows[-1][3]


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("studies", nargs="+", metavar="STUDY")
    ap.add_argument("--csv", metavar="FILE")
    args = ap.parse_args()
    runs = []
    for study in args.studies:
        for rundir in sorted(glob.glob(os.path.join(study, "runs", "*"))):
            r = read_run(rundir)
            if r:
                runs.append((os.path.basename(rundir), study) + r)
    if not runs:
        sys.exit("replay: no run at rest with fabric_series.txt and screen.txt under %s"
                 % " ".join(args.studies))
    out = []
    for name, study, grains, ke_limit, rows in runs:
        ref_steps, ref_p = replay(rows, ke_limit, 1.0, 0.05)
        for rule, f, pf, st in RULES:
            steps, p = replay(rows, ke_limit * f * f, pf, st)
            out.append((rule, name, study, grains, steps, ref_steps, p, p - ref_p))
    print("%-20s %6s %18s %16s %16s" % ("rule", "runs", "particle-steps", "max |change|",
                                       "mean change"))
    for rule, *_ in RULES:
        sel = [o for o in out if o[0] == rule]
        cost = sum(o[3] * o[4] for o in sel) / sum(o[3] * o[5] for o in sel)
        ch = [o[7] for o in sel]
        worst = max(sel, key=lambda o: abs(o[7]))
        print("%-20s %6d %17.0f%% %9.2f pts (%s) %+10.2f pts"
              % (rule, len(sel), 100 * cost, abs(worst[7]), worst[1], sum(ch) / len(ch)))
    if args.csv:
        # csv quotes a rule whose name holds a comma ("ke x2, pf 2")
        with open(args.csv, "w", newline="") as fh:
            w = csv.writer(fh)
            w.writerow(["rule", "run", "study", "grains", "steps", "reference_steps",
                        "primary_mass_pct", "change_pts"])
            for o in out:
                w.writerow([o[0], o[1], o[2], "%d" % o[3], "%d" % o[4], "%d" % o[5],
                            "%.2f" % o[6], "%+.2f" % o[7]])


if __name__ == "__main__":
    main()
