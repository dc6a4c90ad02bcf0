#!/usr/bin/python3
"""Scene test: a wide PSD whose coarse grains have more neighbours than
LIGGGHTS' neighbour list holds per grain stops with the fix's message, which
names a neigh_modify (and a neighbor skin) that works.

The PSD (data/psd_ratio30.txt) spans a size ratio of 30; a cube of 4 mm
holds about 14,000 grains of it. With the default SI skin of 1 mm a coarse
grain has about 4,000 neighbours within its radius + theirs + skin, more
than the default 'neigh_modify one 2000': LIGGGHTS would stop in its first
neighbour build with 'Neighbor list overflow, boost neigh_modify one'
(error->one, no hint of what to set). Checked:
  * without neigh_modify (serially and on 2 ranks): the run stops after the
    packing with the fix's ERROR naming 'neigh_modify one N page M' and a
    'neighbor S bin' that would do, not with LIGGGHTS' overflow or a crash;
  * with the suggested 'neigh_modify one N page M' the same input runs;
  * with the suggested 'neighbor S bin' (and the default one) it runs too;
  * a narrow PSD (cu2.5) with the default settings is not stopped.
"""

import os
import re

import scene_util as su

EDGE = 4.0e-3
PSD = os.path.join(su.DATA_DIR, "psd_ratio30.txt")


def scene(psd, extra=""):
    text = su.header(EDGE)
    text += su.block_region("container", (0, 0, 0), (EDGE, EDGE, EDGE))
    text += ("fix             pack all sequential/pack psd %s porosity 0.4 "
             "arrangement discrete region container seed 1 verbose no\n"
             % psd)
    text += su.MATERIALS + extra
    text += "run             1\n"
    text += 'print           "RUN COMPLETED"\n'
    return text


def run(args, name, text, nprocs=None):
    d = su.fresh_dir(os.path.join(args.work, name))
    return su.run_launcher(args, su.write_file(os.path.join(d, "in.scene"),
                                               text), nprocs=nprocs)


def main():
    args = su.parse_args(__doc__)
    chk = su.Checker()

    suggestion = None
    for nprocs in (None, 2):
        tag = "serial" if nprocs is None else "%d ranks" % nprocs
        res = run(args, "default_" + tag.replace(" ", ""), scene(PSD), nprocs)
        errors = res.errors()
        fix_error = [l for l in errors if "Fix sequential/pack" in l
                     and "neighbours" in l]
        chk.check("%s, default neigh_modify: stops with the fix's ERROR "
                  "(%.1f s)" % (tag, res.seconds),
                  fix_error and res.returncode != 0 and not res.crashed()
                  and not res.timed_out, res.describe())
        chk.check("%s: not LIGGGHTS' 'Neighbor list overflow'" % tag,
                  "boost neigh_modify one" not in res.text, res.describe())
        chk.check("%s: the specimen was packed first (summary printed)" % tag,
                  su.pack_summary(res.text) is not None)
        if not fix_error:
            continue
        line = fix_error[0]
        chk.note(line.strip())
        m = re.search(r"has (\d+) neighbours .*'neigh_modify one (\d+) page "
                      r"(\d+)'.*'neighbor (\S+) bin'", line)
        chk.check("%s: the message gives the count, 'neigh_modify one N page "
                  "M' and 'neighbor S bin'" % tag, m, line)
        if not m:
            continue
        count, one, page = int(m.group(1)), int(m.group(2)), int(m.group(3))
        chk.check("%s: count %d > 2000 (the default), one %d >= count, page "
                  "%d >= 10 x one" % (tag, count, one, page),
                  count > 2000 and one >= count and page >= 10 * one)
        suggestion = suggestion or (one, page, m.group(4))

    if suggestion is None:
        chk.finish()
    one, page, skin = suggestion
    res = run(args, "suggested_one",
              scene(PSD, "neigh_modify    one %d page %d\n" % (one, page)))
    chk.check("with 'neigh_modify one %d page %d': the run completes "
              "(%.1f s)" % (one, page, res.seconds),
              res.returncode == 0 and not res.errors()
              and "RUN COMPLETED" in res.output, res.describe())
    res = run(args, "suggested_skin", scene(PSD, "neighbor        %s bin\n"
                                                 % skin))
    chk.check("with 'neighbor %s bin' and the default one: the run completes "
              "(%.1f s)" % (skin, res.seconds),
              res.returncode == 0 and not res.errors()
              and "RUN COMPLETED" in res.output, res.describe())

    narrow = os.path.join(args.source, "input_scripts", "psd", "cu2.5.txt")
    res = run(args, "narrow", scene(narrow))
    chk.check("a narrow PSD (cu2.5) with default settings runs (%.1f s)"
              % res.seconds, res.returncode == 0 and not res.errors()
              and "RUN COMPLETED" in res.output, res.describe())
    chk.finish()


if __name__ == "__main__":
    main()
