#!/usr/bin/python3
"""Scene test: compute constriction/size through the launcher.

1. A simple cubic lattice of slightly overlapping grains (so each carries
   loaded contacts at run 0) with fine grains at the cube centres (no
   contacts: loose). With `fabric pf` the pores are the lattice's: every
   constriction diameter, D_c5..D_c95 and the percolation opening, is
   2 (a / sqrt 2 - R); the loose grains finer than it (half of them, 0.5 mm)
   are counted as passing by their mass, the coarser (1.0 mm) not; `loose`
   with a group gives the same verdict; without `psd` the criteria are 0.
   The whole specimen (no `fabric`) gives finer constrictions. 1, 2 and 4
   ranks print the same vector to the last digit, and the local discs
   number entry 1.
2. The examples of docs/compute_constriction_size.md run as written: its
   script, examples/in.constriction_size, prints the same vector on 1, 2
   and 4 ranks; the page's lines for a loading scene (in the lattice scene,
   where compute pf exists) both Wan & Fell probabilities of their psd.
   The page's output table quotes
   constriction_outputs.h (entries by name, as every check here reads them).
3. Height slices (keyword slices): the page's example with `slices 3`
   prints the same vector on 1 and 2 ranks, its entries 1-58 those without
   slices, its slices count every constriction; `slices 1` gives entries
   1, 41 and 42. In the lattice with `fabric pf slices 5` each slice's
   D_cP is the lattice's opening, its loose mass that of the fines whose
   centre lies in it, and its verdict the share of the fine ones in it.
4. Bad input stops with an error (3 grains, a sphere container, an unknown
   keyword, a fabric compute of another style, slices 0 and 2.5) and a
   grain hidden inside another is counted with a warning.
"""
import math
import os
import re

import scene_util as su

A = 2e-3            # lattice spacing (m)
R = 1.0005e-3       # lattice grain radius: overlaps of 1e-6 m
N = 6               # grains per lattice edge
D_OPEN = 2.0 * (A / math.sqrt(2.0) - R)
FINE, COARSE = 0.5e-3, 1.0e-3   # loose diameters, alternating
# The global vector, by the names of constriction_outputs.h: AT[name] is the
# 0-based index of an entry.
ENTRIES = su.outputs.constriction_vector()
NV = len(ENTRIES)
AT = su.outputs.index(ENTRIES)
DIAMETERS = slice(AT["dc5_number"], AT["dc95_cubed"] + 1)   # D_c5..D_c95, twice
CRITERIA = slice(AT["kezdi_max_ratio"], AT["wan_fell_sand_gravel_probability"] + 1)

MATERIALS = """\
pair_style      gran model hooke tangential history
pair_coeff      * *
fix m1 all property/global youngsModulus peratomtype 5.e6 5.e6
fix m2 all property/global poissonsRatio peratomtype 0.45 0.45
fix m3 all property/global coefficientRestitution peratomtypepair 2 0.3 0.3 0.3 0.3
fix m4 all property/global coefficientFriction peratomtypepair 2 0.5 0.5 0.5 0.5
fix m5 all property/global characteristicVelocity scalar 0.1
neigh_modify    delay 0
timestep        1e-7
"""


def lattice_scene(processors=None):
    lo, hi = -2 * A, (N + 1) * A
    text = su.preamble(processors=processors)
    text += ("region          box block %s %s %s %s %s %s units box\n"
             "create_box      2 box\n" % ((su.num(lo), su.num(hi)) * 3))
    for i in range(N):
        for j in range(N):
            for k in range(N):
                text += "create_atoms 1 single %s %s %s units box\n" % (
                    su.num(i * A), su.num(j * A), su.num(k * A))
    n = 0
    for i in range(N - 1):
        for j in range(N - 1):
            for k in range(N - 1):
                n += 1
                text += "create_atoms 2 single %s %s %s units box\n" % (
                    su.num((i + .5) * A), su.num((j + .5) * A), su.num((k + .5) * A))
                text += "set atom %d diameter %s density 2650\n" % (
                    N ** 3 + n, su.num(FINE if n % 2 else COARSE))
    text += "set type 1 diameter %s density 2650\n" % su.num(2 * R)
    text += MATERIALS
    text += "compute pf all primary/fabric intervals 3\n"
    text += "group fines type 2\n"
    return text


def vector_keywords(cid):
    """The thermo keywords of thermo_vector(cid): step, c_ID[1..NV]."""
    return ["step"] + ["c_%s[%d]" % (cid, i) for i in range(1, NV + 1)]


def thermo_vector(cid):
    return ("thermo_style custom %s\nthermo_modify format float %%.17g\n"
            % " ".join(vector_keywords(cid)))


def last_thermo(text, cid):
    """The vector of compute `cid` (entry I at I-1, named by AT) from the
    last thermo row that prints it, read by its keywords
    (outputs.read_thermo), or None."""
    rows = su.outputs.read_thermo(text, vector_keywords(cid))
    return [rows[-1][k] for k in vector_keywords(cid)[1:]] if rows else None


def local_radii(path, cid):
    """The radius column of the last snapshot of a dump local of compute
    constriction/size `cid` (by its name, tools/outputs.py)."""
    snap = su.outputs.last_snapshot(path)
    return snap.col(su.outputs.constriction_local_name("radius", cid))


def run(args, chk, name, text, nprocs=None, timeout=None):
    inp = su.write_file(os.path.join(args.work, name, "in." + name), text)
    res = su.run_launcher(args, inp, nprocs=nprocs, timeout=timeout)
    ok = chk.check("%s runs (%.1f s)" % (name, res.seconds),
                   res.returncode == 0 and not res.errors(), res.describe())
    return res if ok else None


def lattice_checks(args, chk):
    fine_m, coarse_m = 0.0, 0.0
    for n in range(1, (N - 1) ** 3 + 1):
        if n % 2:
            fine_m += FINE ** 3
        else:
            coarse_m += COARSE ** 3
    expect_pass = 100.0 * fine_m / (fine_m + coarse_m)
    vectors = {}
    for ranks in (None, 2, 4):
        text = lattice_scene(processors="1 1 %d" % ranks if ranks else None)
        text += ("compute cs all constriction/size fabric pf\n"
                 "compute cl type1 constriction/size loose fines\n"
                 "compute ca all constriction/size\n").replace(
            "type1", "lat")
        text = text.replace("group fines type 2\n",
                            "group fines type 2\ngroup lat type 1\n")
        text += ("dump dl all local 1 discs.txt c_cs[1] c_cs[2] c_cs[3] "
                 "c_cs[4] c_cs[5] c_cs[6] c_cs[7]\n")
        text += thermo_vector("cs") + "run 0\n"
        text += thermo_vector("cl") + "run 0\n"
        text += thermo_vector("ca") + "run 0\n"
        name = "lattice_np%d" % (ranks or 1)
        res = run(args, chk, name, text, nprocs=ranks)
        if not res:
            continue
        vs = [last_thermo(res.text, c) for c in ("cs", "cl", "ca")]
        if not chk.check("%s prints the three vectors" % name, all(vs)):
            continue
        vectors[ranks or 1] = vs
        if ranks:
            continue
        cs, cl, ca = vs
        dc = cs[DIAMETERS]
        chk.check("fabric pf: D_c5..D_c95 and D_c by D^3 all %.9g (got %.9g..%.9g)"
                  % (D_OPEN, min(dc), max(dc)),
                  all(abs(v - D_OPEN) < 1e-9 * D_OPEN for v in dc))
        perc = cs[AT["percolation"]]
        chk.check("percolation opening %.9g = D_open" % perc,
                  abs(perc - D_OPEN) < 1e-9 * D_OPEN)
        finer = cs[AT["loose_finer_control_percent"]]
        chk.check("loose finer than D_c35: %.6f %% = %.6f %% (the 0.5 mm ones)"
                  % (finer, expect_pass), abs(finer - expect_pass) < 1e-6)
        finer = cs[AT["loose_finer_percolation_percent"]]
        chk.check("loose finer than the percolation opening: %.6f %%" % finer,
                  abs(finer - expect_pass) < 1e-6)
        chk.check("triangulated grains %d = the lattice's %d"
                  % (cs[AT["grains"]], N ** 3), cs[AT["grains"]] == N ** 3)
        chk.check("loose group gives the same CSD and verdict",
                  cl[:DIAMETERS.stop] == cs[:DIAMETERS.stop]
                  and abs(cl[AT["loose_finer_control_percent"]]
                          - cs[AT["loose_finer_control_percent"]]) < 1e-9)
        chk.check("without psd the criteria (entries %d-%d) are 0: %s"
                  % (CRITERIA.start + 1, CRITERIA.stop, cs[CRITERIA]),
                  cs[CRITERIA] == [0.0] * (CRITERIA.stop - CRITERIA.start))
        n_all, n_pf = ca[AT["constrictions"]], cs[AT["constrictions"]]
        chk.check("the whole specimen (fines split the pores): %d > %d "
                  "constrictions, D_c5 %.4g finer than %.4g"
                  % (n_all, n_pf, ca[AT["dc5_number"]], D_OPEN),
                  n_all > n_pf and ca[AT["dc5_number"]] < 0.99 * D_OPEN)
        radii = local_radii(os.path.join(args.work, name, "discs.txt"), "cs")
        chk.check("the dump local (6 digits) holds entry 1 = %d discs of radius D_open/2"
                  % n_pf, len(radii) == int(n_pf) and all(
                      abs(r - D_OPEN / 2) < 1e-5 * D_OPEN for r in radii))
    slice_lattice(args, chk)
    if 1 in vectors:
        for r in (2, 4):
            if r in vectors:
                chk.check("lattice: %d ranks print the vectors of 1 rank" % r,
                          vectors[r] == vectors[1])


def page_blocks(args, chk):
    """The page's one block of lines, after examples/in.constriction_size's
    full script; None unless the page has the block and the link."""
    page = os.path.join(args.source, "docs", "compute_constriction_size.md")
    with open(page) as f:
        t = f.read()
    sec = t[t.index("## Examples"):t.index("## Description")]
    blocks = re.findall(r"```\n(.*?)```", sec, re.S)
    if not chk.check("the page links to examples/in.constriction_size and has one "
                     "block of lines", len(blocks) == 1
                     and "(../examples/in.constriction_size)" in sec):
        return None
    with open(os.path.join(args.source, "examples", "in.constriction_size")) as f:
        blocks.insert(0, f.read())
    return blocks


def work_folder(path, source):
    """A work folder that sees input_scripts/."""
    os.makedirs(path, exist_ok=True)
    link = os.path.join(path, "input_scripts")
    if not os.path.exists(link):
        os.symlink(os.path.join(source, "input_scripts"), link)
    return path


def run_example1(args, chk, root, script):
    """Example 1 as written on 1, 2 and 4 ranks: {ranks: its vector}."""
    vec = {}
    for ranks in (None, 2, 4):
        text = script + thermo_vector("csd") + "run 0\n"
        inp = su.write_file(os.path.join(root, "in.ex1_np%d" % (ranks or 1)), text)
        res = su.run_launcher(args, inp, nprocs=ranks, cwd=root, timeout=300)
        ok = chk.check("example 1 runs as written on %d rank(s) (%.1f s)"
                       % (ranks or 1, res.seconds),
                       res.returncode == 0 and not res.errors(), res.describe())
        if ok:
            vec[ranks or 1] = last_thermo(res.text, "csd")
    return vec


def check_control_by_area(args, chk, root, script, csd, dc35_number):
    """control_by area: D_c35 weighted by the discs' area, as computed from
    the diameters of csd_all.txt."""
    d = sorted(float(x) for x in csd["diameter"])
    tot, cum, want = sum(x * x for x in d), 0.0, None
    for x in d:
        cum += x * x
        if want is None and 100.0 * cum / tot >= 35.0:
            want = x
    line = [l for l in script.splitlines()
            if l.startswith("compute") and "constriction/size" in l][0]
    text = (script.replace(line, line + " control_by area")
            + thermo_vector("csd") + "run 0\n")
    res = su.run_launcher(args, su.write_file(os.path.join(root, "in.ex1_area"), text),
                          cwd=root, timeout=300)
    va = last_thermo(res.text, "csd") if res.returncode == 0 else None
    got = va[AT["control"]] if va else None
    chk.check("control_by area: entry 41 %s is D_c35 by area from csd_all.txt's diameters "
              "(%s), above D_c35 by number %.4g" % (got, want, dc35_number),
              got is not None and want is not None and abs(got - want) <= 1e-6 * want
              and got >= dc35_number, res.describe())


def check_example1(args, chk, root, script, vec):
    v = {e.name: vec[1][e.position - 1] for e in ENTRIES}
    n = v["constrictions"]
    chk.check("example 1: %d constrictions, D_c35 %.3g <= D_c50 %.3g, %d pores"
              % (n, v["dc35_number"], v["dc50_number"], v["pores"]),
              n > 100 and 0 < v["dc35_number"] <= v["dc50_number"]
              and v["pores"] > n / 10)
    csd = su.outputs.read_csd(os.path.join(root, "out", "constriction_size", "csd_all.txt"))
    chk.check("csd_all.txt has entry 1 = %d rows" % len(csd["diameter"]),
              len(csd["diameter"]) == n)
    check_control_by_area(args, chk, root, script, csd, v["dc35_number"])
    for r in (2, 4):
        if vec.get(r):
            chk.check("example 1: %d ranks print the vector of 1 rank" % r,
                      vec[r] == vec[1])


def check_example2(args, chk, block):
    text = lattice_scene() + block + "run 0\n"
    work_folder(os.path.join(args.work, "example2"), args.source)
    res = run(args, chk, "example2", text)
    if not res:
        return
    snaps = [f for f in os.listdir(os.path.join(args.work, "example2"))
             if f.startswith("discs_")]
    chk.check("example 2 writes the discs (%s)" % snaps, len(snaps) == 1)
    # psd: both Wan & Fell models, probabilities that differ
    cols = thermo_columns(res.text, text)
    p57, p58 = (cols.get("c_csp[%d]" % (AT[n] + 1)) for n in
                ("wan_fell_probability", "wan_fell_sand_gravel_probability"))
    chk.check("example 2 prints both Wan & Fell probabilities of the psd "
              "(%s, %s): in (0, 1), not equal" % (p57, p58),
              p57 is not None and p58 is not None and 0 < p57 < 1
              and 0 < p58 < 1 and p57 != p58, cols)


def doc_examples(args, chk):
    blocks = page_blocks(args, chk)
    if blocks is None:
        return
    root = work_folder(os.path.join(args.work, "doc"), args.source)
    vec = run_example1(args, chk, root, blocks[0])
    if vec.get(1):
        check_example1(args, chk, root, blocks[0], vec)
    slice_example(args, chk, root, blocks[0], vec.get(1))
    check_example2(args, chk, blocks[1])


def slice_keywords(cid, slices):
    """The thermo keywords of the whole vector of compute `cid` with
    `slices` height slices: step, c_ID[1..NV + K slices]."""
    n = len(su.outputs.constriction_vector(slices=slices))
    return ["step"] + ["c_%s[%d]" % (cid, i) for i in range(1, n + 1)]


def slice_vector(text, cid, slices):
    """The last whole vector of compute `cid` with `slices` slices printed
    by the thermo_style of slice_keywords (entry I at I-1), or None."""
    keys = slice_keywords(cid, slices)
    rows = su.outputs.read_thermo(text, keys)
    return [rows[-1][k] for k in keys[1:]] if rows else None


def slice_example(args, chk, root, script, whole):
    """The page's example with `slices 3` (and a second compute with
    `slices 1`) on 1 and 2 ranks; `whole`: its vector without slices."""
    line = [l for l in script.splitlines()
            if l.startswith("compute") and "constriction/size" in l][0]
    one = line.replace("compute         csd ", "compute         one ").split(" csd ")[0]
    text = script.replace(line, line + " slices 3\n" + one + " slices 1")
    keys = slice_keywords("csd", 3)[1:] + slice_keywords("one", 1)[1:]
    text += ("thermo_style custom step %s\nthermo_modify format float %%.17g\nrun 0\n"
             % " ".join(keys))
    got = {}
    for ranks in (None, 2):
        inp = su.write_file(os.path.join(root, "in.slices_np%d" % (ranks or 1)), text)
        res = su.run_launcher(args, inp, nprocs=ranks, cwd=root, timeout=300)
        if chk.check("example 1 with slices 3 runs on %d rank(s) (%.1f s)"
                     % (ranks or 1, res.seconds),
                     res.returncode == 0 and not res.errors(), res.describe()):
            rows = su.outputs.read_thermo(res.text, ["step"] + keys)
            got[ranks or 1] = [rows[-1][k] for k in keys] if rows else None
    if not got.get(1):
        return
    n3 = len(su.outputs.constriction_vector(slices=3))
    v3, v1 = got[1][:n3], got[1][n3:]
    if got.get(2):
        chk.check("slices: 2 ranks print the vectors of 1 rank", got[2] == got[1])
    chk.check("slices 3: entries 1-%d are those without slices" % NV,
              whole is not None and v3[:NV] == whole)
    rows = su.outputs.constriction_slices(v3)
    named = dict(zip((e.name for e in su.outputs.constriction_vector(slices=3)), v3))
    counted = sum(r["slice_constrictions"] for r in rows)
    chk.check("slices 3: they join, span the grains, count every constriction "
              "(%s of %d), each with a D_cP (%s)"
              % ([r["slice_constrictions"] for r in rows], v3[AT["constrictions"]],
                 [r["slice_control"] for r in rows]),
              len(rows) == 3 and rows[0]["slice_top"] == rows[1]["slice_bottom"]
              and rows[1]["slice_top"] == rows[2]["slice_bottom"]
              and named["slice2_control"] == rows[1]["slice_control"]
              and counted == v3[AT["constrictions"]]
              and all(r["slice_control"] > 0 for r in rows))
    s1 = su.outputs.constriction_slices(v1)
    chk.check("slices 1 gives entries 1, 41 and 42: %s" % s1,
              len(s1) == 1 and s1[0]["slice_constrictions"] == v1[AT["constrictions"]]
              and s1[0]["slice_control"] == v1[AT["control"]]
              and s1[0]["slice_loose_finer_control_percent"]
              == v1[AT["loose_finer_control_percent"]])


def slice_lattice(args, chk):
    """The lattice with fabric pf slices 5: the grains span -R to 5 A + R,
    so the fines at heights (k + 1/2) A, k = 0..4, fall one layer in each
    slice (0.2 mm and more from its bounds)."""
    fine, mass = [0.0] * 5, [0.0] * 5
    layer_slice = [0, 1, 2, 3, 4]
    n = 0
    for i in range(N - 1):
        for j in range(N - 1):
            for k in range(N - 1):
                n += 1
                d = FINE if n % 2 else COARSE
                m = 2650 * math.pi / 6 * d ** 3
                mass[layer_slice[k]] += m
                if d == FINE:
                    fine[layer_slice[k]] += m
    for ranks in (None, 2):
        text = lattice_scene(processors="1 1 2" if ranks else None)
        text += "compute cs all constriction/size fabric pf slices 5\n"
        keys = slice_keywords("cs", 5)
        text += ("thermo_style custom %s\nthermo_modify format float %%.17g\nrun 0\n"
                 % " ".join(keys))
        name = "slices_np%d" % (ranks or 1)
        res = run(args, chk, name, text, nprocs=ranks)
        v = slice_vector(res.text, "cs", 5) if res else None
        if not chk.check("%s prints the vector with 5 slices" % name, v is not None):
            continue
        if ranks:
            chk.check("lattice slices: 2 ranks print the vector of 1 rank",
                      v == first)
            continue
        first = v
        rows = su.outputs.constriction_slices(v)
        for s, r in enumerate(rows):
            want = 100.0 * fine[s] / mass[s]
            chk.check("lattice slice %d: %d constrictions of D_cP %.9g = D_open, loose "
                      "mass %.6g = %.6g, %.4f %% finer = %.4f %%"
                      % (s + 1, r["slice_constrictions"], r["slice_control"],
                         r["slice_loose_mass"], mass[s],
                         r["slice_loose_finer_control_percent"], want),
                      r["slice_constrictions"] > 0
                      and abs(r["slice_control"] - D_OPEN) < 1e-9 * D_OPEN
                      and abs(r["slice_loose_mass"] - mass[s]) < 1e-9 * mass[s]
                      and abs(r["slice_loose_finer_control_percent"] - want) < 1e-6)


def thermo_columns(text, script):
    """{keyword: value} of the last thermo row printed by the last
    thermo_style line of `script` (outputs.read_thermo), or {}."""
    line = [l for l in script.splitlines() if l.startswith("thermo_style")][-1]
    rows = su.outputs.read_thermo(text, line)
    return rows[-1] if rows else {}


def doc_table(args, chk):
    """The page's output table quotes constriction_outputs.h: every entry
    as `| position | `name` | meaning |`, but the percentiles 2-20 and
    21-39, one row each naming the first and last entry; and the size."""
    with open(os.path.join(args.source, "docs", "compute_constriction_size.md"),
              encoding="utf-8") as f:
        doc = f.read()
    rows = []
    for first, last in (("dc5_number", "dc95_number"), ("dc5_cubed", "dc95_cubed")):
        rows.append("| %d–%d | `%s` … `%s` |" % (AT[first] + 1, AT[last] + 1, first, last))
    rows += ["| %d | `%s` | %s |" % e for e in ENTRIES
             if not DIAMETERS.start <= e.position - 1 < DIAMETERS.stop]
    rows += ["| %d | `%s` | %s |" % e for e in su.outputs.constriction_slice_entries(args.source)]
    missing = [r for r in rows if r not in doc]
    chk.check("the page quotes constriction_outputs.h: %d entries, position, "
              "name and meaning" % NV,
              not missing and "**global vector** of %d entries" % NV in doc,
              "\n".join(missing))


def bad_input(args, chk):
    base = su.header(0.01) + su.MATERIALS
    three = "".join("create_atoms 1 single %s 0.005 0.005 units box\n"
                    % su.num(0.002 + 0.002 * i) for i in range(3))
    # each case with the phrase its own check writes, so that another error
    # on the way cannot pass for it (without grains LIGGGHTS stops first:
    # "Atom types must start from 1")
    grains = three + "set type 1 diameter 0.002 density 2650\n"
    cases = [
        ("three grains", three + "set type 1 diameter 0.002 density 2650\n"
         "compute c all constriction/size\nthermo_style custom step c_c[1]\nrun 0\n",
         "has 3 grains; a constriction network needs at least 4"),
        ("sphere container", grains + "region s sphere 0 0 0 1 units box\n"
         "compute c all constriction/size container s\nrun 0\n",
         "only a block container is supported"),
        ("unknown keyword", "compute c all constriction/size walls 1\n",
         "unknown keyword 'walls': allowed are container"),
        ("fabric of another style", grains + "compute k all ke\n"
         "compute c all constriction/size fabric k\nthermo_style custom step c_c[1]\nrun 0\n",
         "is style ke, not primary/fabric"),
        ("slices 0", "compute c all constriction/size slices 0\n",
         "Compute constriction/size: slices 0 must lie in 1..1000"),
        ("slices 2.5", "compute c all constriction/size slices 2.5\n",
         "Compute constriction/size: slices '2.5' is not an integer in 1..1000"),
    ]
    for what, tail, phrase in cases:
        inp = su.write_file(os.path.join(args.work, "bad", "in.bad"), base + tail)
        res = su.run_launcher(args, inp, timeout=60)
        chk.check("%s: an ERROR saying '%s', no crash" % (what, phrase),
                  not res.crashed() and not res.timed_out
                  and any(phrase in e for e in res.errors()),
                  res.describe())
    # A fine grain inside a coarse one: hidden, counted, warned.
    text = lattice_scene() + ("create_atoms 2 single %s %s %s units box\n"
                              "set atom %d diameter 2e-4 density 2650\n"
                              % (su.num(A + 1e-4), su.num(A), su.num(A),
                                 N ** 3 + (N - 1) ** 3 + 1))
    text += "compute cs all constriction/size\n" + thermo_vector("cs") + "run 0\n"
    res = run(args, chk, "hidden", text)
    if res:
        v = last_thermo(res.text, "cs")
        hidden = v and v[AT["hidden"]]
        chk.check("the hidden grain is counted (entry %d = %s) with a warning"
                  % (AT["hidden"] + 1, hidden), hidden == 1 and re.search(
                      r"WARNING: Compute constriction/size: 1 of", res.text))


def main():
    args = su.parse_args(__doc__)
    chk = su.Checker()
    lattice_checks(args, chk)
    doc_examples(args, chk)
    doc_table(args, chk)
    bad_input(args, chk)
    chk.finish()


if __name__ == "__main__":
    main()
