#!/usr/bin/python3
"""Scene test: the seepage test of in.oedometer (-var gradients ...).

A Cu 2.5 DA specimen at side 3.3 (4,188 grains) brought to rest,
then water pushed down through it at gradient 0 and then 3000 (short
stages: blocks of 1,000 steps, 2 to 3 of them). Checked:

1. one suffusion.txt row per stage, read by name (tools/outputs.py), and a
   SEEPAGE line per stage that quotes the row;
2. nothing is lost but what the outlet counts: the eroded share of the
   specimen's volume is the volume of the grains in the stages'
   eroded_i<gradient>.txt files (to 1e-6 of the specimen), and the grains
   eroded are as many as the files' lines;
3. the filter holds: no grain coarser than the filter's opening (the
   soil's d60) leaves;
4. the lid holds the target stress at the end of each stage (within 5 %);
   a stage cut short by stage_max before a free fine grain could cross
   the specimen is called so, before it (WARNING) and in its line;
5. the seepage force acts: gradient 3000 (a pressure drop about the stress) erodes more than gradient 0 did in the same short stage;
   tools/suffusion_report.py's depth profile (where the eroded grains were
   at rest, by slices from the outlet) holds the volume of every eroded
   grain, in slices that cover the specimen;
6. bad input stops with an ERROR naming the value, before the packing
   and loading it would follow: a negative gradient, a negative opening, a
   block that is not a multiple of store_every, Cundall's damping 1, and the
   scene's slices -1 and hold_damping 1.
"""
import glob
import math
import os
import re
import sys

import scene_util as su

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tools"))
import outputs  # noqa: E402
import suffusion_report  # noqa: E402

SCENE = {"psd": "input_scripts/psd/cu2.5.txt", "side": 3.3, "stage_block": 1000,
         "stage_min": 2, "stage_max": 3, "flow_every": 200}


def run(args, name, **extra):
    out = os.path.join(args.work, name)
    variables = dict(SCENE, out=out)
    variables.update(extra)
    res = su.run_launcher(args, os.path.join(args.source, "input_scripts", "in.oedometer"),
                          variables=variables, log=out + ".log", cwd=args.source, timeout=600)
    return out, res


def check_stages(chk, out, res):
    rows = outputs.read_suffusion(os.path.join(out, "suffusion.txt"))
    lines = list(dict.fromkeys(re.findall(
        r"^SEEPAGE: gradient (\S+) .*? for (\d+) steps: eroded (\S+) % of the specimen", res.text, re.M)))
    cut = re.search(r"^WARNING: gradient 3000: a free fine grain takes (\S+) steps", res.text, re.M)
    last = re.search(r"^SEEPAGE: gradient 3000 .*; (stopped at stage_max, before a free "
                     r"fine grain could cross the specimen)$", res.text, re.M)
    chk.check("the short stage at 3000 is called short: a WARNING before it (%s steps to cross) and "
              "its line says it stopped at stage_max" % (cut and cut.group(1)),
              cut is not None and float(cut.group(1)) > 3000 and last is not None, res.text[-1500:])
    chk.check("two stages, rows and SEEPAGE lines agree (%s)" % lines,
              rows["gradient_text"] == ["0", "3000"] and len(lines) == 2
              and all(abs(float(e) - r) < 1e-9 for (_, _, e), r in zip(lines, rows["eroded_pct"])),
              res.text[-1500:])
    return rows


def check_balance(chk, out, rows, d60):
    head = open(os.path.join(out, "suffusion.txt")).readline()
    v0 = float(re.search(r"\((\S+) m\^3 of grains\)", head).group(1))
    left = [outputs.read_outlet(outputs.eroded_file(out, g)) for g in rows["gradient_text"]]
    diam = [d for t in left for d in t["diameter"]]
    vol = sum(math.pi / 6.0 * d ** 3 for d in diam)
    chk.check("the eroded share %.6f %% is the outlet files' %d grains (%.6f %%)"
              % (rows["eroded_pct"][-1], len(diam), 100.0 * vol / v0),
              abs(100.0 * vol / v0 - rows["eroded_pct"][-1]) < 1e-4
              and len(diam) == int(rows["grains_eroded"][-1]) and len(diam) > 0, "")
    chk.check("no grain coarser than the filter's opening %.4g m left (largest %.4g m)"
              % (d60, max(diam) if diam else 0), all(d < d60 * 1.0001 for d in diam), "")
    chk.check("the lid holds the stress at the end of each stage (%s Pa)" % rows["lid_stress"],
              all(abs(s / 1e5 - 1.0) < 0.05 for s in rows["lid_stress"]), "")
    chk.check("gradient 3000 erodes more than gradient 0 (%.4f against %.4f %%)"
              % (rows["stage_eroded_pct"][1], rows["stage_eroded_pct"][0]),
              rows["stage_eroded_pct"][1] > rows["stage_eroded_pct"][0] + 1e-3, "")
    _, _, depth = suffusion_report.run_report(out)
    in_slices = sum(float(r["eroded_volume_mm3"]) for r in depth) * 1e-9
    # the outlet file writes diameters to 4 digits: volumes agree to 3 parts in 10^3
    at_rest = outputs.last_snapshot(os.path.join(out, "final.dump")).natoms
    in_depth = sum(r["grains"] for r in depth)
    chk.check("the depth profile holds every eroded grain's volume (%.6g against the outlet files' "
              "%.6g m^3) and its %d slices every grain at rest (%d of %d)"
              % (in_slices, vol, len(depth), in_depth, at_rest),
              abs(in_slices - vol) <= 3e-3 * vol and len(depth) >= 3 and in_depth == at_rest
              and all(r["grains"] > 0 for r in depth), "")


BAD = [
    ("a negative gradient", {"gradients": [-2]}, r"ERROR.*gradient -2"),
    ("a negative opening", {"gradients": [0], "opening": -1e-4}, r"ERROR.*opening -0.0001"),
    ("a block not a multiple of store_every", {"gradients": [0], "stage_block": 750},
     r"ERROR.*stage_block 750"),
    ("Cundall's damping 1", {"gradients": [0], "seep_damping": 1}, r"ERROR.*seep_damping 1"),
    ("a negative slice count", {"slices": -1}, r"ERROR.*slices -1"),
    ("a hold damping of 1", {"hold_damping": 1}, r"ERROR.*hold_damping 1"),
]


def check_bad(args, chk):
    for name, extra, pattern in BAD:
        out, res = run(args, "bad_" + name.split()[-1], **extra)
        m = re.search(pattern, res.text)
        chk.check("%s: ERROR before the loading (%s)" % (name, m.group(0)[:120] if m else "none"),
                  res.returncode != 0 and m is not None and "BEFORE LOADING" not in res.text,
                  res.text[-800:])


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    out, res = run(args, "seep", gradients=[0, 3000])
    if chk.check("the scene runs the seepage test (%.0f s)" % res.seconds, res.returncode == 0,
                 res.describe()):
        rows = check_stages(chk, out, res)
        d60 = float(re.search(r"d60 = (\S+),", res.text).group(1))   # psd_info's line
        check_balance(chk, out, rows, d60)
        chk.check("ParaView dumps of each stage",
                  glob.glob(os.path.join(out, "seepage_i3000_*.vtk")) != [], "")
    check_bad(args, chk)
    chk.finish()


if __name__ == "__main__":
    main()
