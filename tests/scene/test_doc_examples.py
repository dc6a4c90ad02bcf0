#!/usr/bin/python3
"""Scene test: the examples on the command pages run as written.

fix sequential/pack (docs/fix_sequential_pack.md, section Examples):

1. The complete script the page links to, examples/in.sequential_pack,
   runs from a folder that sees the repository's input_scripts/, prints
   the fix's global vector and writes a full-precision dump and a restart
   file (in out/sequential_pack/); the dump holds as many atoms as f_sp[1]
   says.
2. The one-line fix (layer-wise, start centre, group soil) runs in the
   setting its sentence describes (a group soil defined before).
3. The read_restart lines read the restart file of example 1 and do not
   pack again: the atom count stays, no packing message.

compute primary/fabric (docs/compute_primary_fabric.md, section Examples):
4. The complete scene the page links to, examples/in.primary_fabric_column,
   runs as written and prints what the page says it prints (the sentence
   after the link quotes the thermo line of step 0).
5. The output lines (thermo_style, fix ave/time, dump) run in that scene.

6. The fix page's output table quotes pack_outputs.h: the position, name
   and meaning of every entry, and the vector's size.
"""

import os
import re
import shutil

import scene_util as su


def examples(page, with_text=False):
    with open(page) as f:
        text = f.read()
    section = text[text.index("## Examples"):text.index("## Description")]
    blocks = [b.strip("\n") for b in re.findall(r"```\n(.*?)```", section, re.S)]
    return (blocks, section) if with_text else blocks


def main():
    args = su.parse_args(__doc__)
    chk = su.Checker()
    page = os.path.join(args.source, "docs", "fix_sequential_pack.md")
    blocks = examples(page)
    with open(page) as f:
        linked = "(../examples/in.sequential_pack)" in f.read()
    chk.check("the page links to examples/in.sequential_pack and has two "
              "examples (found %d)" % len(blocks), linked and len(blocks) == 2)
    if len(blocks) != 2:
        chk.finish()
    root = su.fresh_dir(os.path.join(args.work, "doc_examples"))
    os.symlink(os.path.join(args.source, "input_scripts"),
               os.path.join(root, "input_scripts"))
    out, natoms = check_complete_script(args, chk, root)
    check_one_line_fix(args, chk, root, blocks[0])
    if os.path.isfile(os.path.join(out, "packed.restart")):
        check_read_restart(args, chk, root, blocks[1], natoms)
    compute_examples(args, chk, root)
    check_output_table(args, chk, page)
    chk.finish()


def check_complete_script(args, chk, root):
    """1. The complete script, as written: its output folder and the atom
    count of its dump (None without one)."""
    inp = os.path.join(args.source, "examples", "in.sequential_pack")
    res = su.run_launcher(args, inp, log=os.path.join(root, "example1.log"),
                          cwd=root, timeout=300)
    ok = chk.check("example 1 runs as written (%.1f s)" % res.seconds,
                   res.returncode == 0 and not res.errors(), res.describe())
    m = re.search(r"^placed (\S+), porosity (\S+)$", res.text, re.M)
    out = os.path.join(root, "out", "sequential_pack")
    dump = os.path.join(out, "specimen.dump")
    natoms = None
    if ok and os.path.isfile(dump):
        natoms = su.last_snapshot(dump).natoms
    chk.check("example 1 prints f_sp[1] and f_sp[3] (%s) and the dump holds "
              "that many atoms (%s)" % (m and m.groups(), natoms),
              m is not None and natoms is not None
              and float(m.group(1)) == natoms
              and abs(float(m.group(2)) - 0.35) < 0.005)
    chk.check("example 1 writes its restart file",
              os.path.isfile(os.path.join(out, "packed.restart")))
    return out, natoms


def check_one_line_fix(args, chk, root, example):
    """2. The one-line fix in the setting its sentence names."""
    d2 = su.fresh_dir(os.path.join(root, "example2"))
    shutil.copy(os.path.join(args.source, "input_scripts", "psd", "cu2.5.txt"),
                os.path.join(d2, "soil.txt"))
    text = su.preamble()
    text += ("region          box block 0 0.007 0 0.007 0 0.007 units box\n"
             "create_box      1 box\n"
             "region          container block 0 0.007 0 0.007 0 0.007 units box\n"
             "group           soil region container\n"
             "neighbor        1e-4 bin\n")
    text += example + "\n" + su.MATERIALS
    text += ("run             0\n"
             "variable        n2 equal count(soil)\n"
             "print           \"SOIL ${n2}\"\n")
    inp = su.write_file(os.path.join(d2, "in.example2"), text)
    res = su.run_launcher(args, inp, cwd=d2, timeout=300)
    chk.check("example 2 runs (%.1f s)" % res.seconds,
              res.returncode == 0 and not res.errors(), res.describe())
    m = re.search(r"^SOIL (\S+)$", res.text, re.M)
    chk.check("example 2 puts its grains in group soil (%s)"
              % (m and m.group(1)), m is not None and float(m.group(1)) > 100)
    chk.check("example 2 packs layer-wise from the centre, 40 intervals",
              "arrangement layerwise, start centre" in res.text
              and "40 equal-mass intervals" in res.text, res.text[-2000:])


def check_read_restart(args, chk, root, example, natoms):
    """3. The read_restart lines, after example 1 (its `natoms` atoms)."""
    lines = example.splitlines()
    text = "atom_modify     map array\n" + lines[0] + "\n"
    text += "newton          off\ncommunicate     single vel yes\n"
    text += "\n".join(lines[1:]) + "\n" + su.MATERIALS
    text += "run             1\n"
    inp = su.write_file(os.path.join(root, "in.example3"), text)
    res = su.run_launcher(args, inp, cwd=root, timeout=300)
    chk.check("example 3 runs (%.1f s)" % res.seconds,
              res.returncode == 0 and not res.errors(), res.describe())
    counts = re.findall(r"Loop time of \S+ on \d+ procs for \d+ steps "
                        r"with (\d+) atoms", res.text)
    chk.check("example 3 does not pack again (atoms %s, example 1 %s)"
              % (counts, natoms),
              "packing the container full" not in res.text
              and counts and natoms is not None
              and int(counts[-1]) == natoms)


def check_output_table(args, chk, page):
    entries = su.outputs.pack_vector(args.source)
    with open(page) as f:
        doc = f.read()
    missing = ["| %d | `%s` | %s |" % e for e in entries
               if "| %d | `%s` | %s |" % e not in doc]
    chk.check("the fix page quotes pack_outputs.h: %d entries, position, name "
              "and meaning" % len(entries),
              not missing and "global vector** of %d" % len(entries) in doc,
              "\n".join(missing))


def compute_examples(args, chk, root):
    page = os.path.join(args.source, "docs", "compute_primary_fabric.md")
    blocks, section = examples(page, with_text=True)
    script = os.path.join(args.source, "examples", "in.primary_fabric_column")
    with open(script) as f:
        scene = [f.read()]
    outputs = [b for b in blocks if b.startswith("thermo_style")]
    chk.check("the compute page links to its complete scene "
              "(examples/in.primary_fabric_column) and has an output example",
              "(../examples/in.primary_fabric_column)" in section and len(outputs) == 1)
    if len(outputs) != 1:
        return
    d = su.fresh_dir(os.path.join(root, "compute"))
    res = su.run_launcher(args, script, log=os.path.join(d, "scene.log"), cwd=d)
    ok = chk.check("examples/in.primary_fabric_column runs as written (%.1f s)"
                   % res.seconds, res.returncode == 0 and not res.errors(),
                   res.describe())
    # The page: "It prints `4 1 25 75 4 4 350`: ..."
    claim = re.search(r"It prints `([^`]*)`", section)
    printed = re.search(r"^\s*0\s+(.*)$", res.text, re.M) if ok else None
    want = claim.group(1).split() if claim else []
    got = printed.group(1).split() if printed else []
    chk.check("it prints what the page says (page %s, run %s)" % (want, got),
              bool(want) and len(got) == len(want) and all(
                  abs(float(g) - float(w)) <= 1e-6 * max(1.0, abs(float(w)))
                  for g, w in zip(got, want)), res.text[-2000:])
    # The output lines, in place of the scene's own thermo and dump lines.
    lines = [l for l in scene[0].splitlines()
             if not l.startswith(("thermo_style", "dump", "run"))]
    text = "\n".join(lines) + "\n" + outputs[0] + "\nrun 0\n"
    inp = su.write_file(os.path.join(d, "in.outputs"), text)
    res = su.run_launcher(args, inp, cwd=d)
    chk.check("the compute page's output lines run in that scene",
              res.returncode == 0 and not res.errors()
              and os.path.isfile(os.path.join(d, "fabric_vs_time.txt"))
              and os.path.isfile(os.path.join(d, "fabric_intervals.txt")),
              res.describe())


if __name__ == "__main__":
    main()
