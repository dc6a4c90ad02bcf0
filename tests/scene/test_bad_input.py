#!/usr/bin/python3
"""Scene test: bad input to fix sequential/pack ends the run with a clear
error, promptly and without a crash.

For every case the launcher runs a small input (serially, a few cases also
on 2 MPI ranks) and the test asserts that
  * the run ends within the timeout (no hang) with a non-zero exit code that
    is not a signal (no segfault or abort),
  * the output has an 'ERROR:' line,
  * that line names the bad value and/or what is allowed (regular
    expressions and numbers per case, below).
The bad PSD files are in tests/scene/data/ (each says what is wrong with it).
"""

import math
import os
import re

import scene_util as su

BOX = 6e-3          # box and container edge (m)
TIMEOUT = 60.0      # seconds per run; a good error comes in about 1 s


class Case:
    def __init__(self, name, text, patterns, numbers=(), nprocs=None,
                 path=None, extra_check=None):
        self.name = name
        self.text = text            # the input script
        self.patterns = patterns    # regexes the ERROR text must match
        self.numbers = numbers      # values the ERROR text must print
        self.nprocs = nprocs        # None: serial, else mpirun -np
        self.path = path            # a file the ERROR text must name
        self.extra_check = extra_check


def scene(psd, fix_args, box=BOX, region=None, atom_style="granular"):
    """A box [0, box]^3, a container region and the fix; `run 0`."""
    text = su.header(box, atom_style=atom_style)
    if region is None:
        region = su.block_region("container", (0, 0, 0), (box, box, box))
    text += region
    text += "fix             pack all sequential/pack %s\n" % (
        fix_args.replace("PSD", psd))
    text += su.MATERIALS + "run 0\n"
    return text


def fix_args(**kw):
    """The fix's arguments; a value None drops its keyword."""
    args = dict(psd="PSD", porosity="0.4", arrangement="discrete",
                region="container", seed="1")
    args.update(kw)
    return " ".join("%s %s" % (k, v) for k, v in args.items()
                    if v is not None)


def fine_psd_count(volume, porosity, intervals=20):
    """About how many particles psd_fine_0.1mm.txt puts in `volume`: the
    fix's equal-mass intervals, each taken at its middle diameter."""
    lo, hi = math.log(0.09e-3), math.log(0.11e-3)
    n = 0.0
    for k in range(intervals):
        d = math.exp(lo + (k + 0.5) / intervals * (hi - lo))
        n += (1.0 / intervals) * (1 - porosity) * volume / (math.pi / 6 * d**3)
    return n


def memory_message_check(expected_count, nprocs):
    """The message says about how many particles and how many GiB."""
    pages = os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")

    def check(err):
        m = re.search(r"about\s+([0-9.eE+-]+)\s+particles", err)
        g = re.search(r"([0-9.eE+-]+)\s*GiB", err)
        if not m or not g:
            return False, "no 'about N particles' or 'X GiB' in: " + err
        count, gib = float(m.group(1)), float(g.group(1))
        if abs(count / expected_count - 1) > 0.05:
            return False, "says %g particles, expected about %g" % (
                count, expected_count)
        per = gib * 2**30 / count
        if not 50 <= per <= 1e5:
            return False, "says %g GiB for %g particles (%g B each)" % (
                gib, count, per)
        if gib < 0.8 * pages / 2**30:
            return False, "says %g GiB, less than 80%% of this machine's " \
                          "%g GiB, yet refuses" % (gib, pages / 2**30)
        return True, "%g particles, %g GiB (%.0f B per particle on %d " \
                     "rank(s))" % (count, gib, per, nprocs)
    return check


def cases(args, work):
    data = su.DATA_DIR
    ok = os.path.join(data, "psd_ok_small.txt")
    cu = os.path.join(args.source, "input_scripts", "psd", "cu2.5.txt")
    fine = os.path.join(data, "psd_fine_0.1mm.txt")
    out = []

    def add(name, psd, patterns, numbers=(), nprocs=None, **kw):
        check = kw.pop("check", None)
        path = psd if kw.pop("names_psd", False) else None
        text = scene(psd, kw.pop("args", fix_args()), **kw)
        out.append(Case(name, text, patterns, numbers, nprocs, path=path,
                        extra_check=check))

    # -- the PSD file
    missing = os.path.join(work, "no_such_psd.txt")
    add("missing PSD file", missing,
        [r"cannot open|cannot read|no such|not exist|not found"],
        names_psd=True)
    add("missing PSD file, 2 ranks", missing,
        [r"cannot open|cannot read|no such|not exist|not found"],
        nprocs=2, names_psd=True)
    # root reads chmod-000 files, so the unreadable PSD is a folder
    folder = os.path.join(work, "psd_path_case")
    os.makedirs(folder, exist_ok=True)
    add("PSD path is a folder (unreadable)", folder,
        [r"cannot (open|read)|directory|folder|not a (regular )?file"],
        names_psd=True)
    for fname, patterns, numbers in [
            ("psd_bad_nonincreasing_diameter.txt",
             [r"diameter", r"increas|larger"], [1.0e-3]),
            ("psd_bad_decreasing_percent.txt",
             [r"percent", r"decrease|below|increas"], [45, 60]),
            ("psd_bad_percent_above_100.txt",
             [r"percent", r"0\s*(\.\.|-|to|and)\s*100"], [120]),
            ("psd_bad_percent_negative.txt",
             [r"percent", r"0\s*(\.\.|-|to|and)\s*100"], [-5]),
            ("psd_bad_end_not_100.txt", [r"100", r"end|last"], [90]),
            ("psd_bad_start_not_0.txt", [r"\b0\b", r"start|first"], [10]),
            ("psd_bad_one_point.txt", [r"(at least )?(2|two) points"], [1]),
            ("psd_bad_zero_diameter.txt", [r"diameter", r"positive"], [0]),
            ("psd_bad_negative_diameter.txt", [r"diameter", r"positive"],
             [-0.8e-3]),
            ("psd_bad_non_numeric.txt", [r"line 5\b", r"fifty",
                                         r"number"], []),
            ("psd_bad_three_columns.txt", [r"line 5\b", r"2 numbers|two "
                                           r"numbers|extra|columns"], [7]),
            ("psd_bad_one_column.txt", [r"line 5\b", r"diameter percent"
                                        r"_passing|two numbers|2 numbers"],
             []),
            ("psd_bad_empty.txt", [r"(at least )?(2|two) points"], [0])]:
        path = os.path.join(data, fname)
        add("PSD " + fname[4:-4].replace("_", " "), path, patterns,
            numbers, names_psd=True)

    # -- porosity
    for p in ("0", "1", "-0.1", "1.5"):
        # the value beside its keyword: "between 0 and 1" alone holds 0 and 1
        add("porosity %s" % p, ok, [r"porosity %s " % re.escape(p),
                                    r"between 0 and 1|\(0, ?1\)|0\s*\.\.\s*1"
                                    r"|0 < .* < 1"],
            [float(p)], args=fix_args(porosity=p))
    add("porosity 1.5, 2 ranks", ok, [r"porosity", r"between 0 and 1"],
        [1.5], nprocs=2, args=fix_args(porosity="1.5"))
    add("porosity abc (not a number)", ok, [r"porosity", r"abc", r"number"],
        args=fix_args(porosity="abc"))

    # -- the container
    add("container thinner than the largest particle", ok,
        [r"container|region", r"largest|coarsest|smaller"], [1.0e-3],
        region=su.block_region("container", (0, 0, 0), (BOX, BOX, 1.0e-3)))
    add("container holding fewer than 3 particles", ok,
        [r"only \d+ particles|fewer|too few|at least 3"],
        region=su.block_region("container", (0, 0, 0),
                               (1.3e-3, 1.3e-3, 1.3e-3)),
        args=fix_args(porosity="0.5", intervals="1"))
    add("unknown arrangement", ok, [r"arrangement", r"foo", r"discrete",
                                    r"layerwise"],
        args=fix_args(arrangement="foo"))
    add("missing region (undefined ID)", ok, [r"region", r"nope",
                                              r"does not exist|unknown|"
                                              r"not found|undefined"],
        args=fix_args(region="nope"))
    add("sphere region", ok, [r"sphere", r"block"],
        region="region          container sphere 0.003 0.003 0.003 0.002 "
               "units box\n")
    add("region reaching outside the box (x hi)", ok,
        [r"outside|beyond|exceeds", r"box"], [7e-3],
        region=su.block_region("container", (0, 0, 0), (7e-3, BOX, BOX)))
    add("region reaching outside the box (y lo)", ok,
        [r"outside|beyond|exceeds", r"box"], [-1e-3],
        region=su.block_region("container", (0, -1e-3, 0), (BOX, BOX, BOX)))
    add("region side out", ok, [r"side"],
        region=su.block_region("container", (0, 0, 0), (BOX, BOX, BOX),
                               "side out"))

    # -- seed, intervals, other keywords
    for s in ("0", "-3"):
        add("seed %s" % s, ok, [r"seed", r"positive"], [float(s)],
            args=fix_args(seed=s))
    add("seed 1.5 (not an integer)", ok, [r"seed", r"1\.5", r"integer"],
        args=fix_args(seed="1.5"))
    add("seed above 2^31-1", ok, [r"seed", r"2147483647"],
        args=fix_args(seed="99999999999"))
    for n in ("0", "101"):
        add("intervals %s" % n, ok, [r"intervals", r"1\s*\.\.\s*100|"
                                     r"between 1 and 100"], [float(n)],
            args=fix_args(intervals=n))
    add("intervals without a value", ok, [r"intervals", r"value"],
        args=fix_args() + " intervals")
    add("unknown keyword", ok, [r"colour", r"unknown|allowed|illegal"],
        args=fix_args(colour="red"))
    add("missing keyword seed", ok, [r"seed", r"required|missing"],
        args=fix_args(seed=None))
    add("missing keyword psd", ok, [r"psd", r"required|missing"],
        args=fix_args(psd=None))
    add("missing keyword porosity", ok, [r"porosity", r"required|missing"],
        args=fix_args(porosity=None))
    add("missing keyword arrangement", ok, [r"arrangement",
                                            r"required|missing"],
        args=fix_args(arrangement=None))
    add("missing keyword region", ok, [r"region", r"required|missing"],
        args=fix_args(region=None))
    add("type 2 in a box of 1 atom type", ok, [r"type", r"\b2\b",
                                               r"1\s*\.\.\s*1"],
        args=fix_args(type="2"))
    add("density -5", ok, [r"density", r"positive"], [-5],
        args=fix_args(density="-5"))
    add("start top", ok, [r"start", r"'top'", r"auto, floor_ceiling, floor or centre"],
        args=fix_args(start="top"))
    add("layering 0", ok, [r"layering", r"\b0\b", r"positive"],
        args=fix_args(layering="0"))
    add("layering nan", ok, [r"layering", r"nan", r"not a number"],
        args=fix_args(layering="nan"))
    add("fill_pores maybe", ok, [r"fill_pores", r"'maybe'", r"yes or no"],
        args=fix_args(fill_pores="maybe"))

    # -- atom style
    add("atom_style atomic", ok, [r"granular|sphere|radius"],
        atom_style="atomic")

    # -- too many particles for memory (or for int32 atom IDs)
    n_cube = fine_psd_count(1.0, 0.4)
    add("1 m cube of 0.1 mm grains", fine, [r"particles", r"GiB"],
        box=1.0, region=su.block_region("container", (0, 0, 0), (1, 1, 1)),
        check=memory_message_check(n_cube, 1))
    add("1 m cube of 0.1 mm grains, 2 ranks", fine, [r"particles", r"GiB"],
        nprocs=2, box=1.0,
        region=su.block_region("container", (0, 0, 0), (1, 1, 1)),
        check=memory_message_check(n_cube, 2))
    # Below the ID limit (2^31/4 particles) but above this machine's memory.
    target = 4e8
    memory = os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    if target * 2048 > 0.8 * memory:
        edge = (target / fine_psd_count(1.0, 0.4)) ** (1 / 3)
        add("%.3g m cube of 0.1 mm grains (4e8 particles)" % edge, fine,
            [r"particles", r"GiB"], box=edge,
            region=su.block_region("container", (0, 0, 0),
                                   (edge, edge, edge)),
            check=memory_message_check(target, 1))
    else:
        print("       (skipped the 4e8-particle case: this machine has "
              "%.0f GiB)" % (memory / 2**30))
    return out


def main():
    args = su.parse_args(__doc__)
    chk = su.Checker()
    work = su.fresh_dir(os.path.join(args.work, "bad_input"))
    for i, case in enumerate(cases(args, work)):
        inp = su.write_file(os.path.join(work, "case%02d.in" % i), case.text)
        res = su.run_launcher(args, inp, nprocs=case.nprocs, timeout=TIMEOUT)
        errors = res.errors()
        err = " | ".join(dict.fromkeys(errors))  # each line once
        # what the patterns and numbers see: the message without the source
        # location and without the paths of the input files
        msg = re.sub(r"\([^()]*\.(cpp|h):\d+\)", "", err)
        for s in (case.path, inp, su.DATA_DIR, work, args.source):
            if s:
                msg = msg.replace(s, "<path>")
        problems = []
        if res.timed_out:
            problems.append("did not end within %.0f s" % TIMEOUT)
        if res.crashed():
            problems.append("crashed (exit code %s)" % res.returncode)
        elif not res.timed_out and res.returncode == 0:
            problems.append("exit code 0")
        if not errors:
            problems.append("no 'ERROR:' line")
        if errors and case.path and case.path not in err:
            problems.append("the error does not name the file " + case.path)
        for pat in case.patterns:
            if errors and not re.search(pat, msg, re.I):
                problems.append("the error does not match /%s/" % pat)
        for v in case.numbers:
            if errors and not su.mentions_number(msg, v):
                problems.append("the error does not name the value %g" % v)
        detail = ""
        if case.extra_check and errors:
            good, detail = case.extra_check(err)
            if not good:
                problems.append(detail)
        where = "" if case.nprocs is None else " [np %d]" % case.nprocs
        chk.check("%s%s: ERROR in %.1f s" % (case.name, where, res.seconds),
                  not problems,
                  "; ".join(problems) + "\n" + (err or res.describe()))
        if not problems:
            chk.note(err[:300] if len(err) <= 300 else err[:297] + "...")
    chk.finish()


if __name__ == "__main__":
    main()
