#!/usr/bin/python3
"""Tables and figures of docs/validation.md from the runs of
tools/oedometer_study.py, beside the paper's numbers.

    /usr/bin/python3 tools/validation_report.py [--study out/study [DIR ...]]
        [--side 3.3] [--out out/validation] [--size CSV ...] [--page docs/validation.md]

Reads STUDY/study.csv (one row per run) and each run's folder
STUDY/runs/NAME (fabric_global.txt: r1, r2 and their tolerant versions;
fabric_series.txt, fabric_intervals.txt: the figures); several --study
folders are read together (runs of one matrix made by several calls of the
driver; a run name found twice is an error). Writes into OUT:

  study.csv          the rows at the chosen side, as read
  tables.md          per model (rule x Cu): seeds, primary % by mass and
                     loose % by number (mean and range over the seeds), the
                     OZ as Table 2 gives it (r1, r2 in mm, OZ %), the
                     tolerant OZ, a_c, a_n, wall time; the paper's Table 2
                     beside it; each step in Cu split into the mass
                     shift and the change at equal diameter (from
                     fabric_intervals.txt); and the rank-count rows
                     (--ranks runs)
  summary.png        primary % by mass, loose % by number and OZ % against
                     Cu, DA and LA, a bar for the seeds' range, the paper's
                     Table 2 OZ and its 40-90 % band for the primary mass
  intervals.csv      the last interval table of each run (diameter, mass %,
                     primary % of the interval's mass): the step in Cu
                     split reads it
  DA/, LA/           the paper's Figs. 11-19 drawn by tools/plot_fabric.py
                     from the lowest seed's run of each Cu (one line per
                     Cu); not drawn, with a message, when one of those
                     run folders is gone (the figures already in OUT stay)

A run folder may be gone (they hold the VTK dumps: 35 MB per run of Cu 3.5
at side 7.7) once a report has read it: a run of the study CSVs without its
folder takes its step-0 count, r1, r2 and interval table from OUT/study.csv
and OUT/intervals.csv as the earlier report into the same OUT wrote them
(e.g. a seed added later: the report needs the new run's folder only).

With --matrix, tables.md also gets the eight models at one side from the
rows of several study CSVs (any rank count: the rank count acts as a seed),
one row per model with each seed's primary % by mass, and OUT/summary_sideS.png,
the summary figure of those rows (S: their side). With --matrix and no
--study, only that: OUT/tables_sideS.md and OUT/summary_sideS.png (and the
page's matrix block with --page), e.g. from the side-5.5 CSVs kept under
results/. --label L names a second matrix (runs with other scene
settings, e.g. one stiffness number): OUT/tables_sideS_L.md,
OUT/summary_sideS_L.png and the page block <!-- matrix-L --> (with --study,
the other blocks too: <!-- tables-L --> and so on).

With --size, tables.md also gets the size study: Cu 2.5 DA per side, from
the given CSVs of tools/oedometer_study.py (e.g. out/study/study.csv and
the --convergence runs' CSV). With --page, the tables also replace the
blocks between <!-- tables -->, <!-- ranks -->, <!-- size -->,
<!-- matrix --> (each with -L added under --label L) and their
closing markers in that page (docs/validation.md). Prints the tables. Exit status 2 when the CSV holds no row at the side.
"""
import argparse
import csv
import os
import shutil
import subprocess
import sys

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
sys.path.insert(0, os.path.join(ROOT, "tools"))
import oedometer_runs  # noqa: E402
import outputs  # noqa: E402
import plot_fabric  # noqa: E402
from soils import RULES, SOILS  # noqa: E402
# Table 2 of the paper: (r1 mm, r2 mm, OZ % of the mass)
PAPER_TABLE2 = {
    ("layerwise", "cu2.0"): (0.08, 0.33, 85.0), ("layerwise", "cu2.5"): (0.09, 0.35, 70.0),
    ("layerwise", "cu3.0"): (0.16, 0.74, 70.0), ("layerwise", "cu3.5"): (0.34, 1.76, 70.0),
    ("discrete", "cu2.0"): (0.06, 0.20, 75.0), ("discrete", "cu2.5"): (0.11, 0.40, 70.0),
    ("discrete", "cu3.0"): (0.19, 0.82, 70.0), ("discrete", "cu3.5"): (0.40, 1.60, 65.0),
}


def radii(rundir):
    """r1, r2, r1_tolerant, r2_tolerant in mm from the run's last global vector."""
    v = outputs.read_global(os.path.join(rundir, "fabric_global.txt"))
    pos = outputs.index(outputs.fabric_vector())
    names = ("r1", "r2", "r1_tolerant", "r2_tolerant")
    if v is None:
        return [float("nan")] * 4
    return [v[pos[n]] * 1e3 for n in names]


def loose_before_loading(rundir):
    """Loose % by number at step 0 (the packer's geometric contacts), from
    the first row of fabric_series.txt; NaN without the file."""
    path = os.path.join(rundir, "fabric_series.txt")
    if not os.path.exists(path):
        return float("nan")
    return float(outputs.read_series(path)["loose_number_pct"][0])


def stats(values):
    values = [v for v in values if v == v]
    if not values:
        return None
    return sum(values) / len(values), min(values), max(values)


def fmt(s, digits=1):
    if s is None:
        return "-"
    mean, lo, hi = s
    if lo == hi:
        return "%.*f" % (digits, mean)
    return "%.*f (%.*f-%.*f)" % (digits, mean, digits, lo, digits, hi)


def fmt_signed(s):
    """A change: signed mean, and the range as 'lo to hi'."""
    mean, lo, hi = s
    if lo == hi:
        return "%+.1f" % mean
    return "%+.1f (%+.1f to %+.1f)" % (mean, lo, hi)


def cell(v, digits):
    """A CSV cell: the value, or empty when it is not known (NaN)."""
    return "" if v != v else "%.*f" % (digits, v)


def col(got, key):
    return [float(x[key]) for x in got if x.get(key, "") not in ("", None)]


def interval_primary(rundir):
    """(diameters, mass % per interval, primary % of each interval's mass)
    from the last block of the run's fabric_intervals.txt, empty intervals
    left out."""
    iv = plot_fabric.read_intervals(os.path.join(rundir, "fabric_intervals.txt"))
    d, m, q = (iv[k] for k in ("diameter", "mass_percent", "primary_percent_of_interval"))
    held = (m > 0) & (d > 0)
    return d[held], m[held], q[held]


def kept_digest(out):
    """What an earlier report into OUT kept of each run: (rows of
    OUT/study.csv by name, interval tables of OUT/intervals.csv by name as
    (diameters, mass %, primary % of the interval))."""
    rows = {r["name"]: r for r in oedometer_runs.read_rows(os.path.join(out, "study.csv"))}
    tables = {}
    for r in oedometer_runs.read_rows(os.path.join(out, "intervals.csv")):
        tables.setdefault(r["name"], []).append(
            (float(r["diameter_m"]), float(r["mass_pct"]), float(r["primary_pct_of_interval"])))
    return rows, {n: tuple(np.array(c) for c in zip(*v)) for n, v in tables.items()}


def write_intervals(path, tables):
    with open(path, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["name", "diameter_m", "mass_pct", "primary_pct_of_interval"])
        for name in sorted(tables):
            for d, m, q in zip(*tables[name]):
                w.writerow([name, "%.10g" % d, "%.10g" % m, "%.10g" % q])


def cu_step_split(rows, tables):
    """Table lines: per rule, each step from one soil to the next wider one
    (seeds run for both), the change of the primary % by mass split in two:
    the mass shift (the wider soil's interval masses with the narrower
    soil's primary share at the same diameter, interpolated in log d and
    held at its end values, minus the narrower soil's primary %) and the
    change at equal diameter (the rest)."""
    lines = ["", "The step in Cu split (seeds run for both soils; mass shift: the wider soil's "
             "interval masses with the narrower soil's primary share at the same diameter; "
             "equal diameter: the rest):\n",
             "| rule | Cu | seeds | primary % by mass | change | mass shift | at equal diameter |",
             "|---|---|---|---|---|---|---|"]
    for rule, tag in RULES:
        for a, b in zip(SOILS, SOILS[1:]):
            runs = {}
            for soil in (a, b):
                runs[soil] = {x["seed"]: (float(x["primary_mass_pct"]),) + tuple(tables[x["name"]])
                              for x in rows
                              if x["rule"] == rule and x["soil"] == soil and x["name"] in tables}
            seeds = sorted(set(runs[a]) & set(runs[b]), key=int)
            if not seeds:
                continue
            pa, pb, shift, equal = [], [], [], []
            for seed in seeds:
                # the run's own primary % (as in the matrix table); the split
                # from the interval tables, the equal-diameter part the rest
                ra, da, ma, qa = runs[a][seed]
                rb, db, mb, qb = runs[b][seed]
                ta = (ma * qa).sum() / ma.sum()
                order = np.argsort(da)
                moved = (mb * np.interp(np.log(db), np.log(da[order]), qa[order])).sum() / mb.sum()
                pa.append(ra)
                pb.append(rb)
                shift.append(moved - ta)
                equal.append(rb - ra - (moved - ta))
            change = [y - x for x, y in zip(pa, pb)]
            lines.append("| %s | %s to %s | %s | %s to %s | %s | %s | %s |"
                         % (tag, a[2:], b[2:], ", ".join(seeds), fmt(stats(pa)), fmt(stats(pb)),
                            fmt_signed(stats(change)), fmt_signed(stats(shift)),
                            fmt_signed(stats(equal))))
    return lines if len(lines) > 4 else []


def matrix_table(paths, label=""):
    """(lines, summary, side) of the eight models from the rows of the CSVs
    (one side; any rank count), or None with a message."""
    mrows = {}
    for path in paths:
        for x in oedometer_runs.read_rows(path):
            mrows[x["name"]] = x
    sides = sorted({x["side"] for x in mrows.values()}, key=float)
    if len(sides) != 1:
        sys.stderr.write("--matrix: the CSVs hold sides %s; give runs of one side\n"
                         % (", ".join(sides) or "none"))
        return None
    summary = {}
    lines = ["The eight models at side %s d_N%s (rows of several studies):\n"
             % (sides[0], ", " + label if label else ""),
             "| model | grains | seeds (at rest) | primary % by mass per seed | mean "
             "| range | loose % by number | OZ % | tolerant OZ % | a_c | a_n | wall s |",
             "|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for rule, tag in RULES:
        for soil in SOILS:
            got = sorted((x for x in mrows.values() if x["rule"] == rule
                          and x["soil"] == soil),
                         key=lambda x: (int(x["seed"]), int(x.get("ranks") or 1)))
            if not got:
                continue
            s = {k: stats(col(got, k)) for k in
                 ("primary_mass_pct", "loose_number_pct", "oz_mass_pct",
                  "oz_tolerant_mass_pct", "fabric_anisotropy", "force_anisotropy",
                  "wall_s", "grains")}
            summary[(rule, soil)] = s
            per_seed = ", ".join(
                "%.1f%s" % (float(x["primary_mass_pct"]),
                            "" if (x.get("ranks") or "1") == "1" else
                            " (%s ranks)" % x["ranks"]) for x in got)
            p = s["primary_mass_pct"]
            lines.append("| %s Cu %s | %s | %d (%d) | %s | %.1f | %.1f | %s | %s | %s | %s "
                         "| %s | %s |"
                         % (tag, soil[2:], fmt(s["grains"], 0), len(got),
                            sum(1 for x in got if x["at_rest"] == "yes"), per_seed,
                            p[0], p[2] - p[1], fmt(s["loose_number_pct"]),
                            fmt(s["oz_mass_pct"]), fmt(s["oz_tolerant_mass_pct"]),
                            fmt(s["fabric_anisotropy"], 2), fmt(s["force_anisotropy"], 2),
                            fmt(s["wall_s"], 0)))
    return lines, summary, sides[0]


def fill_page(page, text, label=""):
    """Put the tables of tables.md into the marked blocks of the page (into
    <!-- NAME-LABEL --> when a label is given: <!-- matrix-LABEL --> ...)."""
    import re
    blocks = {}
    if "\nTable 2 beside ours" in text:
        head, rest = text.split("\nTable 2 beside ours", 1)
        table2 = "Table 2 beside ours" + rest.split("\nRank count")[0].split("\nSize study")[0]
        table2 = table2.split("\nThe eight models at")[0]
        blocks["tables"] = head.split("\n", 2)[2].strip() + "\n\n" + table2.rstrip()
    if "Rank count" in text:
        blocks["ranks"] = (text.split("MPI ranks):\n", 1)[1].split("\nSize study")[0]
                           .split("\nThe eight models at")[0].strip())
    if "Size study" in text:
        blocks["size"] = text.split("1 MPI rank:\n", 1)[1].split("\nThe eight models at")[0].strip()
    if "The eight models at" in text:
        blocks["matrix"] = text.split("(rows of several studies):\n", 1)[1].strip()
    if label:
        blocks = {name + "-" + label: table for name, table in blocks.items()}
    body = open(page).read()
    for name, table in blocks.items():
        body = re.sub(r"<!-- %s -->.*?<!-- /%s -->" % (re.escape(name), re.escape(name)),
                      lambda m: "<!-- %s -->\n%s\n<!-- /%s -->" % (name, table, name),
                      body, flags=re.S)
    open(page, "w").write(body)


def plot_summary(summary, side, path, label=""):
    """Primary % by mass, loose % by number and OZ % against Cu, both rules,
    bars for the range over seeds, the paper's values beside them."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, axes = plt.subplots(1, 3, figsize=(13, 4))
    keys = [("primary_mass_pct", "primary fabric, % by mass"),
            ("loose_number_pct", "loose grains, % by number"),
            ("oz_mass_pct", "overlapping zone, % of the mass")]
    for ax, (key, ylabel) in zip(axes, keys):
        for i, (rule, tag) in enumerate(RULES):
            cus, mean, err = [], [], [[], []]
            for soil in SOILS:
                s = summary.get((rule, soil), {}).get(key)
                if s:
                    cu = float(soil[2:]) + (i - 0.5) * 0.04
                    cus.append(cu)
                    mean.append(s[0])
                    err[0].append(s[0] - s[1])
                    err[1].append(s[2] - s[0])
            if cus:
                ax.errorbar(cus, mean, yerr=err, marker="os"[i], capsize=4, label="ours, " + tag)
            if key == "oz_mass_pct":
                tol = [(float(s_[2:]), summary[(rule, s_)]["oz_tolerant_mass_pct"][0])
                       for s_ in SOILS if summary.get((rule, s_), {}).get("oz_tolerant_mass_pct")]
                if tol:
                    ax.plot(*zip(*tol), ":", marker="os"[i], mfc="none", color="C%d" % i,
                            label="ours, %s, oz_tolerance 0.1" % tag)
                ax.plot([float(s[2:]) for s in SOILS], [PAPER_TABLE2[(rule, s)][2] for s in SOILS],
                        "x--", color="C%d" % i, label="paper, " + tag)
        if key == "primary_mass_pct":
            ax.axhspan(40, 90, color="0.9", zorder=0, label="paper: 40-90 %")
        ax.set_xlabel("Cu")
        ax.set_ylabel(ylabel)
        ax.set_xticks([2.0, 2.5, 3.0, 3.5])
        ax.set_ylim(0, 100)
        ax.legend(fontsize=7, loc="lower left")
    fig.suptitle("The paper's eight models at side %s d_N%s (bars: range over seeds)"
                 % (side, ", " + label if label else ""))
    fig.tight_layout()
    fig.savefig(path, dpi=90)
    plt.close(fig)
    print(path)


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--study", nargs="+", metavar="DIR")
    ap.add_argument("--side", default="3.3")
    ap.add_argument("--out", default=os.path.join(ROOT, "out", "validation"),
                    help="where the tables and figures go (default out/validation)")
    ap.add_argument("--size", nargs="*", default=[], metavar="CSV")
    ap.add_argument("--matrix", nargs="*", default=[], metavar="CSV")
    ap.add_argument("--page", metavar="MD")
    ap.add_argument("--label", default="", help="names a second --matrix (files and page block)")
    return ap.parse_args()


def matrix_only(a, suffix):
    """--matrix without --study: the eight models from the CSVs, the table
    and its summary figure."""
    got = matrix_table(a.matrix, a.label)
    if got is None:
        return 2
    mlines, matrix_summary, matrix_side = got
    text = "\n".join(mlines) + "\n"
    os.makedirs(a.out, exist_ok=True)
    open(os.path.join(a.out, "tables_side%s%s.md" % (matrix_side, suffix)), "w").write(text)
    if a.page:
        fill_page(a.page, text, a.label)
    print(text)
    plot_summary(matrix_summary, matrix_side,
                 os.path.join(a.out, "summary_side%s%s.png" % (matrix_side, suffix)),
                 a.label)
    return 0


def read_studies(studies):
    """(rows of every study.csv, {run name: the study folder that holds
    it}), or None (after a message) if a run is in two studies."""
    rows, home = [], {}
    for study in studies:
        for r in oedometer_runs.read_rows(os.path.join(study, "study.csv")):
            if r["name"] in home:
                sys.stderr.write("run %s is in both %s and %s; give each run once\n"
                                 % (r["name"], home[r["name"]], study))
                return None
            home[r["name"]] = study
            rows.append(r)
    return rows, home


def fewest_ranks(ranks_rows):
    """Each seed once: its run on the fewest ranks (a seed run on 2 ranks
    only counts as that seed); its runs on more ranks go to the rank-count
    table."""
    fewest = {}
    for r in ranks_rows:
        base = r["name"].split("_ranks")[0]
        if base not in fewest or int(r.get("ranks") or 1) < int(fewest[base].get("ranks") or 1):
            fewest[base] = r
    return [r for r in ranks_rows if fewest[r["name"].split("_ranks")[0]] is r]


DERIVED = ["loose_before_pct", "r1_mm", "r2_mm", "r1_tolerant_mm", "r2_tolerant_mm"]


def add_derived(out, ranks_rows, rundir):
    """Adds to each row what its run folder holds (step-0 loose count, r1,
    r2) or, the folder gone, what an earlier report into `out` kept; returns
    {run name: its interval table}."""
    kept_rows, kept_tables = kept_digest(out)
    tables, gone, lost = {}, [], []
    for r in ranks_rows:
        name = r["name"]
        if not os.path.isdir(rundir(name)):
            # the folder is gone: what an earlier report read from it, if any
            (gone if name in kept_rows else lost).append(name)
            r.update({k: kept_rows.get(name, {}).get(k, "") for k in DERIVED})
            if name in kept_tables:
                tables[name] = kept_tables[name]
            continue
        r1, r2, t1, t2 = radii(rundir(name))
        # a value the folder does not hold is left empty, not written as nan
        r["loose_before_pct"] = cell(loose_before_loading(rundir(name)), 2)
        r.update({"r1_mm": cell(r1, 4), "r2_mm": cell(r2, 4),
                  "r1_tolerant_mm": cell(t1, 4), "r2_tolerant_mm": cell(t2, 4)})
        if os.path.exists(os.path.join(rundir(name), "fabric_intervals.txt")):
            try:
                tables[name] = interval_primary(rundir(name))
            except plot_fabric.InputError as e:
                sys.stderr.write("step in Cu split: %s left out: %s\n" % (name, e))
    if gone:
        sys.stderr.write("%d runs without their folder, read from %s (study.csv, intervals.csv): %s\n"
                         % (len(gone), out, ", ".join(sorted(gone))))
    if lost:
        sys.stderr.write("%d runs without their folder and not kept in %s: their step-0 count, "
                         "r1, r2 and Cu split are left out: %s\n"
                         % (len(lost), out, ", ".join(sorted(lost))))
    return tables


def model_tables(rows, side):
    """The per-model table and Table 2 beside ours: (lines, {(rule, soil):
    statistics})."""
    lines = ["Side %s coarsest diameters, each seed on the fewest MPI ranks it ran on; "
             "mean (range) over the seeds.\n" % side,
             "| model | grains | seeds (at rest) | loose % before loading | primary % by mass "
             "| loose % by number | a_c | a_n | wall s |",
             "|---|---|---|---|---|---|---|---|---|"]
    table2 = ["", "Table 2 beside ours (r1: finest interval with primary grains, r2: coarsest "
              "with loose ones, radii in mm; tolerant: oz_tolerance 0.1):\n",
              "| model | r1 ours | r1 paper | r2 ours | r2 paper | OZ % ours | OZ % paper "
              "| tolerant OZ % |",
              "|---|---|---|---|---|---|---|---|"]
    summary = {}
    for rule, tag in RULES:
        for soil in SOILS:
            got = [x for x in rows if x["rule"] == rule and x["soil"] == soil]
            if not got:
                continue
            p1, p2, poz = PAPER_TABLE2[(rule, soil)]
            s = {k: stats(col(got, k)) for k in
                 ("primary_mass_pct", "loose_number_pct", "oz_mass_pct", "oz_tolerant_mass_pct",
                  "fabric_anisotropy", "force_anisotropy", "wall_s", "grains", "r1_mm", "r2_mm",
                  "loose_before_pct")}
            summary[(rule, soil)] = s
            rest = sum(1 for x in got if x["at_rest"] == "yes")
            model = "%s Cu %s" % (tag, soil[2:])
            lines.append("| %s | %s | %d (%d) | %s | %s | %s | %s | %s | %s |"
                         % (model, fmt(s["grains"], 0), len(got), rest,
                            fmt(s["loose_before_pct"]),
                            fmt(s["primary_mass_pct"]), fmt(s["loose_number_pct"]),
                            fmt(s["fabric_anisotropy"], 2), fmt(s["force_anisotropy"], 2),
                            fmt(s["wall_s"], 0)))
            table2.append("| %s | %s | %.2f | %s | %.2f | %s | %.0f | %s |"
                          % (model, fmt(s["r1_mm"], 3), p1, fmt(s["r2_mm"], 3), p2,
                             fmt(s["oz_mass_pct"]), poz, fmt(s["oz_tolerant_mass_pct"])))
    return lines + table2, summary


def rank_table(rows, ranks_rows):
    """The rank-count rows: each run on more ranks beside its seed's run on
    the fewest."""
    multi = [x for x in ranks_rows if x not in rows]
    if not multi:
        return []
    lines = ["", "Rank count (the same model and seed on more MPI ranks):\n",
             "| run | ranks | primary % by mass | loose % by number | OZ % | wall s |",
             "|---|---|---|---|---|---|"]
    shown = set()
    for x in sorted(multi, key=lambda r: (r["name"].split("_ranks")[0], int(r["ranks"]))):
        base = [y for y in rows
                if y["name"].split("_ranks")[0] == x["name"].split("_ranks")[0]
                and y["name"] not in shown]
        shown.update(y["name"] for y in base)
        for y in base + [x]:
            lines.append("| %s | %s | %s | %s | %s | %s |"
                         % (y["name"].split("_ranks")[0], y.get("ranks") or "1",
                            y["primary_mass_pct"], y["loose_number_pct"], y["oz_mass_pct"],
                            y["wall_s"]))
    return lines


def size_table(paths):
    """The size study, Cu 2.5 DA on 1 rank per side, from the CSVs."""
    size_rows = {}
    for path in paths:
        for x in oedometer_runs.read_rows(path):
            if (x["rule"] == "discrete" and x["soil"] == "cu2.5"
                    and x.get("ranks", "1") in ("", "1")):
                size_rows[x["name"]] = x
    lines = ["", "Size study, Cu 2.5 DA, 1 MPI rank:\n",
             "| side (d_N) | grains | seeds (at rest) | primary % by mass per seed | mean | range "
             "| loose % by number, mean | wall s per run |",
             "|---|---|---|---|---|---|---|---|"]
    for side in sorted({x["side"] for x in size_rows.values()}, key=float):
        got = sorted((x for x in size_rows.values() if x["side"] == side),
                     key=lambda x: int(x["seed"]))
        p = col(got, "primary_mass_pct")
        lines.append("| %s | %s | %d (%d) | %s | %.1f | %.1f | %.1f | %s |"
                     % (side, fmt(stats(col(got, "grains")), 0), len(got),
                        sum(1 for x in got if x["at_rest"] == "yes"),
                        ", ".join("%.1f" % v for v in p), sum(p) / len(p), max(p) - min(p),
                        stats(col(got, "loose_number_pct"))[0],
                        fmt(stats(col(got, "wall_s")), 0)))
    return lines


def draw_figures(rows, rundir, out):
    """The paper's figures per rule by tools/plot_fabric.py, from the lowest
    seed's run of each Cu; 0, or 2 if plot_fabric.py failed."""
    for rule, tag in RULES:
        dirs, labels = [], []
        for soil in SOILS:
            got = sorted((x for x in rows if x["rule"] == rule and x["soil"] == soil),
                         key=lambda x: int(x["seed"]))
            if got:
                dirs.append(rundir(got[0]["name"]))
                labels.append("%s Cu %s seed %s" % (tag, soil[2:], got[0]["seed"]))
        missing = [d for d in dirs if not os.path.isdir(d)]
        if missing:
            sys.stderr.write("the %s figures are not drawn (run folders gone: %s); those "
                             "already in %s are kept\n" % (tag, ", ".join(missing), out))
            continue
        if not dirs:
            continue
        png = os.path.join(out, tag)
        shutil.rmtree(png, ignore_errors=True)
        if subprocess.call(["/usr/bin/python3", os.path.join(ROOT, "tools", "plot_fabric.py")]
                           + dirs + ["--labels"] + labels + ["--png-dir", png]) != 0:
            sys.stderr.write("the %s figures were not drawn (plot_fabric.py's message above)\n" % tag)
            return 2
    return 0


def write_study(out, ranks_rows, fields, tables):
    """OUT/study.csv (the rows at the side, with what was added) and
    OUT/intervals.csv."""
    with open(os.path.join(out, "study.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields, extrasaction="ignore")
        w.writeheader()
        w.writerows(sorted(ranks_rows, key=lambda r: r["name"]))
    write_intervals(os.path.join(out, "intervals.csv"), tables)


def main():
    a = parse_args()
    if a.label and not a.label.replace("_", "").replace(".", "").isalnum():
        sys.stderr.write("--label %s: letters, digits, '.' and '_' only\n" % a.label)
        return 2
    suffix = "_" + a.label if a.label else ""
    if a.study is None and a.matrix:
        return matrix_only(a, suffix)
    if a.study is None:
        a.study = [os.path.join(ROOT, "out", "study")]
    got = read_studies(a.study)
    if got is None:
        return 2
    rows, home = got

    def rundir(name):
        return os.path.join(home[name], "runs", name)
    ranks_rows = [r for r in rows if r["side"] == a.side]
    rows = fewest_ranks(ranks_rows)
    if not rows:
        sys.stderr.write("no run at side %s in %s\n"
                         % (a.side, ", ".join(os.path.join(d, "study.csv") for d in a.study)))
        return 2
    os.makedirs(a.out, exist_ok=True)
    fields = [k for k in rows[0].keys() if k not in DERIVED] + DERIVED
    tables = add_derived(a.out, ranks_rows, rundir)
    write_study(a.out, ranks_rows, fields, tables)

    lines, summary = model_tables(rows, a.side)
    lines += cu_step_split(rows, tables)
    lines += rank_table(rows, ranks_rows)
    if a.size:
        lines += size_table(a.size)
    matrix_summary = None
    if a.matrix:
        got = matrix_table(a.matrix, a.label)
        if got is None:
            return 2
        mlines, matrix_summary, matrix_side = got
        lines += [""] + mlines
    text = "\n".join(lines) + "\n"
    open(os.path.join(a.out, "tables.md"), "w").write(text)
    if a.page:
        fill_page(a.page, text, a.label)
    print(text)

    plot_summary(summary, a.side, os.path.join(a.out, "summary.png"), a.label)
    if matrix_summary:
        plot_summary(matrix_summary, matrix_side,
                     os.path.join(a.out, "summary_side%s%s.png" % (matrix_side, suffix)),
                     a.label)
    return draw_figures(rows, rundir, a.out)


if __name__ == "__main__":
    sys.exit(main())
