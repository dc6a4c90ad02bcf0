#!/usr/bin/python3
"""Scene test: fix sequential/pack says what is true, and only then.

1. A near-empty container (porosity 0.999) keeps only a few grains: the
   fix warns which intervals round to no grain and how much larger the
   container must be; a well-sized specimen gets no such warning and no
   'not placed' warning.
2. After read_restart, the same fix ID with other settings keeps the
   restored specimen and says so, naming both settings; the same settings
   say nothing.
3. The specimen's structure: the summary and f_ID[10] give the size
   assortativity of touching pairs (below 0 for a discrete specimen), f_ID[12]
   that of the interior's pairs. A layer-wise specimen is judged by its
   interior: Cu 2.0 and Cu 3.0, whose like sizes touch mainly in the fine
   layer on the floor (f_ID[10] above f_ID[12]), get a warning naming both
   values as the vector holds them; a discrete specimen gets none.
"""

import os
import re

import scene_util as su

EDGE = 5.6e-3
FIX = "pack"


def fix_line(psd, porosity, seed):
    return ("fix             %s all sequential/pack psd %s porosity %s "
            "arrangement discrete region container seed %d verbose no\n"
            % (FIX, psd, su.num(porosity), seed))


def main():
    args = su.parse_args(__doc__)
    chk = su.Checker()
    psd = os.path.join(args.source, "input_scripts", "psd", "cu2.5.txt")
    root = su.fresh_dir(os.path.join(args.work, "fix_messages"))

    # 1. empty intervals
    inp = su.write_file(os.path.join(root, "in.sparse"), su.pack_scene(
        psd, EDGE, porosity=0.999, fix_id=FIX, extra_fix="verbose no"))
    res = su.run_launcher(args, inp)
    m = re.search(r"WARNING: Fix sequential/pack: (\d+) of 20 intervals hold "
                  r"no grain.*?at least (\S+) times the volume", res.text)
    chk.check("porosity 0.999: a warning names the empty intervals and the "
              "container needed (%s)" % str(m and m.groups()),
              res.returncode == 0 and m is not None and int(m.group(1)) > 0
              and float(m.group(2)) > 1.0, res.text[-3000:])
    inp = su.write_file(os.path.join(root, "in.dense"), su.pack_scene(
        psd, 6 * 1.603e-3, porosity=0.35, fix_id=FIX, extra_fix="verbose no"))
    res = su.run_launcher(args, inp)
    chk.check("porosity 0.35 in 6 coarsest diameters: no warning",
              res.returncode == 0 and "WARNING: Fix sequential/pack"
              not in res.text, res.text[-3000:])
    vec = su.pack_vector(res.text)
    line = re.search(r"structure: size assortativity of touching pairs ([-+0-9.]+)",
                     res.text)
    chk.check("discrete: f_ID[10], the size assortativity, is below 0 (fines "
              "between coarse grains) and the summary prints it (%s, %s)"
              % (vec and vec["size_assortativity"], line and line.group(1)),
              vec is not None and line is not None
              and vec["size_assortativity"] < 0.0
              and abs(float(line.group(1)) - vec["size_assortativity"]) < 6e-4
              and abs(vec["radius_distance_spearman"]) < 0.1, res.text[-3000:])
    inp = su.write_file(os.path.join(root, "in.small"), su.pack_scene(
        psd, EDGE, porosity=0.35, fix_id=FIX, extra_fix="verbose no"))
    res = su.run_launcher(args, inp)
    vec = su.pack_vector(res.text)
    missing = vec and vec["listed"] - vec["placed"]
    if missing:
        chk.check("porosity 0.35 in 3.2 coarsest diameters, %d not placed: "
                  "the warning says the container is too small, not the "
                  "porosity too low" % missing,
                  "found no" not in res.text and "too late to find a place"
                  in res.text and "use at least 6" in res.text
                  and "Use a porosity" not in res.text, res.text[-3000:])
    else:
        chk.check("porosity 0.35 in 3.2 coarsest diameters, all placed: no "
                  "not-placed warning", "not placed (" not in res.text)

    # 3. a layer-wise specimen not layered in its interior says so, with
    # the values of the vector: Cu 3.0 in a cube of 4.5 coarsest diameters
    # (32,000 grains), Cu 2.0 at 0.40 in 8.6 (over the container +0.2 or
    # more from the fine floor layer, below 0 inside)
    for soil, edge, porosity in (("cu3.0", 10.4e-3, 0.35),
                                 ("cu2.0", 8.75e-3, 0.40)):
        inp = su.write_file(os.path.join(root, "in.la_" + soil), su.pack_scene(
            os.path.join(args.source, "input_scripts", "psd", soil + ".txt"),
            edge, porosity=porosity, arrangement="layerwise", fix_id=FIX,
            extra_fix="verbose no"))
        res = su.run_launcher(args, inp)
        vec = su.pack_vector(res.text)
        m = re.search(r"WARNING: Fix sequential/pack: the layer-wise specimen "
                      r"is not layered in its interior: the size assortativity "
                      r"of the touching pairs there is (\S+), below 0.1.*?"
                      r"Over the whole container it is ([-+0-9.]+)", res.text)
        line = re.search(r"structure: size assortativity of touching pairs "
                         r"(\S+), in the interior (\S+) ", res.text)
        a = vec and vec["size_assortativity"]
        ai = vec and vec["interior_size_assortativity"]
        chk.check("layer-wise %s at %s: assortativity %s over the container, "
                  "%s in the interior: a warning and the summary give both "
                  "as the vector holds them" % (soil, su.num(porosity), a, ai),
                  res.returncode == 0 and vec is not None and m is not None
                  and line is not None and ai < 0.1 and a > ai
                  and abs(float(m.group(1)) - ai) < 6e-4
                  and abs(float(m.group(2)) - a) < 6e-4
                  and abs(float(line.group(1)) - a) < 6e-4
                  and abs(float(line.group(2)) - ai) < 6e-4,
                  res.text[-3000:])
    inp = su.write_file(os.path.join(root, "in.da_cu2.0"), su.pack_scene(
        os.path.join(args.source, "input_scripts", "psd", "cu2.0.txt"),
        8.75e-3, porosity=0.40, fix_id=FIX, extra_fix="verbose no"))
    res = su.run_launcher(args, inp)
    vec = su.pack_vector(res.text)
    chk.check("discrete cu2.0 at 0.4: no layering warning, interior "
              "assortativity below 0 (%s)"
              % (vec and vec["interior_size_assortativity"]),
              res.returncode == 0 and vec is not None
              and "not layered" not in res.text
              and vec["interior_size_assortativity"] < 0.0, res.text[-3000:])

    # 2. redefinition after read_restart with other settings
    restart = os.path.join(root, "packed.restart")
    text = su.header(EDGE)
    text += su.block_region("container", (0, 0, 0), (EDGE, EDGE, EDGE))
    text += fix_line(psd, 0.4, 3) + su.MATERIALS
    text += "run             1\nwrite_restart   %s\n" % restart
    res = su.run_launcher(args, su.write_file(os.path.join(root, "in.write"),
                                              text))
    chk.check("a specimen is packed and saved", res.returncode == 0
              and os.path.isfile(restart), res.describe())
    for porosity, seed, expect in ((0.4, 3, False), (0.37, 9, True)):
        text = ("atom_modify     map array\nread_restart    %s\n"
                "newton          off\ncommunicate     single vel yes\n"
                % restart)
        text += su.block_region("container", (0, 0, 0), (EDGE, EDGE, EDGE))
        text += fix_line(psd, porosity, seed) + su.MATERIALS + "run 1\n"
        res = su.run_launcher(args, su.write_file(
            os.path.join(root, "in.read_%d" % seed), text))
        said = re.search(r"WARNING: Fix sequential/pack: the specimen restored "
                         r"from the restart file was packed with porosity 0.4"
                         r".*?seed 3.*?porosity 0.37.*?seed 9", res.text,
                         re.S) is not None
        chk.check("read_restart, porosity %s seed %d: %s" % (
                      su.num(porosity), seed,
                      "warns with both settings" if expect else "no warning"),
                  res.returncode == 0 and said == expect
                  and "packing the container full" not in res.text
                  and ("restored from the restart" in res.text) == expect,
                  res.text[-3000:])
    chk.finish()


if __name__ == "__main__":
    main()
