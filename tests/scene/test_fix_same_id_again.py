#!/usr/bin/python3
"""Scene test: defining fix sequential/pack again with the same ID after it
packed is refused; before the packing it replaces the settings.

LIGGGHTS replaces a fix defined again under an existing ID (Modify::add_fix
deletes the old one and creates the new one in its place): the new fix
starts without the old one's state and packed a second specimen on top of
the first (coincident grains, NaN forces, exit code 0). Checked:
  * fix, run 1, the same fix ID again, run 10: an ERROR from the fix that
    names the ID, no second packing, no NaN, no crash;
  * the same on 2 ranks (error->all on every rank, no hang);
  * two definitions with the same ID before the first run (other seed): the
    second replaces the first, one specimen is packed (the atom count of a
    single packing), the run completes.
(After read_restart the same ID restores the fix without packing:
test_restart_no_reinsert.py.)
"""

import os
import re

import scene_util as su

EDGE = 3.5e-3
FIX = "pack"


def fix_line(psd, seed):
    return ("fix             %s all sequential/pack psd %s porosity 0.4 "
            "arrangement layerwise region container seed %d verbose no\n"
            % (FIX, psd, seed))


def start(psd):
    text = su.header(EDGE)
    text += su.block_region("container", (0, 0, 0), (EDGE, EDGE, EDGE))
    return text


def atoms_of(text):
    """Atom counts of the 'Loop time ... with N atoms' lines."""
    return [int(n) for n in re.findall(r"Loop time .* with (\d+) atoms", text)]


def main():
    args = su.parse_args(__doc__)
    chk = su.Checker()
    psd = os.path.join(args.source, "input_scripts", "psd", "cu2.5.txt")
    root = su.fresh_dir(os.path.join(args.work, "same_id_again"))

    # After the packing: refused.
    text = start(psd) + fix_line(psd, 3) + su.MATERIALS
    text += "run             1\n"
    text += fix_line(psd, 3)
    text += ("fix             nve all nve/sphere\n"
             "thermo_style    custom step atoms fmax\n"
             "run             10\n"
             'print           "RUN COMPLETED"\n')
    for nprocs in (None, 2):
        tag = "serial" if nprocs is None else "%d ranks" % nprocs
        d = su.fresh_dir(os.path.join(root, "after_" + tag.replace(" ", "")))
        res = su.run_launcher(args, su.write_file(os.path.join(d, "in.again"),
                                                  text), nprocs=nprocs)
        errors = res.errors()
        ok = [l for l in errors if "Fix sequential/pack" in l
              and "'%s'" % FIX in l and "defined again" in l]
        chk.check("%s: the same ID again after the packing stops with the "
                  "fix's ERROR (%.1f s)" % (tag, res.seconds),
                  ok and res.returncode != 0 and not res.crashed()
                  and not res.timed_out, res.describe())
        if ok:
            chk.note(ok[0].strip())
        chk.check("%s: packed once, no second run" % tag,
                  res.output.count("fix sequential/pack summary") == 1
                  and "RUN COMPLETED" not in res.output
                  and len(atoms_of(res.output)) == 1, res.describe())
        chk.check("%s: no NaN printed" % tag,
                  not re.search(r"\bnan\b", res.output, re.I), res.describe())

    # Before the packing: the second definition replaces the first.
    text = start(psd) + fix_line(psd, 3) + fix_line(psd, 4) + su.MATERIALS
    text += "run             1\n" + 'print           "RUN COMPLETED"\n'
    d = su.fresh_dir(os.path.join(root, "before"))
    res = su.run_launcher(args, su.write_file(os.path.join(d, "in.before"),
                                              text))
    chk.check("the same ID twice before the first run: runs (%.1f s)"
              % res.seconds, res.returncode == 0 and not res.errors()
              and "RUN COMPLETED" in res.output, res.describe())
    summary = su.pack_summary(res.text)
    n = atoms_of(res.output)
    chk.check("... one specimen packed, with the second definition's seed "
              "(%s atoms)" % n,
              res.output.count("fix sequential/pack summary") == 1
              and "seed 4" in res.output and summary is not None
              and n == [summary[1]], res.describe())
    chk.finish()


if __name__ == "__main__":
    main()
