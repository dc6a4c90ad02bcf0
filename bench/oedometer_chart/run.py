#!/usr/bin/python3
"""Speed against accuracy of the oedometer scene: one factor at a time.

    /usr/bin/python3 bench/oedometer_chart/run.py [--jobs 2] [--out DIR] [--runs DIR]
                          [--set numerics|model|all|converged|model55|quartz] [--only NAME ...] [--plot-only]

Runs input_scripts/in.oedometer (Cu 2.5, discrete arrangement, porosity 0.35,
a cube of side 3.3 coarsest diameters unless the variant sets it)
once per variant of the table VARIANTS below: the default setting, each
factor moved alone to a cheaper and to a more refined value, and seeds 2 and 3
of the default for the seed spread. One run per core (--jobs), resumable: a
variant with a row in DIR/chart.csv is not run again (delete the row to
redo it). Every run writes its LIGGGHTS output under RUNS/NAME (--runs,
default out/oedometer_chart).

Each row: the variant, its factor and value, wall time (s), steps, whether
the run stopped at rest, the lid stress, primary fabric % by mass, loose % by
number, the OZ % of the mass and grains. The chart (DIR/chart.png) draws, per
factor, the deviation of the primary % by mass from that factor's most
refined run against the wall time (a point per run, a line per factor), with
the seed spread of the default as a band. The model choices (MODEL_VARIANTS:
rolling resistance eta, sliding friction mu, the rolling model, the
specimen's porosity) go to DIR/model.png, primary % against the value.
Default DIR: out/oedometer_chart (the measurements kept with the
documentation live under results/: give --out for them).
"""
import argparse
import os
import sys

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), "..", ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import oedometer_runs  # noqa: E402  (the one runner of the scene)
from oedometer_runs import read_rows  # noqa: E402

# name, factor, value as printed, -var overrides, ranks, refined
# ("refined": this factor's reference, the most refined value of the sweep)
VARIANTS = [
    ("default",       "default",    "",      {},                      1, False),
    ("seed2",         "seed",       "2",     {"seed": "2"},           1, False),
    ("seed3",         "seed",       "3",     {"seed": "3"},           1, False),
    ("lid_fast",      "lid rate",   "kp 0.8", {"kp": "0.8"},          1, False),
    ("lid_slow",      "lid rate",   "kp 0.05", {"kp": "0.05"},        1, True),
    ("mass_1e5",      "mass scaling", "1e5", {"mass_scale": "1e5"},   1, False),
    ("mass_1e3",      "mass scaling", "1e3", {"mass_scale": "1e3"},   1, True),
    ("zeta_0.5",      "damping ratio", "0.5", {"zeta": "0.5"},        1, False),
    ("zeta_0.25",     "damping ratio", "0.25", {"zeta": "0.25"},      1, True),
    ("dt_0.4",        "time step",  "dtfac 0.4", {"dtfac": "0.4"},    1, False),
    ("dt_0.1",        "time step",  "dtfac 0.1", {"dtfac": "0.1"},    1, True),
    ("ke_1e-3",       "KE threshold", "ke_vrms 1e-3", {"ke_vrms": "1e-3"}, 1, False),
    ("ke_1e-5",       "KE threshold", "ke_vrms 1e-5", {"ke_vrms": "1e-5"}, 1, True),
    ("steady_4",      "steadiness", "pf_tol 4", {"pf_tol": "4"},      1, False),
    ("steady_0.25",   "steadiness", "pf_tol 0.25", {"pf_tol": "0.25"}, 1, True),
    ("thr_1e-2",      "force threshold", "1e-2", {"threshold": "1e-2"}, 1, False),
    ("thr_1e-4",      "force threshold", "1e-4", {"threshold": "1e-4"}, 1, False),
    ("thr_1e-5",      "force threshold", "1e-5", {"threshold": "1e-5"}, 1, True),
    ("prune_iterate", "prune",      "iterate", {"prune": "iterate"},  1, False),
    ("ranks_2",       "ranks",      "2",     {},                      2, False),
    ("side_4.4",      "specimen size", "side 4.4", {"side": "4.4"},   1, False),
    ("side_5.5",      "specimen size", "side 5.5", {"side": "5.5"},   1, True),
]
# The model choices (item "model no more than the scene needs"): what each
# does to the answer, against the default (eta 1, mu 0.4, porosity 0.35,
# epsd3, tangential dashpot on, walls as rough as the grains). Drawn as
# primary % against the value, a panel per factor.
MODEL_VARIANTS = [
    ("eta_0",         "rolling eta", "0",    {"eta": "0"},            1, False),
    ("eta_0.25",      "rolling eta", "0.25", {"eta": "0.25"},         1, False),
    ("eta_0.5",       "rolling eta", "0.5",  {"eta": "0.5"},          1, False),
    ("mu_0.2",        "sliding mu",  "0.2",  {"mu": "0.2"},           1, False),
    ("mu_0.8",        "sliding mu",  "0.8",  {"mu": "0.8"},           1, False),
    ("rolling_epsd",  "rolling model", "epsd", {"rolling": "epsd"},   1, False),
    ("porosity_0.38", "porosity",    "0.38", {"porosity": "0.38"},    1, False),
    ("porosity_0.42", "porosity",    "0.42", {"porosity": "0.42"},    1, False),
    ("tdamp_off",     "tangential damping", "off", {"tdamp": "off"},  1, False),
    ("mu_wall_0",     "wall friction", "0",  {"mu_wall": "0"},        1, False),
    ("hertz",         "normal contact", "Hertz", {"hertz": "1", "kn": "0", "overlap_max": "0.2"}, 1, False),
    ("servo_pi",      "servo",       "PI, ki 200/s", {"ki": "200"},   1, False),
]
MODEL_DEFAULTS = {"rolling eta": "1", "sliding mu": "0.4", "rolling model": "epsd3",
                  "porosity": "0.35", "tangential damping": "on", "wall friction": "0.4",
                  "normal contact": "Hooke", "servo": "P"}
# every variant runs on this base (the quick-look size of the main job, 4,188
# grains of Cu 2.5, and the time step, t_max, servo and energy limit the
# chart was measured with: the scene's defaults before the PI servo and
# ke_vrms 2e-4, whose knee at the default size docs/user_guide.md shows);
# a variant's own settings replace it
BASE = {"side": "3.3", "kn": "2e7", "dtfac": "0.2", "t_max": "0.1", "ki": "0", "ke_vrms": "1e-4"}
# The chart at the converged setting (--set converged, chart_side5.5.csv and
# .png): the scene's former defaults (side 5.5, linear kn 2e7 N/m, PI servo, ke_vrms 2e-4,
# dtfac 0.4), Cu 2.5 DA, every run on 2 ranks and one run at a time (--jobs
# 1), so that the wall times compare: each factor once cheaper and once more
# refined than the default where both exist. Not here: pf_tol 4 (the
# steadiness rule is not what stops the default run, the energy limit is)
# and the damping ratio (a model parameter: docs/user_guide.md).
CONVERGED_BASE = {"side": "5.5", "kn": "2e7"}
CONVERGED_VARIANTS = [
    ("default",       "default",    "",      {},                      2, False),
    ("seed2",         "seed",       "2",     {"seed": "2"},           2, False),
    ("seed3",         "seed",       "3",     {"seed": "3"},           2, False),
    ("lid_fast",      "lid rate",   "kp 0.8", {"kp": "0.8"},          2, False),
    ("lid_slow",      "lid rate",   "kp 0.05", {"kp": "0.05"},        2, True),
    ("mass_2e4",      "mass scaling", "2e4", {"mass_scale": "2e4"},   2, False),
    ("mass_2.5e3",    "mass scaling", "2.5e3", {"mass_scale": "2.5e3"}, 2, True),
    ("dt_0.2",        "time step",  "dtfac 0.2", {"dtfac": "0.2"},    2, True),
    ("ke_4e-4",       "KE threshold", "ke_vrms 4e-4", {"ke_vrms": "4e-4"}, 2, False),
    ("ke_1e-4",       "KE threshold", "ke_vrms 1e-4", {"ke_vrms": "1e-4"}, 2, True),
    ("steady_0.25",   "steadiness", "pf_tol 0.25", {"pf_tol": "0.25"}, 2, True),
    ("thr_1e-2",      "force threshold", "1e-2", {"threshold": "1e-2"}, 2, False),
    ("thr_1e-4",      "force threshold", "1e-4", {"threshold": "1e-4"}, 2, False),
    ("thr_1e-5",      "force threshold", "1e-5", {"threshold": "1e-5"}, 2, True),
    ("prune_iterate", "prune",      "iterate", {"prune": "iterate"},  2, False),
    ("ranks_1",       "ranks",      "1",     {},                      1, False),
    ("ranks_4",       "ranks",      "4",     {},                      4, False),
    ("side_3.3",      "specimen size", "side 3.3", {"side": "3.3"},   2, False),
    ("side_4.4",      "specimen size", "side 4.4", {"side": "4.4"},   2, False),
    ("side_6.6",      "specimen size", "side 6.6", {"side": "6.6"},   2, True),
]
# The model choices at the converged setting (--set model55, model_side5.5.csv
# and .png): as CONVERGED_VARIANTS, 2 ranks, one run at a time; the default
# and its seeds are the converged chart's rows. Most needed first: the
# rolling resistance eta over 0-1, then sliding and wall friction.
MODEL55_VARIANTS = [
    ("eta_0.5",       "rolling eta", "0.5",  {"eta": "0.5"},          2, False),
    ("eta_0",         "rolling eta", "0",    {"eta": "0"},            2, False),
    ("eta_0.25",      "rolling eta", "0.25", {"eta": "0.25"},         2, False),
    ("mu_0.2",        "sliding mu",  "0.2",  {"mu": "0.2"},           2, False),
    ("mu_0.8",        "sliding mu",  "0.8",  {"mu": "0.8"},           2, False),
    ("mu_wall_0",     "wall friction", "0",  {"mu_wall": "0"},        2, False),
    ("porosity_0.42", "porosity",    "0.42", {"porosity": "0.42"},    2, False),
    ("servo_p",       "servo",       "P (ki 0)", {"ki": "0"},         2, False),
    ("hertz_1",       "normal contact", "Hertz", {"hertz": "1", "kn": "0", "overlap_max": "0.2"}, 2, False),
]
MODEL55_DEFAULTS = {"rolling eta": "1", "sliding mu": "0.4", "wall friction": "0.4",
                    "porosity": "0.35", "servo": "PI, ki 200/s", "normal contact": "Hooke"}
# The chart at the material setting (--set quartz, chart_quartz_side7.7.csv
# and .png, model_quartz_side7.7.png): Hertz-Mindlin quartz (hertz 1, the
# scene's material defaults) at 100 kPa, Cu 2.5 DA, side 7.7 (53,237 grains),
# every run on 1 rank, two at a time (--jobs 2): the particle-steps panel is
# the cost that machine noise does not change. Run in the order of quartz()'s
# list: the levers that could halve the cost (each factor's cheaper value),
# the refined runs that place the default, the model choices, then the rest.
# The chart was measured under the former kinetic-energy rest rule (zeta 0.6,
# rest_tol 0, one density), which the base keeps so that it regenerates
# results/settings/chart.
QUARTZ_BASE = {"side": "7.7", "hertz": "1", "zeta": "0.6", "rest_tol": "0", "dt_gain": "1"}
QUARTZ_VARIANTS = [
    ("default",       "default",    "",      {},                      1, False),
    ("mass_4e4",      "mass scaling", "4e4", {"mass_scale": "4e4"},   1, False),
    ("ke_4e-4",       "KE threshold", "ke_vrms 4e-4", {"ke_vrms": "4e-4"}, 1, False),
    ("every_1000",    "check interval", "every 1000", {"every": "1000"}, 1, False),
    ("lid_fast",      "lid rate",   "kp 0.4", {"kp": "0.4"},          1, False),
    ("skin_1e-4",     "neighbour skin", "1e-4 m", {"skin": "1e-4"},   1, False),
    ("dt_0.2",        "time step",  "dtfac 0.2", {"dtfac": "0.2"},    1, True),
    # lighter grains with the lid as fast per step as the default's (kp
    # halved with the time step): at kp 0.2, mass_scale 1e3 swings the lid
    ("mass_2.5e3",    "mass scaling", "2.5e3, kp 0.1", {"mass_scale": "2.5e3", "kp": "0.1"}, 1, True),
    ("ke_1e-4",       "KE threshold", "ke_vrms 1e-4", {"ke_vrms": "1e-4"}, 1, True),
    ("lid_slow",      "lid rate",   "kp 0.05", {"kp": "0.05"},        1, True),
    ("steady_0.25",   "steadiness", "pf_tol 0.25", {"pf_tol": "0.25"}, 1, True),
    ("every_4000",    "check interval", "every 4000", {"every": "4000"}, 1, True),
    ("skin_2.5e-5",   "neighbour skin", "2.5e-5 m", {"skin": "2.5e-5"}, 1, True),
    ("thr_1e-2",      "force threshold", "1e-2", {"threshold": "1e-2"}, 1, False),
    ("thr_1e-5",      "force threshold", "1e-5", {"threshold": "1e-5"}, 1, True),
    ("ranks_2",       "ranks",      "2",     {},                      2, False),
    # a job of 4 blocks at a time, each going on from the last one's
    # checkpoint (3 resumes): its reference is the uninterrupted 2-rank run
    ("resume_4",      "resume",     "checkpoint 4, 2 ranks", {"checkpoint": "4"}, 2, False),
    ("side_6.6",      "specimen size", "side 6.6", {"side": "6.6"},   1, False),
    ("side_8.8",      "specimen size", "side 8.8", {"side": "8.8"},   1, True),
    ("seed2",         "seed",       "2",     {"seed": "2"},           1, False),
    ("seed3",         "seed",       "3",     {"seed": "3"},           1, False),
]
QUARTZ_MODEL_VARIANTS = [
    ("stress_3e4",    "stress (kPa)", "30",  {"stress": "3e4"},       1, False),
    ("stress_3e5",    "stress (kPa)", "300", {"stress": "3e5"},       1, False),
    ("linear_3957",   "normal contact", "linear, kappa 3957", {"hertz": "0", "kappa": "3957"}, 1, False),
    ("eta_0.5",       "rolling eta", "0.5",  {"eta": "0.5"},          1, False),
    ("mu_0.2",        "sliding mu",  "0.2",  {"mu": "0.2"},           1, False),
    # (mu 0.8, like 0.6, throws grains out of the container within 4,000
    # steps with Hertz quartz at dtfac 0.4: README.md)
    ("mu_wall_0",     "wall friction", "0",  {"mu_wall": "0"},        1, False),
    ("zeta_0.3",      "damping ratio", "0.3", {"zeta": "0.3"},        1, False),
]
QUARTZ_MODEL_DEFAULTS = {"stress (kPa)": "100", "normal contact": "Hertz", "rolling eta": "1",
                         "sliding mu": "0.4", "wall friction": "0.4", "damping ratio": "0.6"}
# prune and ranks have no "more refined" value: their reference is the default
FIELDS = ["name", "factor", "value"] + oedometer_runs.RESULT_FIELDS


def run_variant(v, rundir_root, base):
    name, factor, value, over, ranks, _ = v
    row = oedometer_runs.run_scene(os.path.join(rundir_root, name), dict(base, **over), ranks)
    if row:
        row.update({"name": name, "factor": factor, "value": value})
    return row


def _wall(r):
    return float(r["wall_s"])


def _particle_steps(r):
    return float(r["steps"]) * float(r["grains"])


def plot(rows, png, variants=VARIANTS, title=None, xlabel=None, steps_panel=False, symlog=False):
    """Error against cost, a line per factor; with steps_panel a second panel
    against particle-steps (steps x grains), the cost that machine noise
    does not change."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    by = {r["name"]: r for r in rows}
    if "default" not in by:
        sys.stderr.write("no default run yet: nothing to plot\n")
        return
    seeds = [float(by[n]["primary_mass_pct"]) for n in ("default", "seed2", "seed3") if n in by]
    spread = (max(seeds) - min(seeds)) if len(seeds) > 1 else 0.0
    panels = [(_wall, xlabel or "wall time of the run (s, one core unless 'ranks')")]
    if steps_panel:
        panels.append((_particle_steps, "particle-steps of the run (steps x grains)"))
    fig, axes = plt.subplots(1, len(panels), figsize=(8 * len(panels), 5.5), squeeze=False)
    factors = []
    for v in variants:
        if v[1] not in ("default", "seed") and v[1] not in factors:
            factors.append(v[1])
    for ax, (cost, label) in zip(axes[0], panels):
        for fac in factors:
            members = [v for v in variants if v[1] == fac and v[0] in by]
            ref = [v for v in members if v[5]]
            ref_row = by[ref[0][0]] if ref else by["default"]
            pts = [by["default"]] + [by[v[0]] for v in members]
            pts.sort(key=cost)
            x = [cost(r) for r in pts]
            y = [abs(float(r["primary_mass_pct"]) - float(ref_row["primary_mass_pct"])) for r in pts]
            line, = ax.plot(x, y, "o-", label=fac)
            for r, xx, yy in zip(pts, x, y):
                if r["name"] != "default":
                    ax.annotate(r["value"], (xx, yy), fontsize=7, xytext=(3, 3),
                                textcoords="offset points", color=line.get_color())
                else:  # the default at its distance from this factor's refined run
                    ax.plot([xx], [yy], "*", ms=12, color=line.get_color(), mec="k")
        ax.plot([], [], "k*", ms=12, label="default (on each factor's line)")
        ax.axhspan(0, spread, color="0.85", zorder=0,
                   label="seed spread (3 seeds): %.1f points" % spread)
        ax.set_xscale("log")
        if symlog:  # prune iterate lies 40 points off: linear up to 1 point, log above
            ax.set_yscale("symlog", linthresh=1.0)
            ax.set_ylim(bottom=0.0)
        ax.set_xlabel(label)
        ax.set_ylabel("|primary fabric % by mass - factor's most refined run| (points)")
        ax.legend(fontsize=7, ncol=2)
    fig.suptitle(title or "Oedometer, Cu 2.5 DA, porosity 0.35: error against cost, one factor at a time")
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print(png)


def plot_model(rows, png, variants=MODEL_VARIANTS, defaults=MODEL_DEFAULTS, title=None):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    by = {r["name"]: r for r in rows}
    if "default" not in by:
        return
    seeds = [float(by[n]["primary_mass_pct"]) for n in ("default", "seed2", "seed3") if n in by]
    factors = [f for f in defaults if any(v[1] == f and v[0] in by for v in variants)]
    if not factors:
        return
    fig, axes = plt.subplots(1, len(factors), figsize=(max(4.0, 3.2 * len(factors)), 4.0), sharey=True,
                             squeeze=False)
    axes = axes[0]
    for ax, fac in zip(axes, factors):
        pts = [(defaults[fac], by["default"])] + [
            (v[2], by[v[0]]) for v in variants if v[1] == fac and v[0] in by]
        numeric = all(_isnum(x) for x, _ in pts)
        if numeric:
            pts.sort(key=lambda p: float(p[0]))
        xs = [float(x) for x, _ in pts] if numeric else list(range(len(pts)))
        ax.plot(xs, [float(r["primary_mass_pct"]) for _, r in pts], "o-", label="primary % by mass")
        ax.plot(xs, [100.0 - float(r["loose_number_pct"]) for _, r in pts], "s--",
                label="100 - loose % by number")
        if not numeric:
            ax.set_xticks(xs)
            ax.set_xticklabels([x for x, _ in pts])
        if seeds:
            ax.axhspan(min(seeds), max(seeds), color="0.88", zorder=0)
        ax.set_title(fac)
        ax.set_xlabel(fac)
    axes[0].set_ylabel("% (grey: default over 3 seeds)")
    axes[0].legend(fontsize=7)
    fig.suptitle(title or "Oedometer, Cu 2.5 DA: the answer against the model choices (one seed each)")
    fig.tight_layout()
    fig.savefig(png, dpi=120)
    print(png)


def _isnum(x):
    try:
        float(x)
        return True
    except ValueError:
        return False


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "oedometer_chart"),
                    help="where chart.csv and chart.png go")
    ap.add_argument("--runs", default=os.path.join(ROOT, "out", "oedometer_chart"),
                    help="where each run's LIGGGHTS output goes")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--only", nargs="*", help="run only these variants")
    ap.add_argument("--plot-only", action="store_true")
    ap.add_argument("--set", choices=("numerics", "model", "all", "converged", "model55", "quartz"),
                    default="all",
                    help="the numerical factors (chart.png), the model choices (model.png), both; "
                         "at the converged setting: the chart (chart_side5.5.csv and .png) or "
                         "the model choices (model_side5.5.csv and .png); at the material setting "
                         "(quartz): chart_quartz_side7.7.csv, its chart and model-choice PNGs")
    a = ap.parse_args()
    os.makedirs(a.out, exist_ok=True)
    if a.set in ("converged", "model55"):
        converged(a)
        return
    if a.set == "quartz":
        quartz(a)
        return
    csv_path = os.path.join(a.out, "chart.csv")
    rows = read_rows(csv_path)
    done = {r["name"] for r in rows}
    table = {"numerics": VARIANTS, "model": VARIANTS[:3] + MODEL_VARIANTS,
             "all": VARIANTS + MODEL_VARIANTS}[a.set]
    todo = [v for v in table if v[0] not in done and (not a.only or v[0] in a.only)]
    if not a.plot_only and todo:
        print("%d runs to do (%d done), %d at a time" % (len(todo), len(done), a.jobs), flush=True)

        def one(v):
            row = run_variant(v, a.runs, BASE)
            if row:
                print("%-14s %-16s %-12s %7s s  primary %6s %%  loose %6s %%  at rest %s" % (
                    row["name"], row["factor"], row["value"], row["wall_s"], row["primary_mass_pct"],
                    row["loose_number_pct"], row["at_rest"]), flush=True)
            return row

        oedometer_runs.run_all(todo, a.jobs, one, csv_path, FIELDS,
                               [v[0] for v in VARIANTS + MODEL_VARIANTS])
    plot(read_rows(csv_path), os.path.join(a.out, "chart.png"))
    plot_model(read_rows(csv_path), os.path.join(a.out, "model.png"))


def run_table(a, table, csv_path, rundir_root, base):
    """Run the variants of table that have no row in csv_path yet (--only
    narrows them), --jobs at a time, each row written as it comes."""
    rows = read_rows(csv_path)
    done = {r["name"] for r in rows}
    todo = [v for v in table if v[0] not in done and (not a.only or v[0] in a.only)]
    if a.plot_only or not todo:
        return
    print("%d runs to do (%d done), %d at a time" % (len(todo), len(done), a.jobs), flush=True)

    def one(v):
        print("start %s" % v[0], flush=True)
        row = run_variant(v, rundir_root, base)
        if row:
            print("%-14s %-16s %-12s %7s s  %s steps  primary %6s %%  loose %6s %%  at rest %s" % (
                row["name"], row["factor"], row["value"], row["wall_s"], row["steps"],
                row["primary_mass_pct"], row["loose_number_pct"], row["at_rest"]), flush=True)
        return row

    oedometer_runs.run_all(todo, a.jobs, one, csv_path, FIELDS, [v[0] for v in table])


def converged(a):
    """The chart (or the model choices) at the converged setting: one run at a
    time unless --jobs."""
    model = a.set == "model55"
    table = MODEL55_VARIANTS if model else CONVERGED_VARIANTS
    csv_path = os.path.join(a.out, "model_side5.5.csv" if model else "chart_side5.5.csv")
    run_table(a, table, csv_path, os.path.join(a.runs, "side5.5"), CONVERGED_BASE)
    if model:
        # the default and its seeds: the converged chart's runs
        chart = [r for r in read_rows(os.path.join(a.out, "chart_side5.5.csv"))
                 if r["name"] in ("default", "seed2", "seed3")]
        plot_model(chart + read_rows(csv_path), os.path.join(a.out, "model_side5.5.png"),
                   MODEL55_VARIANTS, MODEL55_DEFAULTS,
                   "At the converged setting\n(Cu 2.5 DA, side 5.5, one seed each)")
        return
    plot(read_rows(csv_path), os.path.join(a.out, "chart_side5.5.png"), CONVERGED_VARIANTS,
         "Oedometer at the converged setting (Cu 2.5 DA, side 5.5, 19,402 grains):\n"
         "error against cost, one factor at a time",
         "wall time of the run (s, 2 ranks, one run at a time, unless 'ranks')", steps_panel=True,
         symlog=True)


def quartz(a):
    """The chart and the model choices at the material setting, one CSV."""
    table = QUARTZ_VARIANTS + QUARTZ_MODEL_VARIANTS
    # the run order: the cheaper levers, the references that decide the
    # default's distance, the model choices, then the rest
    first = ["default", "mass_4e4", "ke_4e-4", "every_1000", "lid_fast", "skin_1e-4",
             "dt_0.2", "ke_1e-4", "side_8.8"] + [v[0] for v in QUARTZ_MODEL_VARIANTS]
    table.sort(key=lambda v: first.index(v[0]) if v[0] in first else len(first))
    csv_path = os.path.join(a.out, "chart_quartz_side7.7.csv")
    run_table(a, table, csv_path, os.path.join(a.runs, "quartz"), QUARTZ_BASE)
    rows = read_rows(csv_path)
    plot(rows, os.path.join(a.out, "chart_quartz_side7.7.png"), QUARTZ_VARIANTS,
         "Oedometer, Hertz-Mindlin quartz at 100 kPa (Cu 2.5 DA, side 7.7, 53,237 grains):\n"
         "error against cost, one factor at a time",
         "wall time of the run (s, 1 rank, two runs at a time, unless 'ranks')", steps_panel=True,
         symlog=True)
    plot_model(rows, os.path.join(a.out, "model_quartz_side7.7.png"), QUARTZ_MODEL_VARIANTS,
               QUARTZ_MODEL_DEFAULTS, "At the material setting\n(Hertz quartz, Cu 2.5 DA, side 7.7, one seed each)")


if __name__ == "__main__":
    main()
