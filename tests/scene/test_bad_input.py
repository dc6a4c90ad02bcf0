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


def case(name, psd, patterns, numbers=(), nprocs=None, check=None, names_psd=False,
         args=None, **scene_kw):
    """A Case running `scene(psd, args or fix_args(), **scene_kw)`; with
    names_psd the error must name the PSD file."""
    text = scene(psd, fix_args() if args is None else args, **scene_kw)
    return Case(name, text, patterns, numbers, nprocs, path=psd if names_psd else None,
                extra_check=check)


MISSING = r"cannot open|cannot read|no such|not exist|not found"

# The bad PSD files of tests/scene/data: (file, patterns, numbers).
PSD_FILE_CASES = [
    ("psd_bad_nonincreasing_diameter.txt", [r"diameter", r"increas|larger"], [1.0e-3]),
    ("psd_bad_decreasing_percent.txt", [r"percent", r"decrease|below|increas"], [45, 60]),
    ("psd_bad_percent_above_100.txt", [r"percent", r"0\s*(\.\.|-|to|and)\s*100"], [120]),
    ("psd_bad_percent_negative.txt", [r"percent", r"0\s*(\.\.|-|to|and)\s*100"], [-5]),
    ("psd_bad_end_not_100.txt", [r"100", r"end|last"], [90]),
    ("psd_bad_start_not_0.txt", [r"\b0\b", r"start|first"], [10]),
    ("psd_bad_one_point.txt", [r"(at least )?(2|two) points"], [1]),
    ("psd_bad_zero_diameter.txt", [r"diameter", r"positive"], [0]),
    ("psd_bad_negative_diameter.txt", [r"diameter", r"positive"], [-0.8e-3]),
    ("psd_bad_non_numeric.txt", [r"line 5\b", r"fifty", r"number"], []),
    ("psd_bad_three_columns.txt", [r"line 5\b", r"2 numbers|two numbers|extra|columns"], [7]),
    ("psd_bad_one_column.txt", [r"line 5\b", r"diameter percent_passing|two numbers|2 numbers"],
     []),
    ("psd_bad_empty.txt", [r"(at least )?(2|two) points"], [0]),
]


def psd_cases(work):
    """The PSD file: missing, a folder, and the bad files."""
    missing = os.path.join(work, "no_such_psd.txt")
    # root reads chmod-000 files, so the unreadable PSD is a folder
    folder = os.path.join(work, "psd_path_case")
    os.makedirs(folder, exist_ok=True)
    out = [case("missing PSD file", missing, [MISSING], names_psd=True),
           case("missing PSD file, 2 ranks", missing, [MISSING], nprocs=2, names_psd=True),
           case("PSD path is a folder (unreadable)", folder,
                [r"cannot (open|read)|directory|folder|not a (regular )?file"], names_psd=True)]
    for fname, patterns, numbers in PSD_FILE_CASES:
        out.append(case("PSD " + fname[4:-4].replace("_", " "), os.path.join(su.DATA_DIR, fname),
                        patterns, numbers, names_psd=True))
    return out


def porosity_cases(ok):
    out = []
    for p in ("0", "1", "-0.1", "1.5"):
        # the value beside its keyword: "between 0 and 1" alone holds 0 and 1
        out.append(case("porosity %s" % p, ok,
                        [r"porosity %s " % re.escape(p),
                         r"between 0 and 1|\(0, ?1\)|0\s*\.\.\s*1|0 < .* < 1"],
                        [float(p)], args=fix_args(porosity=p)))
    return out + [
        case("porosity 1.5, 2 ranks", ok, [r"porosity", r"between 0 and 1"], [1.5], nprocs=2,
             args=fix_args(porosity="1.5")),
        case("porosity abc (not a number)", ok, [r"porosity", r"abc", r"number"],
             args=fix_args(porosity="abc")),
    ]


def container_cases(ok):
    box = (BOX, BOX, BOX)
    return [
        case("container thinner than the largest particle", ok,
             [r"container|region", r"largest|coarsest|smaller"], [1.0e-3],
             region=su.block_region("container", (0, 0, 0), (BOX, BOX, 1.0e-3))),
        case("container holding fewer than 3 particles", ok,
             [r"only \d+ particles|fewer|too few|at least 3"],
             region=su.block_region("container", (0, 0, 0), (1.3e-3, 1.3e-3, 1.3e-3)),
             args=fix_args(porosity="0.5", intervals="1")),
        case("unknown arrangement", ok, [r"arrangement", r"foo", r"discrete", r"layerwise"],
             args=fix_args(arrangement="foo")),
        case("missing region (undefined ID)", ok,
             [r"region", r"nope", r"does not exist|unknown|not found|undefined"],
             args=fix_args(region="nope")),
        case("sphere region", ok, [r"sphere", r"block"],
             region="region          container sphere 0.003 0.003 0.003 0.002 units box\n"),
        case("region reaching outside the box (x hi)", ok,
             [r"outside|beyond|exceeds", r"box"], [7e-3],
             region=su.block_region("container", (0, 0, 0), (7e-3, BOX, BOX))),
        case("region reaching outside the box (y lo)", ok,
             [r"outside|beyond|exceeds", r"box"], [-1e-3],
             region=su.block_region("container", (0, -1e-3, 0), box)),
        case("region side out", ok, [r"side"],
             region=su.block_region("container", (0, 0, 0), box, "side out")),
    ]


# Bad keywords and values of the fix: (name, patterns, numbers, the fix's
# arguments); the PSD is a good one.
KEYWORD_CASES = [
    ("seed 0", [r"seed", r"positive"], [0.0], fix_args(seed="0")),
    ("seed -3", [r"seed", r"positive"], [-3.0], fix_args(seed="-3")),
    ("seed 1.5 (not an integer)", [r"seed", r"1\.5", r"integer"], [], fix_args(seed="1.5")),
    ("seed above 2^31-1", [r"seed", r"2147483647"], [], fix_args(seed="99999999999")),
    ("intervals 0", [r"intervals", r"1\s*\.\.\s*100|between 1 and 100"], [0.0],
     fix_args(intervals="0")),
    ("intervals 101", [r"intervals", r"1\s*\.\.\s*100|between 1 and 100"], [101.0],
     fix_args(intervals="101")),
    ("intervals without a value", [r"intervals", r"value"], [], fix_args() + " intervals"),
    ("unknown keyword", [r"colour", r"unknown|allowed|illegal"], [], fix_args(colour="red")),
    ("missing keyword seed", [r"seed", r"required|missing"], [], fix_args(seed=None)),
    ("missing keyword psd", [r"psd", r"required|missing"], [], fix_args(psd=None)),
    ("missing keyword porosity", [r"porosity", r"required|missing"], [], fix_args(porosity=None)),
    ("missing keyword arrangement", [r"arrangement", r"required|missing"], [],
     fix_args(arrangement=None)),
    ("missing keyword region", [r"region", r"required|missing"], [], fix_args(region=None)),
    ("type 2 in a box of 1 atom type", [r"type", r"\b2\b", r"1\s*\.\.\s*1"], [],
     fix_args(type="2")),
    ("density -5", [r"density", r"positive"], [-5], fix_args(density="-5")),
    ("start top", [r"start", r"'top'", r"auto, floor_ceiling, floor or centre"], [],
     fix_args(start="top")),
    ("layering 0", [r"layering", r"\b0\b", r"positive"], [], fix_args(layering="0")),
    ("layering nan", [r"layering", r"nan", r"not a number"], [], fix_args(layering="nan")),
    ("fill_pores maybe", [r"fill_pores", r"'maybe'", r"yes or no"], [],
     fix_args(fill_pores="maybe")),
]


def memory_cases(fine):
    """Too many particles for memory (or for int32 atom IDs)."""
    n_cube = fine_psd_count(1.0, 0.4)
    cube = su.block_region("container", (0, 0, 0), (1, 1, 1))
    out = [case("1 m cube of 0.1 mm grains", fine, [r"particles", r"GiB"], box=1.0,
                region=cube, check=memory_message_check(n_cube, 1)),
           case("1 m cube of 0.1 mm grains, 2 ranks", fine, [r"particles", r"GiB"], nprocs=2,
                box=1.0, region=cube, check=memory_message_check(n_cube, 2))]
    # Below the ID limit (2^31/4 particles) but above this machine's memory.
    target = 4e8
    memory = os.sysconf("SC_PHYS_PAGES") * os.sysconf("SC_PAGE_SIZE")
    if target * 2048 > 0.8 * memory:
        edge = (target / fine_psd_count(1.0, 0.4)) ** (1 / 3)
        out.append(case("%.3g m cube of 0.1 mm grains (4e8 particles)" % edge, fine,
                        [r"particles", r"GiB"], box=edge,
                        region=su.block_region("container", (0, 0, 0), (edge, edge, edge)),
                        check=memory_message_check(target, 1)))
    else:
        print("       (skipped the 4e8-particle case: this machine has "
              "%.0f GiB)" % (memory / 2**30))
    return out


def cases(args, work):
    ok = os.path.join(su.DATA_DIR, "psd_ok_small.txt")
    fine = os.path.join(su.DATA_DIR, "psd_fine_0.1mm.txt")
    return (psd_cases(work) + porosity_cases(ok) + container_cases(ok)
            + [case(name, ok, patterns, numbers, args=a)
               for name, patterns, numbers, a in KEYWORD_CASES]
            # the atom style
            + [case("atom_style atomic", ok, [r"granular|sphere|radius"], atom_style="atomic")]
            + memory_cases(fine))


def problems_of(case, res, err, msg):
    """What is wrong with the run of `case`: [] if it ended promptly with
    the ERROR it should (`err` its ERROR lines, `msg` them without source
    locations and paths)."""
    problems = []
    if res.timed_out:
        problems.append("did not end within %.0f s" % TIMEOUT)
    if res.crashed():
        problems.append("crashed (exit code %s)" % res.returncode)
    elif not res.timed_out and res.returncode == 0:
        problems.append("exit code 0")
    if not err:
        problems.append("no 'ERROR:' line")
        return problems
    if case.path and case.path not in err:
        problems.append("the error does not name the file " + case.path)
    for pat in case.patterns:
        if not re.search(pat, msg, re.I):
            problems.append("the error does not match /%s/" % pat)
    for v in case.numbers:
        if not su.mentions_number(msg, v):
            problems.append("the error does not name the value %g" % v)
    if case.extra_check:
        good, detail = case.extra_check(err)
        if not good:
            problems.append(detail)
    return problems


def run_case(args, chk, work, i, case):
    inp = su.write_file(os.path.join(work, "case%02d.in" % i), case.text)
    res = su.run_launcher(args, inp, nprocs=case.nprocs, timeout=TIMEOUT)
    err = " | ".join(dict.fromkeys(res.errors()))  # each line once
    # what the patterns and numbers see: the message without the source
    # location and without the paths of the input files
    msg = re.sub(r"\([^()]*\.(cpp|h):\d+\)", "", err)
    for s in (case.path, inp, su.DATA_DIR, work, args.source):
        if s:
            msg = msg.replace(s, "<path>")
    problems = problems_of(case, res, err, msg)
    where = "" if case.nprocs is None else " [np %d]" % case.nprocs
    chk.check("%s%s: ERROR in %.1f s" % (case.name, where, res.seconds),
              not problems,
              "; ".join(problems) + "\n" + (err or res.describe()))
    if not problems:
        chk.note(err[:300] if len(err) <= 300 else err[:297] + "...")


def main():
    args = su.parse_args(__doc__)
    chk = su.Checker()
    work = su.fresh_dir(os.path.join(args.work, "bad_input"))
    for i, c in enumerate(cases(args, work)):
        run_case(args, chk, work, i, c)
    chk.finish()


if __name__ == "__main__":
    main()
