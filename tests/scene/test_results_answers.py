#!/usr/bin/python3
"""results/ as answers: the numbers the pages quote are the CSV's.

1. Every folder of results/ has a README.md whose first paragraph after the
   title is the answer (starts with **Answer**) and a make.sh that bash
   parses, and its README names `bash results/FOLDER/make.sh`.
2. results/models/README.md: each model's per-seed primary % by mass, mean
   and range equal the rows of its study.csv (rounded as quoted).
3. README.md's answer table quotes the same mean and seed range for every
   model that results/models has three seeds of.

Reads files only (no LIGGGHTS run); the launcher argument is not used.
"""
import csv
import os
import re
import subprocess

import scene_util as su

RULES = {"DA": "discrete", "LA": "layerwise"}


def folders_answer_first(chk, root):
    res = os.path.join(root, "results")
    for d in sorted(os.listdir(res)):
        path = os.path.join(res, d)
        if not os.path.isdir(path):
            continue
        readme = os.path.join(path, "README.md")
        make = os.path.join(path, "make.sh")
        text = open(readme, encoding="utf-8").read() if os.path.exists(readme) else ""
        body = [p for p in text.split("\n\n")[1:] if p.strip()]
        chk.check("results/%s: README with the answer first" % d,
                  bool(body) and body[0].lstrip().startswith("**Answer"),
                  body[0][:80] if body else "no README.md")
        ok = os.path.exists(make) and subprocess.call(["bash", "-n", make]) == 0
        chk.check("results/%s: make.sh parses and the README names it" % d,
                  ok and "bash results/%s/make.sh" % d in text, "")


def study_rows(path):
    """{(rule, soil): [primary % of seeds 1, 2, 3 ...]} from a study.csv."""
    out = {}
    with open(path) as f:
        for r in sorted(csv.DictReader(f), key=lambda r: int(r["seed"])):
            out.setdefault((r["rule"], r["soil"]), []).append(float(r["primary_mass_pct"]))
    return out


def models_table(text):
    """{(rule, soil): (seeds, mean, range)} of the rows with three seeds."""
    out = {}
    for m in re.finditer(r"^\| (DA|LA) Cu (\d\.\d) \| ([\d., ]+) \| \*\*([\d.]+)\*\* \| ([\d.]+) \|",
                         text, re.M):
        seeds = [float(x) for x in m.group(3).split(",")]
        out[(RULES[m.group(1)], "cu" + m.group(2))] = (seeds, float(m.group(4)), float(m.group(5)))
    return out


def models_match_csv(chk, root):
    res = os.path.join(root, "results", "models")
    table = models_table(open(os.path.join(res, "README.md"), encoding="utf-8").read())
    rows = study_rows(os.path.join(res, "study.csv"))
    text = open(os.path.join(res, "README.md"), encoding="utf-8").read()
    full = {k for k, v in rows.items() if len(v) >= 3}
    chk.check("results/models/README.md quotes every model of study.csv with three seeds (%d)"
              % len(full), len(full) >= 6 and full <= set(table),
              "table %s, csv %s" % (sorted(table), sorted(full)))
    for (rule, soil), seeds in sorted(rows.items()):
        if len(seeds) >= 3:
            continue
        tag = "DA" if rule == "discrete" else "LA"
        line = re.search(r"^\| %s Cu %s \|(.*)$" % (tag, re.escape(soil[2:])), text, re.M)
        want = ["%.2f" % x for x in seeds]
        chk.check("results/models/README.md's row %s %s quotes its %d seed(s) of study.csv (%s)"
                  % (tag, soil, len(seeds), ", ".join(want)),
                  bool(line) and all(w in line.group(1) for w in want),
                  line.group(0) if line else "no row")
    for key, (seeds, mean, rng) in sorted(table.items()):
        csv_seeds = rows.get(key, [])
        same = (len(csv_seeds) == len(seeds)
                and all(abs(a - b) < 0.006 for a, b in zip(seeds, csv_seeds))
                and abs(mean - sum(csv_seeds) / len(csv_seeds)) < 0.051
                and abs(rng - (max(csv_seeds) - min(csv_seeds))) < 0.051)
        chk.check("results/models %s %s: seeds, mean and range are study.csv's" % key, same,
                  "page %s %.1f %.1f, csv %s" % (seeds, mean, rng, csv_seeds))
    return rows


def readme_matches(chk, root, rows):
    text = open(os.path.join(root, "README.md"), encoding="utf-8").read()
    for (rule, soil), seeds in sorted(rows.items()):
        if len(seeds) < 3:
            continue
        col = 1 if rule == "discrete" else 2
        line = re.search(r"^\| %s \|(.*)$" % re.escape(soil[2:]), text, re.M)
        cell = line.group(1).split("|")[col - 1] if line else ""
        want = "%.1f (%.1f–%.1f)" % (sum(seeds) / len(seeds), min(seeds), max(seeds))
        chk.check("README.md's answer for %s %s is results/models' (%s)" % (rule, soil, want),
                  want in cell, cell.strip())


def main():
    args = su.parse_args(__doc__)
    chk = su.Checker()
    folders_answer_first(chk, args.source)
    rows = models_match_csv(chk, args.source)
    readme_matches(chk, args.source, rows)
    chk.finish()


if __name__ == "__main__":
    main()
