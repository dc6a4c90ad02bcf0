#!/usr/bin/python3
"""The answer against the vertical stress: primary % by mass and loose % by
number of oedometer studies run at several stresses (tools/oedometer_study.py
with --var hertz=1 stress=S, one study folder per stress).

    /usr/bin/python3 tools/stress_curve.py 1e4=out/stress_hz/s1e4 1e5=out/stress_hz/s1e5 ... \\
        [--linear CSV ... --kappa 1963] [--runs stress_runs.csv ...]
        [--youngs 70e9 --poisson 0.25] [--soils cu2.0 ...] [--out DIR]

Each STRESS=DIR names the target stress (Pa) of the study in DIR (its
study.csv); a row whose measured lid stress is more than 5 % off the stress
given is refused (a folder given the wrong stress). --linear adds the rows
of a study with linear springs at the stiffness number --kappa, drawn at
the stress where Hertz contacts of the material (--youngs, --poisson; quartz
by default) have that secant stiffness number, (2 Y*/(3 sigma))^(2/3) =
kappa (docs/method.md): the stress those springs stand for. --runs adds
the rows of an earlier stress_runs.csv as they are (runs whose folders are
gone: a curve is extended by new studies without running the old ones
again). A run given twice (same source, stress, rule, soil and seed) is
refused. Writes into OUT (default out/stress_curve):

  stress_runs.csv   one row per run: stress, rule, soil, seed, at rest,
                    lid stress, primary % by mass, loose % by number, steps
  stress_curve.csv  per rule, soil and stress: seeds, mean, min and max of
                    both, and the stiffness number of the material there
  stress_curve.png  both against the stress (log scale), a bar for the seeds'
                    range, the paper's 40-90 % of the mass shaded
"""
import argparse
import csv
import os
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt


def secant_kappa(stress, youngs, poisson):
    ystar = youngs / (2.0 * (1.0 - poisson ** 2))
    return (2.0 * ystar / (3.0 * stress)) ** (2.0 / 3.0)


def stress_of_kappa(kappa, youngs, poisson):
    ystar = youngs / (2.0 * (1.0 - poisson ** 2))
    return 2.0 * ystar / (3.0 * kappa ** 1.5)


def read_study(path, stress, source):
    csv_path = os.path.join(path, "study.csv") if os.path.isdir(path) else path
    if not os.path.isfile(csv_path):
        sys.exit("stress_curve: no study.csv at %s" % csv_path)
    rows = []
    for r in csv.DictReader(open(csv_path)):
        lid = float(r["lid_stress_Pa"])
        if source == "hertz" and abs(lid / stress - 1.0) > 0.05:
            sys.exit("stress_curve: %s: %s has a lid stress of %.0f Pa, not %g Pa: "
                     "is the folder given the right stress?" % (csv_path, r["name"], lid, stress))
        rows.append({"stress": stress, "source": source, "rule": r["rule"], "soil": r["soil"],
                     "seed": r["seed"], "at_rest": r["at_rest"], "lid_stress_Pa": lid,
                     "primary": float(r["primary_mass_pct"]),
                     "loose": float(r["loose_number_pct"]), "steps": int(r["steps"])})
    return rows


def summarise(rows, youngs, poisson):
    groups = {}
    for r in rows:
        groups.setdefault((r["source"], r["rule"], r["soil"], r["stress"]), []).append(r)
    out = []
    for (source, rule, soil, stress), g in sorted(groups.items()):
        p = np.array([r["primary"] for r in g])
        n = np.array([r["loose"] for r in g])
        out.append({"source": source, "rule": rule, "soil": soil, "stress_Pa": stress,
                    "kappa": secant_kappa(stress, youngs, poisson), "seeds": len(g),
                    "at_rest": sum(r["at_rest"] == "yes" for r in g),
                    "primary_mean": p.mean(), "primary_min": p.min(), "primary_max": p.max(),
                    "loose_mean": n.mean(), "loose_min": n.min(), "loose_max": n.max()})
    return out


def plot(summary, path):
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.3))
    keys = sorted({(s["rule"], s["soil"]) for s in summary})
    for ax, what, label in ((axes[0], "primary", "primary fabric, % of the mass"),
                            (axes[1], "loose", "loose grains, % of the number")):
        if what == "primary":
            ax.axhspan(40, 90, color="0.95", label="the paper's 40-90 %")
        for k, (rule, soil) in enumerate(keys):
            col = "C%d" % k
            tag = "%s %s" % ("DA" if rule == "discrete" else "LA", soil.replace("cu", "Cu "))
            for source, style in (("hertz", "-o"), ("linear", "s")):
                sel = sorted((s for s in summary if (s["rule"], s["soil"], s["source"])
                              == (rule, soil, source)), key=lambda s: s["stress_Pa"])
                if not sel:
                    continue
                x = np.array([s["stress_Pa"] / 1e3 for s in sel])
                y = np.array([s[what + "_mean"] for s in sel])
                err = np.array([[s[what + "_mean"] - s[what + "_min"] for s in sel],
                                [s[what + "_max"] - s[what + "_mean"] for s in sel]])
                lab = tag + (", Hertz quartz" if source == "hertz"
                             else ", linear kappa %.0f (at the stress where quartz has it)"
                             % sel[0]["kappa"])
                ax.errorbar(x, y, yerr=err, fmt=style, color=col, capsize=3, label=lab,
                            mfc="none" if source == "linear" else col, ms=7)
        ax.set_xscale("log")
        ax.set_xlabel("vertical stress (kPa), log scale")
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
    axes[0].legend(fontsize=7)
    fig.suptitle("The answer against the stress (side 7.7, three seeds: bars the range)")
    fig.tight_layout()
    fig.savefig(path, dpi=130)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("studies", nargs="*", metavar="STRESS=DIR")
    ap.add_argument("--runs", nargs="*", default=[], metavar="CSV",
                    help="rows of an earlier stress_runs.csv, taken as they are")
    ap.add_argument("--linear", nargs="*", default=[], metavar="CSV")
    ap.add_argument("--kappa", type=float)
    ap.add_argument("--youngs", type=float, default=70e9)
    ap.add_argument("--poisson", type=float, default=0.25)
    ap.add_argument("--soils", nargs="*", metavar="SOIL",
                    help="only these soils (e.g. cu2.0 cu2.5), from every study")
    ap.add_argument("--out", default=os.path.join("out", "stress_curve"))
    a = ap.parse_args()
    if a.linear and not a.kappa:
        sys.exit("stress_curve: --linear needs --kappa, the stiffness number of those runs")
    rows = []
    for item in a.studies:
        stress, sep, path = item.partition("=")
        try:
            s = float(stress)
        except ValueError:
            s = -1.0
        if not sep or s <= 0:
            sys.exit("stress_curve: %s: give STRESS=DIR with a positive stress in Pa" % item)
        rows += read_study(path, s, "hertz")
    for path in a.linear:
        rows += read_study(path, stress_of_kappa(a.kappa, a.youngs, a.poisson), "linear")
    for path in a.runs:
        if not os.path.isfile(path):
            sys.exit("stress_curve: --runs %s: no such file%s" % (
                path, " (give the STRESS=DIR studies before --runs, which takes every"
                " name after it)" if "=" in path else ""))
        for r in csv.DictReader(open(path)):
            rows.append({"stress": float(r["stress"]), "source": r["source"], "rule": r["rule"],
                         "soil": r["soil"], "seed": r["seed"], "at_rest": r["at_rest"],
                         "lid_stress_Pa": float(r["lid_stress_Pa"]),
                         "primary": float(r["primary"]), "loose": float(r["loose"]),
                         "steps": int(r["steps"])})
    seen = {}
    for r in rows:
        key = (r["source"], "%.6g" % r["stress"], r["rule"], r["soil"], r["seed"])
        if key in seen:
            sys.exit("stress_curve: the run %s (source, stress, rule, soil, seed) is given twice"
                     % (key,))
        seen[key] = True
    if a.soils:
        rows = [r for r in rows if r["soil"] in a.soils]
    if not rows:
        sys.exit("stress_curve: no run left (--soils %s)" % " ".join(a.soils or []))
    os.makedirs(a.out, exist_ok=True)
    with open(os.path.join(a.out, "stress_runs.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    summary = summarise(rows, a.youngs, a.poisson)
    with open(os.path.join(a.out, "stress_curve.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(summary[0].keys()))
        w.writeheader()
        for s in summary:
            w.writerow({k: ("%.6g" % v if isinstance(v, float) else v) for k, v in s.items()})
    plot(summary, os.path.join(a.out, "stress_curve.png"))
    print("%-7s %-9s %-6s %10s %8s %6s %22s %22s" % ("source", "rule", "soil", "stress_kPa",
                                                     "kappa", "seeds", "primary % (range)",
                                                     "loose % (range)"))
    for s in summary:
        print("%-7s %-9s %-6s %10.1f %8.0f %3d/%-2d %8.1f (%4.1f-%4.1f) %8.1f (%4.1f-%4.1f)"
              % (s["source"], s["rule"], s["soil"], s["stress_Pa"] / 1e3, s["kappa"],
                 s["at_rest"], s["seeds"], s["primary_mean"], s["primary_min"],
                 s["primary_max"], s["loose_mean"], s["loose_min"], s["loose_max"]))


if __name__ == "__main__":
    main()
