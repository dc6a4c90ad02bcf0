#!/usr/bin/python3
"""Scene test, label `scene`: the study's tools on the runs of the small
matrix (tools/oedometer_study.py --small, both arrangements x Cu 2.0 and
2.5, seed 1) cut short: side 2.5 and 2 ms of loading (4,000 steps), some
seconds per run. What they show of the physics is tests/scene/
test_study_small.py (label `study`); here only what the tools make of the
runs, which does not need a specimen at rest:

1. The driver writes one CSV row per run (4) with the run's folder, and
   resumes: run again, it finds every run done and runs none.
2. tools/validation_report.py turns the runs into the validation page's
   tables (a row per model, Table 2 beside the paper's) and figures; with
   --matrix a row per model carries its seed's primary % as the CSV has it
   and the number of runs at rest; with --label a second matrix goes to
   files and a page block of its own; the runs split over two --study
   folders give the same tables; a run in two folders is refused.
3. tools/fabric_layers.py cuts every run's final state into layers by
   height: they hold every grain once and all of the mass, the core lies
   inside the interior, and the whole specimen's primary share is the CSV
   row's; cut into equal slices (--slices, --csv) the slices hold every
   grain, all of the mass and all of the fines, and their primary shares
   weighted by mass give the CSV row's; one slice gives the CSV row's a_c
   and a_n.
4. tools/kinetic_energy.py finds in every run's final state the kinetic
   energy of the run's last check (fabric_series.txt) and the CSV row's
   primary share of the mass; its split into the slices' mean velocity and
   the motion about it adds up to the whole.
5. tools/constriction_verdict.py gives a verdict row per run with the
   launcher given by a path relative to the caller's folder.
"""
import csv
import os
import re
import subprocess

import scene_util as su
import soils  # noqa: E402  (tools/, on the path through scene_util)

SIDE = "2.5"
# fabric_layers.py's layers, from the floor to the top
LAYER_NAMES = ["floor, first half d_N", "floor, second half d_N", "interior",
               "top, second half d_N", "top, first half d_N"]
CORE = "core, 1 d_N from every wall"


def tool(args, name, argv, timeout):
    """Runs tools/NAME with `argv` from the repository root."""
    return subprocess.run(["/usr/bin/python3", os.path.join(args.source, "tools", name)] + argv,
                          cwd=args.source, capture_output=True, text=True, timeout=timeout)


def tail(p, n=1500):
    return p.stdout[-n:] + p.stderr[-n:]


def read_text(path, ok=True):
    """The text of `path` if `ok`, else ''."""
    if not ok:
        return ""
    with open(path) as f:
        return f.read()


def read_csv(path, ok=True):
    """The rows of a CSV file as dicts by its header ([] if not `ok` or no file)."""
    if not ok or not os.path.isfile(path):
        return []
    with open(path) as f:
        return list(csv.DictReader(f))


def write_csv(path, fields, rows):
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        w.writerows(rows)


def csv_fields(path):
    with open(path) as f:
        return next(csv.reader(f))


def link_runs(study, rows, target=lambda r: r["name"]):
    """study/runs/NAME -> WORK/runs/target(row) for each row."""
    runs = os.path.join(study, "runs")
    os.makedirs(runs, exist_ok=True)
    for r in rows:
        link = os.path.join(runs, r["name"])
        if not os.path.lexists(link):
            os.symlink(os.path.join(os.path.dirname(study), "runs", target(r)), link)


def model(row):
    """'DA Cu 2.5': a CSV row's model as the report's tables name it."""
    return "%s Cu %s" % (soils.TAG[row["rule"]], row["soil"][2:])


def check_driver(args, chk):
    """1. One CSV row per run with its folder; run again, nothing to run."""
    driver = os.path.join(args.source, "tools", "oedometer_study.py")
    cmd = ["/usr/bin/python3", driver, "--small", "--sides", SIDE, "--var", "t_max=0.002", "slices=5",
           "--jobs", "2", "--out", args.work]
    p = subprocess.run(cmd, cwd=args.source, capture_output=True, text=True, timeout=600)
    print(p.stdout[-3000:], p.stderr[-3000:])
    rows = read_csv(os.path.join(args.work, "study.csv"))
    chk.check("the driver exits 0 with 4 CSV rows (both rules x Cu 2.0, 2.5), each with "
              "its run folder: exit %d, %d rows" % (p.returncode, len(rows)),
              p.returncode == 0 and len(rows) == 4
              and all(os.path.isfile(os.path.join(args.work, "runs", r["name"], "fabric_global.txt"))
                      for r in rows))
    p2 = subprocess.run(cmd, cwd=args.source, capture_output=True, text=True, timeout=300)
    chk.check("run again, the driver resumes and runs nothing: %s"
              % (p2.stdout.splitlines()[0] if p2.stdout else "(no output)"),
              p2.returncode == 0 and re.search(r"4 done, 0 to run", p2.stdout) is not None)
    return rows


def check_report(args, chk, rows):
    """2. validation_report's tables and figures, --matrix and --label;
    the tables (for the split-study check)."""
    report = os.path.join(args.work, "report")
    study_csv = os.path.join(args.work, "study.csv")
    p3 = tool(args, "validation_report.py", ["--study", args.work, "--side", SIDE,
                                             "--out", report, "--matrix", study_csv], 600)
    tables = read_text(os.path.join(report, "tables.md"), p3.returncode == 0)
    pngs = ["summary.png", "DA/fig11_loose_number.png", "LA/fig19_primary_of_interval.png",
            "DA/fig17_18_distributions.png", "LA/fig15_16_direction_rose.png"]
    chk.check("validation_report: a table row per model, Table 2 with the paper's values, figures",
              p3.returncode == 0 and all("| %s Cu %s |" % (r, c) in tables
                                         for r in ("DA", "LA") for c in ("2.0", "2.5"))
              and re.search(r"\| DA Cu 2\.5 \| [0-9.() -]+ \| 0\.11 \|", tables) is not None
              and all(os.path.exists(os.path.join(report, f)) for f in pngs),
              p3.stdout[-2000:] + p3.stderr[-2000:])
    # --matrix: one row per model from the CSV, each seed's primary % as the
    # CSV has it, and its own summary figure.
    matrix = tables.split("The eight models at side %s d_N" % SIDE, 1)[1] if tables else ""
    rest = {model(r): int(r["at_rest"] == "yes") for r in rows}
    want = {model(r): "%.1f" % float(r["primary_mass_pct"]) for r in rows}
    chk.check("validation_report --matrix: a row per model with its seed's primary %% %s" % want,
              all(re.search(r"\| %s \| [0-9.() -]+ \| 1 \(%d\) \| %s \| %s \|"
                            % (re.escape(m), rest[m], re.escape(v), re.escape(v)), matrix)
                  for m, v in want.items())
              and os.path.exists(os.path.join(report, "summary_side%s.png" % SIDE)),
              matrix[:2000])
    # --label: a second matrix beside the first, in files and a page block of
    # its own; the unlabelled block stays as it was.
    page = su.write_file(os.path.join(args.work, "page.md"),
                         "<!-- matrix -->\nkept\n<!-- /matrix -->\n"
                         "<!-- matrix-k1 -->\nold\n<!-- /matrix-k1 -->\n")
    p5 = tool(args, "validation_report.py", ["--out", report, "--matrix", study_csv,
                                             "--label", "k1", "--page", page], 300)
    body = read_text(page)
    chk.check("validation_report --matrix --label k1: tables_sideS_k1.md, summary_sideS_k1.png, "
              "the page's matrix-k1 block filled, the matrix block kept",
              p5.returncode == 0 and "kept" in body and "old" not in body
              and all("| %s |" % m in body for m in want)
              and os.path.exists(os.path.join(report, "tables_side%s_k1.md" % SIDE))
              and os.path.exists(os.path.join(report, "summary_side%s_k1.png" % SIDE)),
              tail(p5) + body[:1500])
    return tables


def check_split_studies(args, chk, rows, tables):
    """2. Several --study folders: the runs split by rule over two folders
    (as two calls of the driver leave them) give the tables of the one
    folder; with --label and --page the tables go to the labelled blocks; a
    run given twice is refused."""
    fields = csv_fields(os.path.join(args.work, "study.csv"))
    halves = []
    for rule in ("discrete", "layerwise"):
        d = os.path.join(args.work, "split_" + rule)
        mine = [r for r in rows if r["rule"] == rule]
        link_runs(d, mine)
        write_csv(os.path.join(d, "study.csv"), fields, mine)
        halves.append(d)
    page2 = su.write_file(os.path.join(args.work, "page2.md"),
                          "<!-- tables -->\nkept\n<!-- /tables -->\n"
                          "<!-- tables-k2 -->\nold\n<!-- /tables-k2 -->\n")
    report2 = os.path.join(args.work, "report2")
    p6 = tool(args, "validation_report.py", ["--study"] + halves + [
        "--side", SIDE, "--out", report2, "--label", "k2", "--page", page2], 600)
    tables2 = read_text(os.path.join(report2, "tables.md"), p6.returncode == 0)
    body2 = read_text(page2)
    chk.check("validation_report --study A B: the tables of the one folder, "
              "the page's tables-k2 block filled, the tables block kept",
              p6.returncode == 0 and tables2.split("\n\nThe eight models")[0].strip()
              == tables.split("\n\nThe eight models")[0].strip()
              and "kept" in body2 and "old" not in body2
              and all("| %s |" % model(r) in body2 for r in rows)
              and os.path.exists(os.path.join(report2, "DA", "fig12_primary_mass.png")),
              tail(p6) + body2[:1500])
    p7 = tool(args, "validation_report.py", ["--study", args.work, halves[0], "--side", SIDE,
                                             "--out", os.path.join(args.work, "report3")], 300)
    chk.check("validation_report --study with a run in two folders: exit 2 naming it (%s)"
              % p7.stderr.strip()[:200],
              p7.returncode == 2 and "in both" in p7.stderr)


def check_rank_counts(args, chk, rows):
    """2. Rank counts: a seed run on 2 ranks only is that seed in the
    tables; a seed run on 1 and on 2 ranks is counted once (its 1-rank run)
    and its 2-rank run goes to the rank-count table. The 2-rank rows are
    made from the DA rows (their folders linked), with primary % of their
    own."""
    mixed = os.path.join(args.work, "mixed")
    da = {r["soil"]: r for r in rows if r["rule"] == "discrete"}

    def plus10(r):
        return "%.2f" % (float(r["primary_mass_pct"]) + 10)
    new_seed = dict(da["cu2.0"], name=da["cu2.0"]["name"].replace("seed1", "seed2") + "_ranks2",
                    seed="2", ranks="2", primary_mass_pct=plus10(da["cu2.0"]))
    same_seed = dict(da["cu2.5"], name=da["cu2.5"]["name"] + "_ranks2", ranks="2",
                     primary_mass_pct=plus10(da["cu2.5"]))
    link_runs(mixed, rows)
    link_runs(mixed, [new_seed], lambda r: da["cu2.0"]["name"])
    link_runs(mixed, [same_seed], lambda r: da["cu2.5"]["name"])
    write_csv(os.path.join(mixed, "study.csv"), csv_fields(os.path.join(args.work, "study.csv")),
              rows + [new_seed, same_seed])
    p8 = tool(args, "validation_report.py", ["--study", mixed, "--side", SIDE,
                                             "--out", os.path.join(args.work, "report4")], 300)
    tables4 = read_text(os.path.join(args.work, "report4", "tables.md"), p8.returncode == 0)
    first = tables4.split("\n\nTable 2")[0]
    ranks_table = tables4.split("Rank count", 1)[1].split("\n\n", 2)[1] if "Rank count" in tables4 else ""
    mean20 = 0.5 * (float(da["cu2.0"]["primary_mass_pct"]) + float(new_seed["primary_mass_pct"]))
    one25 = float(da["cu2.5"]["primary_mass_pct"])
    chk.check("validation_report, a seed on 2 ranks only: DA Cu 2.0 has 2 seeds, mean %.1f; "
              "a seed on 1 and 2 ranks: DA Cu 2.5 1 seed (%.1f), its 2-rank run in the rank table"
              % (mean20, one25),
              re.search(r"\| DA Cu 2\.0 \| [0-9]+ \| 2 \(\d\) \| [^|]+ \| %.1f \(" % mean20, first)
              is not None
              and re.search(r"\| DA Cu 2\.5 \| [0-9]+ \| 1 \(\d\) \| [^|]+ \| %.1f \|" % one25, first)
              is not None
              and same_seed["primary_mass_pct"] in ranks_table
              and new_seed["primary_mass_pct"] not in ranks_table,
              p8.stderr[-1500:] + tables4[:3000])


def number(word):
    """A number of a printed table; nan for '-' (an empty layer)."""
    return float("nan") if word == "-" else float(word)


def layer_table(stdout):
    """fabric_layers.py's layer table, {layer label: {column: value}}, by
    the column names of its 'layer ...' header line (the label, which holds
    spaces, is what is left of a row after the other columns)."""
    header = next((l.split() for l in stdout.splitlines() if l.startswith("layer ")), None)
    if header is None:
        return {}
    names = header[1:]
    got = {}
    for line in stdout.splitlines():
        w = line.rsplit(None, len(names))
        if len(w) == 1 + len(names) and not line.startswith(("#", "layer ")):
            got[w[0].strip()] = {n: (w[1 + k] if n == "height/d_N" else number(w[1 + k]))
                                 for k, n in enumerate(names)}
    return got


def check_layers(args, chk, row):
    """3. fabric_layers.py's layers: the layers from the floor to the top
    hold every grain once and all of the mass, the whole specimen's primary
    share is the CSV row's, the core lies inside the interior."""
    rundir = os.path.join(args.work, "runs", row["name"])
    p4 = tool(args, "fabric_layers.py", [rundir], 120)
    got = layer_table(p4.stdout)
    ok = p4.returncode == 0 and all(n in got for n in LAYER_NAMES + ["whole specimen"])
    grains = sum(got[n]["grains"] for n in LAYER_NAMES) if ok else -1
    mass = sum(got[n]["mass%"] for n in LAYER_NAMES) if ok else -1
    whole = got["whole specimen"]["primary%"] if ok else float("nan")
    chk.check("%s: fabric_layers: %d grains in the layers (CSV %s), mass %.1f %%, "
              "whole primary %.2f %% (CSV %s)"
              % (row["name"], grains, row["grains"], mass, whole, row["primary_mass_pct"]),
              ok and grains == int(row["grains"]) and abs(mass - 100) < 0.1
              and abs(whole - float(row["primary_mass_pct"])) < 0.015,
              tail(p4))
    core = got[CORE]["grains"] if CORE in got else -1
    interior = got["interior"]["grains"] if ok else -1
    chk.check("%s: fabric_layers: the core (%d grains) lies inside the interior (%d)"
              % (row["name"], core, interior),
              ok and 0 < core < interior, p4.stdout[-1500:])


def slices_csv(args, row, n):
    """fabric_layers.py --slices N --csv on the run: (process, CSV rows)."""
    path = os.path.join(args.work, row["name"] + ("_slice.csv" if n == 1 else "_slices.csv"))
    p = tool(args, "fabric_layers.py", ["--slices", str(n), "--csv", path,
                                        os.path.join(args.work, "runs", row["name"])], 120)
    return p, read_csv(path, p.returncode == 0)


def check_slices(args, chk, row):
    """3. --slices 5: equal slices hold every grain once, all of the mass
    and all of the fines; their primary shares, weighted by mass, give the
    whole specimen's. The study ran the compute with `slices 5`
    (-var slices 5): every slice gets its a_c and a_n from it, finite, and
    --slices 4 (not the compute's count) gets none rather than figures of
    other slices."""
    p5, sl = slices_csv(args, row, 5)

    def f(k):
        return [float(r[k]) for r in sl]
    ok = len(sl) == 5
    grains = sum(int(r["grains"]) for r in sl)
    mass = sum(f("mass_pct")) if ok else -1
    fines = sum(f("fines_share_pct")) if ok else -1
    whole = sum(a * b for a, b in zip(f("mass_pct"), f("primary_pct"))) / 100 if ok else -1
    chk.check("%s: fabric_layers --slices 5: %d grains (CSV %s), mass %.2f %%, fines %.2f %%, "
              "mass-weighted primary %.2f %% (CSV %s)"
              % (row["name"], grains, row["grains"], mass, fines, whole, row["primary_mass_pct"]),
              ok and grains == int(row["grains"]) and abs(mass - 100) < 0.01
              and abs(fines - 100) < 0.01 and abs(whole - float(row["primary_mass_pct"])) < 0.015,
              tail(p5))
    keys = ("fabric_anisotropy", "force_anisotropy")
    have = [r[k] for r in sl for k in keys if r.get(k)]
    finite = ok and len(have) == 10 and all(abs(float(x)) < 10 for x in have)
    chk.check("%s: fabric_layers --slices 5: a_c and a_n of every slice from the compute's slices (%s)"
              % (row["name"], ", ".join(have)), finite, tail(p5))
    p4, four = slices_csv(args, row, 4)
    none = len(four) == 4 and not any(r.get(k) for r in four for k in keys)
    chk.check("%s: fabric_layers --slices 4 (the compute has 5): no a_c, a_n" % row["name"],
              none, tail(p4))


def check_kinetic_energy(args, chk, row):
    """4. tools/kinetic_energy.py on the run's final state: the scene's own
    kinetic energy at its last check and the CSV's primary share; its split
    into the slices' mean velocity and the motion about it adds up."""
    rundir = os.path.join(args.work, "runs", row["name"])
    series = su.outputs.read_series(os.path.join(rundir, "fabric_series.txt"))
    p6 = tool(args, "kinetic_energy.py", [os.path.join(rundir, "final.dump"), "--slices", "4"], 120)
    tot = re.search(r"kinetic energy (\S+) J", p6.stdout)
    parts = re.search(r"^(\S+) J \(\d+ %\) in the mean velocity of 4 height slices, (\S+) J",
                      p6.stdout, re.M)
    prim = re.search(r"^primary: \d+ grains, (\S+) % of the mass", p6.stdout, re.M)
    ke = float(tot.group(1)) if tot else float("nan")
    want = float(series["ke_translation"][-1])
    split_sum = float(parts.group(1)) + float(parts.group(2)) if parts else float("nan")
    chk.check("%s: kinetic_energy: %.4g J (the last check's %.4g J), slices' mean + about "
              "%.4g J, primary %s %% of the mass (CSV %s)"
              % (row["name"], ke, want, split_sum, prim.group(1) if prim else None,
                 row["primary_mass_pct"]),
              p6.returncode == 0 and abs(ke - want) <= 1e-3 * want
              and abs(split_sum - ke) <= 1e-3 * ke and prim is not None
              and abs(float(prim.group(1)) - float(row["primary_mass_pct"])) < 0.06,
              tail(p6))


def check_verdict(args, chk, rows):
    """5. tools/constriction_verdict.py on the runs, the launcher given
    relative to the caller's folder (each run's compute works in a folder
    of its own, so the tool must resolve it first): a verdict row per run
    with the run's primary share."""
    rel = os.path.relpath(args.launcher, args.source)
    dest = os.path.join(args.work, "verdict")
    p8 = tool(args, "constriction_verdict.py", ["--study", args.work, "--launcher", rel,
                                                "--dest", dest], 600)
    vrows = read_csv(os.path.join(dest, "verdict.csv"))
    share = {r["name"]: float(r["primary_mass_pct"]) for r in rows}
    off = [(v["run"], v["primary_mass_percent"], share.get(v["run"])) for v in vrows
           if v["run"] not in share
           or abs(float(v["primary_mass_percent"]) - share[v["run"]]) > 0.006]
    chk.check("constriction_verdict with --launcher %s (relative): exit %d, a row per run (%d of %d) "
              "with the run's primary %% by mass (to the CSV's 2 decimals; off: %s)"
              % (rel, p8.returncode, len(vrows), len(rows), off),
              p8.returncode == 0 and sorted(v["run"] for v in vrows) == sorted(r["name"] for r in rows)
              and not off,
              tail(p8))


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    rows = check_driver(args, chk)
    tables = check_report(args, chk, rows)
    check_split_studies(args, chk, rows, tables)
    check_rank_counts(args, chk, rows)
    for row in rows:
        check_layers(args, chk, row)
        check_slices(args, chk, row)
    for row in rows:
        check_kinetic_energy(args, chk, row)
    check_verdict(args, chk, rows)
    chk.finish()


if __name__ == "__main__":
    main()
