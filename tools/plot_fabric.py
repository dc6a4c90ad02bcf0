#!/usr/bin/python3
"""Draw the primary-fabric figures of Galindo-Torres & Scheuermann (Figs.
11-19) as PNG files from one or more output folders of
input_scripts/in.oedometer, overlaid like the paper's LA vs DA curves.

    tools/plot_fabric.py OUTDIR [OUTDIR2 ...] [--labels DA LA ...]
                         [--png-dir DIR] [--dt SECONDS]

Reads from each OUTDIR
  fabric_series.txt     (required) time series: Figs. 11, 12
  fabric_intervals.txt  (required) the compute's global array, last block:
                        Figs. 13, 14, 17/18, 19
  fabric_global.txt     (optional) the compute's global vector: r1, r2
                        (radii), the OZ, the fabric tensors and the direction
                        bins, Figs. 15/16 and the shaded zone of Figs. 17/18
  log*/*.log            (optional) a LIGGGHTS log with the in.oedometer line
                        "TIMESTEP: ... dt = X s", to plot against time
The compute's columns and entries are found by their names in
compute_primary_fabric/fabric_outputs.h (tools/outputs.py reads it); the
tool computes none of them again: without fabric_global.txt a run has no
overlapping zone and no direction histogram in the figures.

Writes into --png-dir (default: OUTDIR for one run; for several, the folder
fabric_plots beside the first OUTDIR, e.g. out/fabric_plots) and prints the
path of every PNG written:
  fig11_loose_number.png        loose particles, % by number, vs time/step
  fig12_primary_mass.png        primary fabric, % by mass, vs time/step
  fig13_contacts_per_particle.png   loaded contacts per particle per interval
  fig14_force_per_contact.png   mean normal force per loaded contact
  fig17_18_distributions.png    cumulative PSD, PFD and LPD vs diameter (log),
                                overlapping zone shaded; one panel per run
  fig19_primary_of_interval.png primary % of each interval's own mass
  fig15_16_direction_rose.png   contact fraction and mean normal force by
                                polar angle from z (2-D rose)

Exit status: 0 on success; 2 on a usage error or when a required file is
missing or empty (nothing is drawn then).
"""
import argparse
import glob
import math
import os
import re
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
from matplotlib.ticker import FormatStrFormatter, LogLocator, NullFormatter  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import outputs  # noqa: E402  (the compute's output tables)

PROG = "plot_fabric.py"


VEC = outputs.index(outputs.fabric_vector())   # 0-based entry by name
TENSOR = ("xx", "yy", "zz", "xy", "xz", "yz")


class InputError(Exception):
    pass


def warn(msg):
    print(PROG + ": warning: " + msg, file=sys.stderr)


# ---------------------------------------------------------------- reading
def read_series(path):
    """fabric_series.txt -> {column name of outputs.SERIES_COLUMNS: array}."""
    try:
        return outputs.read_series(path)
    except (ValueError, OSError) as e:
        raise InputError(str(e))


def read_intervals(path):
    """The last block of fabric_intervals.txt: {column name of
    fabric_outputs.h: array}, 'step', 'nblocks'."""
    try:
        iv = outputs.read_intervals(path)
    except ValueError as e:
        raise InputError(str(e))
    if iv is None:
        raise InputError("%s: no data block (the final analysis has not run yet)" % path)
    return iv


def find_dt(outdir):
    pat = re.compile(r"TIMESTEP:.*dt = ([0-9.eE+-]+) s")
    for f in sorted(glob.glob(os.path.join(outdir, "log*")) +
                    glob.glob(os.path.join(outdir, "*.log"))):
        try:
            with open(f, errors="replace") as fh:
                for line in fh:
                    m = pat.search(line)
                    if m:
                        return float(m.group(1))
        except OSError:
            pass
    return None


# ---------------------------------------------------------------- a run
class Run:
    def __init__(self, outdir, label, dt_cli):
        self.dir = outdir
        self.label = label
        self.notes = []
        self.series = read_series(os.path.join(outdir, "fabric_series.txt"))
        self.iv = read_intervals(os.path.join(outdir, "fabric_intervals.txt"))
        self.dt = dt_cli if dt_cli else find_dt(outdir)

        gpath = os.path.join(outdir, "fabric_global.txt")
        self.vector = outputs.read_global(gpath)
        self.oz_tolerant = None
        self.dirs = None
        if self.vector is None:
            warn("%s: not found or without the compute's global vector; this run has "
                 "no overlapping zone and no direction histogram in the figures" % gpath)
            self.r1 = self.r2 = self.oz = 0.0
            return
        v = self.vector
        self.r1, self.r2, self.oz = (float(v[VEC[k]]) for k in (
            "r1", "r2", "overlapping_zone_percent"))
        self.oz_tolerant = tuple(float(v[VEC[k]]) for k in (
            "r1_tolerant", "r2_tolerant", "overlapping_zone_tolerant_percent"))
        fraction, force = outputs.direction_bins(v)
        self.dirs = {"fraction": fraction, "force": force,
                     "F": np.array([v[VEC["fabric_" + t]] for t in TENSOR]),
                     "Phi": np.array([v[VEC["force_fabric_" + t]] for t in TENSOR]),
                     "nloaded": int(v[VEC["loaded_contacts"]]),
                     "source": "fabric_global.txt"}

    def x_time(self, use_time):
        step = self.series["step"]
        if use_time:
            return step * self.dt * 1e3, "time (ms)"
        return step, "step"


# ---------------------------------------------------------------- figures
COLORS = plt.rcParams["axes.prop_cycle"].by_key()["color"]
MARKERS = ["o", "s", "^", "D", "v", "P", "X", "*"]


def style(i):
    return dict(color=COLORS[i % len(COLORS)], marker=MARKERS[i % len(MARKERS)])


def save(fig, pngdir, name, written):
    path = os.path.join(pngdir, name)
    fig.savefig(path, dpi=130, bbox_inches="tight")
    plt.close(fig)
    written.append(path)


def fig_series(runs, key, ylabel, title, name, pngdir, written):
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    use_time = all(r.dt for r in runs)     # one axis for all: time only if all know dt
    for i, r in enumerate(runs):
        x, xl = r.x_time(use_time)
        y = r.series.get(key)
        if y is None:
            warn("%s: fabric_series.txt has no column %s" % (r.dir, key))
            continue
        ax.plot(x, y, ms=4, lw=1.4, label=r.label, **style(i))
    ax.set_xlabel("time since the start of loading (ms)" if use_time else
                  "step (pass --dt SECONDS, or keep the LIGGGHTS log in OUTDIR, for time)")
    ax.set_ylabel(ylabel)
    ax.set_ylim(-2, 102)
    ax.set_title(title)
    ax.grid(alpha=0.3)
    ax.legend()
    save(fig, pngdir, name, written)


def fig_per_interval(runs, key, ylabel, title, name, pngdir, written, ylim=None):
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    for i, r in enumerate(runs):
        # an interval the packer left empty (a row of zeros, diameter 0) has
        # no per-particle value: left out, the line joins its neighbours
        keep = r.iv["particles"] > 0
        d = r.iv["diameter"][keep] * 1e3
        ax.plot(d, r.iv[key][keep], ms=4, lw=1.4, label=r.label, **style(i))
    log_diameter_axis(ax)
    ax.set_xlabel("interval diameter d (mm), log scale")
    ax.set_ylabel(ylabel)
    if ylim:
        ax.set_ylim(*ylim)
    else:
        ax.set_ylim(bottom=0)
    ax.set_title(title)
    ax.grid(alpha=0.3, which="both")
    ax.legend()
    save(fig, pngdir, name, written)


def log_diameter_axis(ax):
    """Log x axis in mm with readable labels (1, 2, 5 x 10^n)."""
    ax.set_xscale("log")
    ax.xaxis.set_major_locator(LogLocator(base=10, subs=(1.0, 2.0, 3.0, 5.0)))
    ax.xaxis.set_major_formatter(FormatStrFormatter("%g"))
    ax.xaxis.set_minor_formatter(NullFormatter())


def cumulative(share):
    tot = float(np.sum(share))
    if tot <= 0:
        return None, 0.0
    return 100.0 * np.cumsum(share) / tot, tot


def fig_distributions(runs, pngdir, written):
    n = len(runs)
    fig, axes = plt.subplots(1, n, figsize=(max(7.5, 5.6 * n), 4.6), sharey=True,
                             squeeze=False)
    for i, (r, ax) in enumerate(zip(runs, axes[0])):
        keep = r.iv["particles"] > 0        # an empty interval adds no mass
        d = r.iv["diameter"][keep] * 1e3
        curves = [("PSD", r.iv["mass_percent"][keep], "k", "-", "o"),
                  ("PFD (primary fabric)", r.iv["primary_mass_percent"][keep], "tab:blue", "--", "s"),
                  ("LPD (loose particles)", r.iv["loose_mass_percent"][keep], "tab:red", ":", "^")]
        for lab, share, c, ls, mk in curves:
            cum, tot = cumulative(share)
            if cum is None:
                ax.plot([], [], color=c, ls=ls, label="%s: empty (0 %% of the mass)" % lab)
                continue
            ax.plot(d, cum, color=c, ls=ls, marker=mk, ms=3.5, lw=1.5,
                    label="%s, %.1f %% of the mass" % (lab, tot))
        d1, d2 = 2e3 * r.r1, 2e3 * r.r2
        if r.r1 > 0 and r.r2 > 0 and d2 >= d1:
            lo, hi = d1, d2
            if hi == lo:            # one interval: shade a sliver around it
                lo, hi = lo / 1.03, hi * 1.03
            ax.axvspan(lo, hi, color="0.6", alpha=0.25, lw=0,
                       label="overlapping zone 2r1=%.3g..2r2=%.3g mm\n(%.1f %% of the mass)"
                       % (d1, d2, r.oz))
        elif r.r1 > 0 and r.r2 > 0:
            ax.axvline(0.5 * (d1 + d2), color="0.4", lw=1,
                       label="no overlap: 2r2=%.3g < 2r1=%.3g mm" % (d2, d1))
        if getattr(r, "oz_tolerant", None):
            t1, t2, toz = r.oz_tolerant
            if t1 > 0 and t2 > 0 and t2 >= t1:
                ax.axvspan(2e3 * t1 / 1.01, 2e3 * t2 * 1.01, facecolor="none", edgecolor="0.2",
                           hatch="//", lw=0.5, label="tolerant zone (oz_tolerance) "
                           "%.3g..%.3g mm\n(%.1f %% of the mass)" % (2e3 * t1, 2e3 * t2, toz))
        log_diameter_axis(ax)
        ax.set_xlabel("diameter d (mm), log scale")
        if i == 0:
            ax.set_ylabel("cumulative mass, % of its own fraction\n"
                          "(each curve ends at 100 %)")
        ax.set_ylim(-2, 102)
        ax.set_title("%s (step %d)" % (r.label, r.iv["step"]))
        ax.grid(alpha=0.3, which="both")
        ax.legend(fontsize=7.5, loc="upper left")
    fig.suptitle("Figs. 17/18: PSD, primary fabric (PFD) and loose particle (LPD) "
                 "distributions, cumulative over the size intervals\n(finest first), "
                 "each normalised to 100 % of its own mass; shaded: overlapping zone "
                 "r1..r2 as diameters", fontsize=10)
    fig.tight_layout()
    save(fig, pngdir, "fig17_18_distributions.png", written)


def fig_rose(runs, pngdir, written):
    have = [(i, r) for i, r in enumerate(runs) if r.dirs is not None]
    if not have:
        warn("no run has a direction histogram (no global vector): "
             "fig15_16_direction_rose.png not drawn")
        return
    fig, axes = plt.subplots(1, 2, figsize=(11, 5.4), subplot_kw={"projection": "polar"})
    texts = []
    for i, r in have:
        frac = np.asarray(r.dirs["fraction"], float)
        force = np.asarray(r.dirs["force"], float)
        m = len(frac)
        edges = np.linspace(0.0, 0.5 * np.pi, m + 1)
        iso = np.cos(edges[:-1]) - np.cos(edges[1:])     # isotropic share per bin
        dens = frac / iso
        fmax = force.max() if force.size else 0.0
        fnorm = force / fmax if fmax > 0 else force
        # mirror the 0..90 degree histogram into the four quadrants (n and -n are
        # one contact; the oedometer is symmetric about z); edges[] are the bins
        if r.dirs["nloaded"] == 0:
            axes[0].plot([], [], color=style(i)["color"], ls=":",
                         label="%s: no loaded contacts" % r.label)
        for ax, val in ((axes[0], dens), (axes[1], fnorm)):
            if r.dirs["nloaded"] == 0:
                continue
            ang = np.linspace(0.0, 2 * np.pi, 1441)
            # plot angle from "up", clockwise: the line's polar angle from z
            theta = np.arccos(np.clip(np.abs(np.cos(ang)), 0.0, 1.0))
            k = np.minimum((theta / (0.5 * np.pi / m)).astype(int), m - 1)
            rad = val[k]
            ax.plot(ang, rad, color=style(i)["color"], lw=1.6,
                    label=r.label if ax is axes[0] else None)
            ax.fill(ang, rad, color=style(i)["color"], alpha=0.12)
        F, P = r.dirs["F"], r.dirs["Phi"]
        texts.append("%s: %d loaded contacts, F_zz=%.3f, Phi_zz=%.3f, max mean force %.3g N [%s]"
                     % (r.label, r.dirs["nloaded"], F[2], P[2], fmax, r.dirs["source"]))
    th = np.linspace(0, 2 * np.pi, 181)
    axes[0].plot(th, np.ones_like(th), "k--", lw=0.8, label="isotropic")
    for ax, t in ((axes[0], "Fig. 15: contact fraction per bin / isotropic share"),
                  (axes[1], "Fig. 16: mean normal force per bin / largest bin")):
        ax.set_theta_zero_location("N")
        ax.set_theta_direction(-1)
        grid = list(range(0, 360, 30))
        ax.set_thetagrids(grid, ["%d\u00b0" % round(math.degrees(math.acos(abs(math.cos(
            math.radians(g)))))) for g in grid])
        ax.set_rlabel_position(100)
        ax.set_title(t, fontsize=10, pad=14)
    axes[0].legend(loc="upper left", bbox_to_anchor=(-0.15, 1.12), fontsize=8)
    fig.text(0.5, 0.01, "2-D simplification of the paper's 3-D histograms: angle labels are the polar "
             "angle of the loaded contact normals from z (up/down = vertical contacts, "
             "sides = horizontal),\nthe 90/M degree bins mirrored into four quadrants "
             "(n and -n are one contact; symmetry about z assumed). Left: share of the loaded "
             "contacts in a bin divided by its isotropic share cos(a) - cos(b) (1 = "
             "isotropic);\nright: mean normal force of the bin divided by the largest "
             "bin, as the paper normalises\n" + "\n".join(texts),
             ha="center", va="bottom", fontsize=7.5)
    fig.subplots_adjust(bottom=0.16 + 0.03 * len(texts))
    save(fig, pngdir, "fig15_16_direction_rose.png", written)


# ---------------------------------------------------------------- main
def main(argv=None):
    ap = argparse.ArgumentParser(
        prog=PROG, description=__doc__.split("\n\n")[0],
        formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("outdirs", nargs="+", metavar="OUTDIR",
                    help="output folder(s) of input_scripts/in.oedometer")
    ap.add_argument("--labels", nargs="+", metavar="LABEL",
                    help="one legend label per OUTDIR (default: folder names)")
    ap.add_argument("--png-dir", metavar="DIR",
                    help="where to write the PNGs (default: OUTDIR for one run, "
                         "fabric_plots beside the first OUTDIR for several)")
    ap.add_argument("--dt", type=float, metavar="SECONDS",
                    help="time step, to plot Figs. 11-12 against time (default: read "
                         "from a LIGGGHTS log in OUTDIR, else plot against the step)")
    a = ap.parse_args(argv)

    if a.labels and len(a.labels) != len(a.outdirs):
        ap.error("--labels has %d labels for %d OUTDIRs" % (len(a.labels), len(a.outdirs)))
    labels = a.labels or [os.path.basename(os.path.normpath(d)) or d for d in a.outdirs]

    missing = []
    for d in a.outdirs:
        if not os.path.isdir(d):
            missing.append("%s: no such folder" % d)
            continue
        for f in ("fabric_series.txt", "fabric_intervals.txt"):
            if not os.path.isfile(os.path.join(d, f)):
                missing.append("%s: not found" % os.path.join(d, f))
    if missing:
        for m in missing:
            print(PROG + ": error: " + m, file=sys.stderr)
        print(PROG + ": run input_scripts/in.oedometer with -var out OUTDIR to the end "
              "first; nothing drawn", file=sys.stderr)
        return 2

    try:
        runs = [Run(d, l, a.dt) for d, l in zip(a.outdirs, labels)]
    except (InputError, OSError) as e:
        print(PROG + ": error: " + str(e), file=sys.stderr)
        return 2

    pngdir = a.png_dir or (a.outdirs[0] if len(runs) == 1 else os.path.join(
        os.path.dirname(os.path.abspath(a.outdirs[0])), "fabric_plots"))
    os.makedirs(pngdir, exist_ok=True)
    written = []
    fig_series(runs, "loose_number_pct", "loose particles, % by number",
               "Fig. 11: loose particles by number", "fig11_loose_number.png",
               pngdir, written)
    fig_series(runs, "primary_mass_pct", "primary fabric, % by mass",
               "Fig. 12: primary fabric fraction by mass", "fig12_primary_mass.png",
               pngdir, written)
    fig_per_interval(runs, "loaded_contacts_per_particle",
                     "loaded contacts per particle",
                     "Fig. 13: mean contacts per particle per size interval",
                     "fig13_contacts_per_particle.png", pngdir, written)
    fig_per_interval(runs, "normal_force_per_loaded_contact", "mean normal force per loaded contact (N)",
                     "Fig. 14: mean normal force per contact per size interval",
                     "fig14_force_per_contact.png", pngdir, written)
    fig_distributions(runs, pngdir, written)
    fig_per_interval(runs, "primary_percent_of_interval",
                     "primary fabric, % of the interval's mass",
                     "Fig. 19: contribution of each interval to the primary fabric",
                     "fig19_primary_of_interval.png", pngdir, written, ylim=(-2, 102))
    fig_rose(runs, pngdir, written)
    for p in written:
        print(p)
    return 0


if __name__ == "__main__":
    sys.exit(main())
