#!/usr/bin/python3
"""Scene test: fix sequential/pack warns when, and only when, something is
wrong, and its warnings and summary carry the right numbers. The facts
checked are whether a warning of the fix is issued and the values it names
(read as numbers, compared with the fix's vector, its summary table or the
settings), never its wording.

1. A near-empty container (porosity 0.999) keeps only a few grains: the
   fix warns, naming the number of intervals that hold no grain (as its
   summary table counts them), the first of them, their share of the mass
   (5 % each), and a volume factor above 1 with its cube root (the edge
   factor). A well-sized specimen gets no warning. A small container that
   leaves grains unplaced names how many, of how many, its width in
   coarsest diameters and the 6 it needs.
2. After read_restart, the same fix ID with other settings keeps the
   restored specimen (no new grains) and warns naming both settings'
   porosity, seed and intervals; the same settings give no warning.
3. The specimen's structure: the summary and f_ID[10] give the size
   assortativity of touching pairs (below 0 for a discrete specimen), f_ID[12]
   that of the interior's pairs. A layer-wise specimen is judged by its
   interior: Cu 3.0, a graded bed, is layered there and gets no warning;
   Cu 2.0 at 0.35, which its densest packing leaves no room to layer, gets
   one naming the value as the vector holds it; a discrete specimen gets
   none.
"""

import os
import re

import scene_util as su

EDGE = 5.6e-3
FIX = "pack"
STYLE = "sequential/pack"
ROUNDED = 6e-4      # the warnings and the summary print 3 decimals


def fix_line(psd, porosity, seed):
    return ("fix             %s all sequential/pack psd %s porosity %s "
            "arrangement discrete region container seed %d verbose no\n"
            % (FIX, psd, su.num(porosity), seed))


def summary_table(text):
    """{interval: (d_mean, target, count)} from the fix's summary table."""
    rows = re.findall(r"^\s+(\d+)\s+(\S+)\s+(\S+)\s+(\d+)\s+\d+\s+\d+\s+\S+\s+\S+\s*$",
                      text, re.M)
    return {int(k): (float(d), float(t), int(c)) for k, d, t, c in rows}


def summary(text):
    """The fix's summary: from its table's first line to its time line."""
    lines = text.splitlines()
    start = [i for i, l in enumerate(lines) if l.strip().startswith("PSD ")]
    if not start:
        return ""
    block = []
    for l in lines[start[-1]:]:
        if not l.startswith("  "):
            break
        block.append(l)
    return "\n".join(block)


def check_empty_intervals(args, chk, psd, root):
    inp = su.write_file(os.path.join(root, "in.sparse"), su.pack_scene(
        psd, EDGE, porosity=0.999, fix_id=FIX, extra_fix="verbose no"))
    res = su.run_launcher(args, inp)
    table = summary_table(res.text)
    empty = sorted(k for k, (_, _, count) in table.items() if count == 0)
    warned = su.warnings_of(res.text, STYLE)
    nums = su.numbers_in(" ".join(warned))
    factors = [v for v in nums if v > 1.0 and any(
        abs(w - v ** (1.0 / 3.0)) <= 0.005 * w for w in nums if w != v)]
    chk.check("porosity 0.999: %d of %d intervals hold no grain; one warning names "
              "that count, the first of them (%s), %s %% of the mass and a volume "
              "factor above 1 with its cube root (%s)"
              % (len(empty), len(table), empty[:1], 5 * len(empty), factors),
              res.returncode == 0 and len(table) == 20 and empty and len(warned) == 1
              and len(empty) in nums and empty[0] in nums and 5.0 * len(empty) in nums
              and factors, "\n".join(warned) + "\n" + res.text[-3000:])


def check_dense(args, chk, psd, root):
    inp = su.write_file(os.path.join(root, "in.dense"), su.pack_scene(
        psd, 6 * 1.603e-3, porosity=0.35, fix_id=FIX, extra_fix="verbose no"))
    res = su.run_launcher(args, inp)
    vec = su.pack_vector(res.text)
    chk.check("porosity 0.35 in 6 coarsest diameters: no warning, every grain placed",
              res.returncode == 0 and not su.warnings_of(res.text, STYLE)
              and vec is not None and vec["placed"] == vec["listed"], res.text[-3000:])
    chk.check("discrete: f_ID[10], the size assortativity, is below 0 (fines "
              "between coarse grains) and the summary prints it (%s)"
              % (vec and vec["size_assortativity"]),
              vec is not None and vec["size_assortativity"] < 0.0
              and su.names_value(summary(res.text), vec["size_assortativity"], ROUNDED)
              and abs(vec["radius_distance_spearman"]) < 0.1, res.text[-3000:])


def check_small(args, chk, psd, root):
    inp = su.write_file(os.path.join(root, "in.small"), su.pack_scene(
        psd, EDGE, porosity=0.35, fix_id=FIX, extra_fix="verbose no"))
    res = su.run_launcher(args, inp)
    vec = su.pack_vector(res.text)
    if vec is None:
        chk.check("porosity 0.35 in 3.5 coarsest diameters packs", False, res.text[-3000:])
        return
    missing = int(vec["listed"] - vec["placed"])
    width = round(10 * EDGE / 1.603e-3) / 10
    named = [w for w in su.warnings_of(res.text, STYLE)
             if vec["listed"] in su.numbers_in(w)]
    if missing:
        nums = su.numbers_in(" ".join(named))
        chk.check("porosity 0.35 in %.1f coarsest diameters, %d of %d not placed: one "
                  "warning names both counts, the width and the 6 diameters needed"
                  % (width, missing, vec["listed"]),
                  len(named) == 1 and missing in nums and width in nums and 6 in nums,
                  "\n".join(named) + res.text[-3000:])
    else:
        chk.check("porosity 0.35 in %.1f coarsest diameters, all placed: no warning "
                  "names the list's %d particles" % (width, vec["listed"]), not named,
                  "\n".join(named))


def check_layering(args, chk, root):
    # Layer-wise Cu 3.0 in a cube of 4.5 coarsest diameters (32,000 grains)
    # is a graded bed: layered in its interior (assortativity 0.1 or more),
    # coarse at the floor and fine under the ceiling by the profile of
    # f_ID[20..25], local Cu below the soil's, and no warning. Cu 2.0 at 0.35
    # packs near its densest whatever the order of the draw, so its interior
    # stays below 0.1: one warning names that value as the vector holds it.
    for soil, edge, layered in (("cu3.0", 10.4e-3, True),
                                ("cu2.0", 8.75e-3, False)):
        inp = su.write_file(os.path.join(root, "in.la_" + soil), su.pack_scene(
            su.soils.psd_path(soil, args.source), edge, porosity=0.35,
            arrangement="layerwise", fix_id=FIX, extra_fix="verbose no"))
        res = su.run_launcher(args, inp)
        vec = su.pack_vector(res.text)
        ai = vec and vec["interior_size_assortativity"]
        warned = [w for w in su.warnings_of(res.text, STYLE)
                  if vec and su.names_value(w, ai, ROUNDED)]
        if layered:
            chk.check("layer-wise %s: interior assortativity %s >= 0.1, floor "
                      "coarser than the top (%s against %s d_N), local Cu / Cu "
                      "%s below 0.9, no warning names it"
                      % (soil, ai, vec and vec["layer1_mean_diameter"],
                         vec and vec["layer6_mean_diameter"],
                         vec and vec["local_cu_ratio"]),
                      res.returncode == 0 and vec is not None and ai >= 0.1
                      and vec["layer1_mean_diameter"]
                      > 1.5 * vec["layer6_mean_diameter"]
                      and vec["local_cu_ratio"] < 0.9 and not warned,
                      res.text[-3000:])
        else:
            chk.check("layer-wise %s at 0.35: interior assortativity %s below "
                      "0.1: one warning and the summary name it as the vector "
                      "holds it" % (soil, ai),
                      res.returncode == 0 and vec is not None and ai < 0.1
                      and len(warned) == 1
                      and su.names_value(summary(res.text), ai, ROUNDED),
                      "\n".join(warned) + res.text[-3000:])
    inp = su.write_file(os.path.join(root, "in.da_cu2.0"), su.pack_scene(
        su.soils.psd_path("cu2.0", args.source), 8.75e-3, porosity=0.40, fix_id=FIX,
        extra_fix="verbose no"))
    res = su.run_launcher(args, inp)
    vec = su.pack_vector(res.text)
    ai = vec and vec["interior_size_assortativity"]
    chk.check("discrete cu2.0 at 0.4: interior assortativity %s below 0, no warning "
              "names it" % ai,
              res.returncode == 0 and vec is not None and ai < 0.0
              and not any(su.names_value(w, ai, ROUNDED)
                          for w in su.warnings_of(res.text, STYLE)), res.text[-3000:])


def check_restart(args, chk, psd, root):
    restart = os.path.join(root, "packed.restart")
    text = su.header(EDGE)
    text += su.block_region("container", (0, 0, 0), (EDGE, EDGE, EDGE))
    text += fix_line(psd, 0.4, 3) + su.MATERIALS
    text += "run             1\nwrite_restart   %s\n" % restart
    res = su.run_launcher(args, su.write_file(os.path.join(root, "in.write"),
                                              text))
    packed = su.nlocal_stats(res.text)
    if not chk.check("a specimen is packed and saved", res.returncode == 0 and packed
                     and os.path.isfile(restart), res.describe()):
        return
    for porosity, seed, expect in ((0.4, 3, False), (0.37, 9, True)):
        text = ("atom_modify     map array\nread_restart    %s\n"
                "newton          off\ncommunicate     single vel yes\n"
                % restart)
        text += su.block_region("container", (0, 0, 0), (EDGE, EDGE, EDGE))
        text += fix_line(psd, porosity, seed) + su.MATERIALS + "run 1\n"
        res = su.run_launcher(args, su.write_file(
            os.path.join(root, "in.read_%d" % seed), text))
        warned = su.warnings_of(res.text, STYLE)
        nums = su.numbers_in(" ".join(warned))
        kept = su.nlocal_stats(res.text) == packed
        if expect:
            ok = len(warned) == 1 and all(v in nums for v in (0.4, 3, 0.37, 9, 20))
        else:
            ok = not warned
        chk.check("read_restart, porosity %s seed %d: the %d grains kept, %s" % (
                      su.num(porosity), seed, packed[0],
                      "one warning naming both settings (porosity, seed, intervals)"
                      if expect else "no warning"),
                  res.returncode == 0 and kept and ok, "\n".join(warned) + res.text[-3000:])


def main():
    args = su.parse_args(__doc__)
    chk = su.Checker()
    psd = su.soils.psd_path("cu2.5", args.source)
    root = su.fresh_dir(os.path.join(args.work, "fix_messages"))
    check_empty_intervals(args, chk, psd, root)
    check_dense(args, chk, psd, root)
    check_small(args, chk, psd, root)
    check_layering(args, chk, root)
    check_restart(args, chk, psd, root)
    chk.finish()


if __name__ == "__main__":
    main()
