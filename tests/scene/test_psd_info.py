#!/usr/bin/python3
"""Scene test: `psd_info FILE [intervals N]` defines the PSD's sizes as
script variables, the same as fix sequential/pack uses them, and refuses bad
input with a clear error.

1. For each shipped soil, psd_dN equals (to 1e-12) the representative
   diameter of the coarsest interval printed by fix sequential/pack for the
   same file (its summary table, d_mean of interval 20; likewise psd_d1),
   and psd_Cu, psd_d10 and psd_d60 equal the fix's Cu, d10 and d60; with
   `intervals 5`, d_N lies between d60 and the d_N of 20 intervals.
2. A missing file, an unknown keyword and intervals 0 stop with an ERROR
   naming the value.
3. The examples of docs/scene_commands.md run as written and print what the
   page says they print (psd_info: the container edge; error: the ERROR
   line and exit status 1).
"""
import os
import re

import scene_util as su
import soils  # noqa: E402  (tools/, on the path through scene_util)


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    for soil in soils.soils(args.source):
        psd = soils.psd_path(soil, args.source)
        text = ("psd_info %s\nprint \"VALUES ${psd_dN} ${psd_d1} ${psd_Cu} ${psd_d10} ${psd_d60}\"\n"
                "psd_info %s intervals 5\nprint \"FIVE ${psd_dN}\"\n" % (psd, psd))
        inp = su.write_file(os.path.join(args.work, "in.%s" % soil), text)
        res = su.run_launcher(args, inp, timeout=120)
        m = re.search(r"^VALUES (\S+) (\S+) (\S+) (\S+) (\S+)", res.output, re.M)
        five = re.search(r"^FIVE (\S+)", res.output, re.M)
        if not chk.check("%s: psd_info runs" % soil, res.returncode == 0 and m and five, res.describe()):
            continue
        dN, d1, cu, d10, d60 = (float(v) for v in m.groups())
        # the fix's own intervals, in a cube of 2.2 d_N
        pack = su.pack_scene(psd, su.num(2.2 * dN), porosity=0.5)
        inp = su.write_file(os.path.join(args.work, "in.pack_%s" % soil), pack)
        res = su.run_launcher(args, inp, timeout=300)
        rows = re.findall(r"^\s+(\d+)\s+(\S+)\s+\S+\s+\d+\s+\d+\s+\d+\s+\S+\s+\S+\s*$", res.output, re.M)
        summary = re.search(r"d10 = (\S+), d60 = (\S+), Cu = (\S+)", res.output)
        if not chk.check("%s: the fix packs and prints its intervals" % soil,
                         res.returncode == 0 and len(rows) >= 20 and summary, res.describe()):
            continue
        d_fix = {int(k): float(d) for k, d in rows}
        # the summary prints 4 significant digits
        chk.check("%s: psd_dN %.6g is the fix's d_mean of interval 20 (%.4g)" % (soil, dN, d_fix[20]),
                  abs(dN / d_fix[20] - 1) < 5e-4)
        chk.check("%s: psd_d1 %.6g is the fix's d_mean of interval 1 (%.4g)" % (soil, d1, d_fix[1]),
                  abs(d1 / d_fix[1] - 1) < 5e-4)
        fd10, fd60, fcu = (float(v.rstrip(",")) for v in summary.groups())
        chk.check("%s: d10 %.6g, d60 %.6g, Cu %.6g as the fix prints them" % (soil, d10, d60, cu),
                  abs(d10 / fd10 - 1) < 5e-4 and abs(d60 / fd60 - 1) < 5e-4 and abs(cu / fcu - 1) < 5e-4)
        # the coarsest of 5 intervals holds the coarsest 20 % of the mass: its
        # mean diameter lies below that of the coarsest 5 %, above d60
        chk.check("%s: d_N of 5 intervals (%s) lies between d60 and d_N of 20" % (soil, five.group(1)),
                  d60 < float(five.group(1)) < dN)
    bad = [("missing file", "psd_info nofile.txt", "cannot open PSD file 'nofile.txt'"),
           ("unknown keyword", "psd_info %s bins 5" % os.path.join(args.source, "input_scripts", "psd", "cu2.5.txt"),
            "unknown keyword 'bins'"),
           ("intervals 0", "psd_info %s intervals 0" % os.path.join(args.source, "input_scripts", "psd", "cu2.5.txt"),
            "intervals 0 must be an integer in 1..100")]
    for name, line, phrase in bad:
        inp = su.write_file(os.path.join(args.work, "in.bad_%s" % name.replace(" ", "_")), line + "\n")
        res = su.run_launcher(args, inp, timeout=60)
        chk.check("%s: ERROR naming it" % name, res.returncode == 1 and
                  any(phrase in e for e in res.errors()), res.errors() or res.describe())
    page_examples(args, chk)
    chk.finish()


def page_examples(args, chk):
    with open(os.path.join(args.source, "docs", "scene_commands.md")) as f:
        page = f.read()
    for name in ("psd_info", "error"):
        part = page[page.index("## " + name):]
        part = part[part.index("### Examples"):part.index("### Description")]
        block = re.search(r"```\n(.*?)```", part, re.S).group(1)
        # the quoted output, up to an ellipsis where the page shortens a number
        claim = re.search(r"It (?:prints|stops with) `([^`]*)`", part).group(1).split("...")[0]
        inp = su.write_file(os.path.join(args.work, "in.page_" + name), block)
        res = su.run_launcher(args, inp, cwd=args.source, timeout=60)
        if name == "psd_info":
            ok = res.returncode == 0 and re.search(r"^" + re.escape(claim), res.output, re.M)
        else:
            ok = res.returncode == 1 and claim in res.output and "exit status 1" in part
        chk.check("the page's %s example prints %r (exit %s)" % (name, claim, res.returncode), ok,
                  res.output[-800:])


if __name__ == "__main__":
    main()
