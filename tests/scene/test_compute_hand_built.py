#!/usr/bin/python3
"""Scene test: compute primary/fabric on hand-built scenes whose answer is
known, and its bad-input errors.

A column of three spheres is squeezed between two walls (each sphere has
two loaded contacts, particles and walls), and a free sphere lies beside
it. With min_contacts 2 the column is primary fabric and the free sphere
loose; with the default min_contacts 3 all four are loose. The same state
on 2 ranks, cut through the column (processors 1 1 2), must classify alike.

Every entry of the global vector and of the per-interval array is checked
through the launcher on a scene whose answer is worked out by hand (RICH
below), by the names of compute_primary_fabric/fabric_outputs.h; the
command page's output tables must quote that header. With slices 3 the
column's height slices report the figures worked out by hand, on 1 and 2
ranks alike, and the classes stay those of the whole column.
"""
import math
import os
import re

import numpy as np

import scene_util as su

COLUMN = """\
{preamble}region box block -0.01 0.01 -0.01 0.01 -0.001 0.008 units box
create_box 2 box
neigh_modify delay 0
fix m1 all property/global kn peratomtypepair 2 2e7 2e7 2e7 2e7
fix m2 all property/global kt peratomtypepair 2 2e7 2e7 2e7 2e7
fix m3 all property/global gamman peratomtypepair 2 1e3 1e3 1e3 1e3
fix m4 all property/global gammat peratomtypepair 2 1e3 1e3 1e3 1e3
fix m5 all property/global coefficientFriction peratomtypepair 2 0.4 0.4 0.4 0.4
pair_style gran model hooke/stiffness tangential history
pair_coeff * *
create_atoms 1 single 0 0 0.00099 units box
create_atoms 1 single 0 0 0.00297 units box
create_atoms 1 single 0 0 0.00495 units box
{free}
set atom * diameter 0.002 density 2650
fix wb all wall/gran model hooke/stiffness tangential history primitive type 2 zplane 0.0 store_force_contact_stress yes
fix wt all wall/gran model hooke/stiffness tangential history primitive type 2 zplane 0.00593 store_force_contact_stress yes
{compute}
fix nve all nve/sphere
timestep 1e-8
thermo_style custom step c_pf[1] c_pf[2] c_pf[3] c_pf[4] c_pf[10] c_pf[11]
thermo_modify format float %.10g
dump d all custom 1 {dump} id z {peratom}
dump_modify d sort id
run 0
"""


FREE = "create_atoms 1 single 0.005 0 0.003 units box"
# A on the bottom wall with B resting on it: B has one loaded contact, A two.
DANGLING = ("create_atoms 1 single 0.005 0 0.00099 units box\n"
            "create_atoms 1 single 0.005 0 0.00297 units box")


# the per-atom columns of compute pf as the dump names them (c_pf[I])
LOADED = su.outputs.peratom_name("loaded_contacts")
PRIMARY = su.outputs.PRIMARY


def column_text(compute, free=FREE, dump="", processors=None):
    """COLUMN with its compute, free grains, dump and processors."""
    peratom = " ".join(su.outputs.peratom_name(e.name) for e in su.outputs.fabric_peratom())
    return COLUMN.format(preamble=su.preamble(processors=processors or None), compute=compute,
                         dump=dump, free=free, peratom=peratom)


def entry(name, source=su.outputs.ROOT):
    """The thermo keyword of global vector entry `name`: c_pf[I]."""
    return "c_pf[%d]" % (su.outputs.index(su.outputs.fabric_vector(source))[name] + 1)


def thermo_values(output, fields):
    """{field: value} of the last thermo row of the thermo_style `step
    fields` (the keywords of the scene's thermo_style, in order), read by
    those keywords (outputs.read_thermo), or None."""
    rows = su.outputs.read_thermo(output, ["step"] + list(fields))
    return rows[-1] if rows else None


def run_column(args, chk, name, compute, nprocs=None, processors="", free=FREE):
    """Runs COLUMN; {id: (loaded contacts, class)} from its dump, by the
    dump's column names, or None if it failed."""
    dump = os.path.join(args.work, name + ".dump")
    inp = su.write_file(os.path.join(args.work, "in." + name),
                        column_text(compute, free, dump, processors))
    res = su.run_launcher(args, inp, nprocs=nprocs)
    ok = chk.check("%s runs" % name, res.returncode == 0 and os.path.isfile(dump),
                   res.describe())
    if not ok:
        return None
    s = su.last_snapshot(dump)
    return dict(zip(s.col("id", int).tolist(),
                    zip(s.col(LOADED, as_int).tolist(), s.col(PRIMARY, as_int).tolist())))


def as_int(token):
    return int(float(token))


def expect_error(args, chk, what, text, expect):
    """Runs `text`; it must end with an ERROR (containing `expect`, if given),
    without a crash or a hang."""
    inp = su.write_file(os.path.join(args.work, "in.bad"), text)
    res = su.run_launcher(args, inp, timeout=60)
    err = [l for l in res.text.splitlines() if "ERROR" in l]
    ok = not res.crashed() and not res.timed_out and bool(err)
    if expect:
        ok = ok and expect in err[0]
    chk.check("%s: ERROR%s" % (what, " containing %r" % expect if expect else ""),
              ok, "\n".join(err) or res.describe())


# The column of three (d 2 mm) between the walls, a tilted pair (d 1 mm)
# floating free, and a free coarse sphere (d 3 mm): three size intervals.
# Overlaps: bottom wall 1e-5 m (200 N), column contacts and top wall 2e-5 m
# (400 N each), the pair 1e-5 m (200 N) along n = (0.48, 0.36, 0.8).
PAIR_N = (0.48, 0.36, 0.8)
PAIR_P = (0.005, 0.0, 0.003)
PAIR_Q = tuple(p + 0.00099 * n for p, n in zip(PAIR_P, PAIR_N))
RICH_ATOMS = """\
create_atoms 1 single {px} {py} {pz} units box
create_atoms 1 single {qx} {qy} {qz} units box
create_atoms 1 single -0.005 0 0.004 units box""".format(
    px=su.num(PAIR_P[0]), py=su.num(PAIR_P[1]), pz=su.num(PAIR_P[2]),
    qx=su.num(PAIR_Q[0]), qy=su.num(PAIR_Q[1]), qz=su.num(PAIR_Q[2]))


def rich_expected():
    """The global vector and array of RICH (min_contacts 2, intervals 3), by
    name, worked out from the overlaps (kn = 2e7 N/m, hooke/stiffness)."""
    n = PAIR_N
    # particle contacts: (force, direction); walls do not enter the tensors
    contacts = [(400.0, (0, 0, 1)), (400.0, (0, 0, 1)), (200.0, n)]
    walls = [200.0, 400.0]
    forces = [f for f, _ in contacts] + walls
    mean = sum(forces) / len(forces)                    # 320 N
    mass = {1: 1.0, 2: 8.0, 3: 27.0}                    # per sphere, d^3
    total = 2 * mass[1] + 3 * mass[2] + mass[3]         # 53
    v = {"particles": 6, "loose_particles": 3, "loose_percent_by_number": 50,
         "primary_percent_by_mass": 100 * 3 * mass[2] / total,
         "coordination": 8 / 6, "primary_coordination": 2,
         "r1": 0.001, "r2": 0.0015,
         "overlapping_zone_percent": 100 * (3 * mass[2] + mass[3]) / total,
         "contacts": 5, "loaded_contacts": 5, "mean_normal_force": mean,
         "threshold_force": 1e-3 * mean, "prune_passes": 0}
    axes = {"x": 0, "y": 1, "z": 2}
    for ab in ("xx", "yy", "zz", "xy", "xz", "yz"):
        a, b = axes[ab[0]], axes[ab[1]]
        v["fabric_" + ab] = sum(d[a] * d[b] for _, d in contacts) / len(contacts)
        v["force_fabric_" + ab] = (sum(f * d[a] * d[b] for f, d in contacts)
                                   / sum(f for f, _ in contacts))
    # anisotropies: a = (15/2) dev(T), scalar sign(a_zz) sqrt(2/3 a:a)
    F = sum(np.outer(d, d) for _, d in contacts) / len(contacts)
    P = sum(f * np.outer(d, d) for f, d in contacts) / sum(f for f, _ in contacts)

    def scalar(D):
        a = 7.5 * D
        return math.copysign(math.sqrt(2.0 / 3.0 * float(np.sum(a * a))), a[2, 2])

    def dev(T):
        return T - np.trace(T) / 3.0 * np.eye(3)
    v["fabric_anisotropy"] = scalar(dev(F))
    v["force_anisotropy"] = scalar(dev(P) - dev(F))
    # the tolerant zone (0.1): each class fills its interval here, as the paper's
    v["r1_tolerant"], v["r2_tolerant"] = v["r1"], v["r2"]
    v["overlapping_zone_tolerant_percent"] = v["overlapping_zone_percent"]
    bins = [(0.0, 0.0)] * 9
    bins[0] = (2 / 3, 400.0)                        # the column, vertical
    theta = math.degrees(math.acos(n[2]))           # 36.9 degrees: bin 4
    bins[int(theta // 10)] = (1 / 3, 200.0)
    rows = [  # diameter mass% primary%ofinterval loose%mass contacts/particle
              # force/contact primary%mass particles
        {"diameter": 0.001, "mass_percent": 100 * 2 * mass[1] / total,
         "primary_percent_of_interval": 0,
         "loose_mass_percent": 100 * 2 * mass[1] / total,
         "loaded_contacts_per_particle": 1,
         "normal_force_per_loaded_contact": 200, "primary_mass_percent": 0,
         "particles": 2},
        {"diameter": 0.002, "mass_percent": 100 * 3 * mass[2] / total,
         "primary_percent_of_interval": 100, "loose_mass_percent": 0,
         "loaded_contacts_per_particle": 2,
         "normal_force_per_loaded_contact": (200 + 400 + 4 * 400) / 6,
         "primary_mass_percent": 100 * 3 * mass[2] / total, "particles": 3},
        {"diameter": 0.003, "mass_percent": 100 * mass[3] / total,
         "primary_percent_of_interval": 0,
         "loose_mass_percent": 100 * mass[3] / total,
         "loaded_contacts_per_particle": 0,
         "normal_force_per_loaded_contact": 0, "primary_mass_percent": 0,
         "particles": 1},
    ]
    return v, bins, rows


def layout(source):
    """(vector entries, array columns) of fabric_outputs.h, as
    tools/outputs.py reads them: lists of (position, name, meaning)."""
    return su.outputs.fabric_vector(source), su.outputs.fabric_array(source)


def rich_text(args, compute, name, sets, fields):
    """The RICH scene: COLUMN with the tilted pair and the coarse sphere,
    `sets` after the diameters are set, thermo of `fields` at full
    precision."""
    text = column_text(compute, RICH_ATOMS, os.path.join(args.work, name + ".dump"))
    text = text.replace("set atom * diameter 0.002 density 2650\n",
                        "set atom * diameter 0.002 density 2650\n" + sets)
    text = re.sub(r"thermo_style custom .*", "thermo_style custom step " + " ".join(fields), text)
    text = text.replace("thermo_modify format float %.10g", "thermo_modify format float %.17g")
    return su.write_file(os.path.join(args.work, "in." + name), text)


def close(a, b):
    return abs(a - b) <= 1e-6 * max(1.0, abs(b))


def check_outputs(args, chk):
    """Every global vector entry and array element of RICH, through thermo
    output at full precision, by the names of fabric_outputs.h."""
    vec, cols = layout(args.source)
    chk.check("fabric_outputs.h: 31 vector entries and 8 array columns, "
              "numbered 1..n in order",
              [p for p, _, _ in vec] == list(range(1, 32))
              and [p for p, _, _ in cols] == list(range(1, 9)), (vec, cols))
    nfixed = len(vec)
    fields = ["c_pf[%d]" % i for i in range(1, su.outputs.fabric_vector_size(9, args.source) + 1)]
    fields += ["c_pf[%d][%d]" % (r, c) for r in range(1, 4) for c in range(1, len(cols) + 1)]
    inp = rich_text(args, "compute pf all primary/fabric min_contacts 2 intervals 3", "rich",
                    "set atom 4*5 diameter 0.001 density 2650\n"
                    "set atom 6 diameter 0.003 density 2650\n", fields)
    res = su.run_launcher(args, inp)
    if not chk.check("the hand-built scene with three intervals runs",
                     res.returncode == 0 and not res.errors(), res.describe()):
        return
    values = thermo_values(res.output, fields)
    if not chk.check("thermo prints all %d values" % len(fields), values, res.describe()):
        return
    want_v, want_bins, want_rows = rich_expected()
    wrong = []
    for pos, name, meaning in vec:
        got = values["c_pf[%d]" % pos]
        if not close(got, want_v[name]):
            wrong.append("c_pf[%d] %s (%s): %r, expected %r"
                         % (pos, name, meaning, got, want_v[name]))
    chk.check("global vector entries 1-31, by name from fabric_outputs.h",
              not wrong, "\n".join(wrong))
    wrong = []
    for b, (frac, force) in enumerate(want_bins):
        # after the fixed entries, (fraction, mean force) per bin
        for k, want in ((nfixed + 1 + 2 * b, frac), (nfixed + 2 + 2 * b, force)):
            got = values["c_pf[%d]" % k]
            if not close(got, want):
                wrong.append("c_pf[%d] (bin %d): %r, expected %r" % (k, b + 1, got, want))
    chk.check("direction bins, entries 32-49 (fraction, mean force per bin)",
              not wrong, "\n".join(wrong))
    wrong = []
    for r, row in enumerate(want_rows):
        for pos, name, meaning in cols:
            got = values["c_pf[%d][%d]" % (r + 1, pos)]
            if not close(got, row[name]):
                wrong.append("c_pf[%d][%d] %s: %r, expected %r"
                             % (r + 1, pos, name, got, row[name]))
    chk.check("global array, 3 rows x 8 columns, by name from fabric_outputs.h",
              not wrong, "\n".join(wrong))


def check_weight(args, chk):
    """weight mass | volume on RICH with the column ten times denser (as a
    density-scaled run makes grains): by mass the column holds 240/269 of
    the mass (d^3 x density), by volume 24/53 whatever the densities."""
    primary = entry("primary_percent_by_mass", args.source)
    for weight, want in (("mass", 100.0 * 240 / 269), ("volume", 100.0 * 24 / 53)):
        inp = rich_text(args, "compute pf all primary/fabric min_contacts 2 intervals 3 weight "
                        + weight, "weight_" + weight,
                        "set atom 1*3 density 26500\n"
                        "set atom 4*5 diameter 0.001 density 2650\n"
                        "set atom 6 diameter 0.003 density 2650\n", [primary])
        res = su.run_launcher(args, inp)
        values = thermo_values(res.output, [primary])
        got = values[primary] if values else None
        chk.check("weight %s: primary %% by mass %s, expected %.6f" % (weight, got, want),
                  got is not None and abs(got - want) < 1e-6 * want, res.describe())


def check_slices(args, chk):
    """slices 3 on the column (min_contacts 2): the grains' extent, z -1e-5
    to 5.95e-3 m, in three slices of 1.98 mm; the column's lower and upper
    sphere alone in slices 1 and 3 (primary), its middle one and the free
    sphere in slice 2 (one primary of two, equal masses). The two column
    contacts, both along z, count half in each slice of their grains. The
    classification is the whole specimen's (the same classes as without
    slices), and 2 ranks cut through the column give the same entries."""
    slices = su.outputs.read_table(os.path.join(args.source, su.outputs.FABRIC_HEADER),
                                   "FABRIC_SLICE_ENTRIES")
    first = len(su.outputs.fabric_vector(args.source)) + 2 * 9 + 1
    n = 3 * len(slices)
    got = {}
    for nprocs, proc in ((None, ""), (2, "1 1 2")):
        out = os.path.join(args.work, "slices_%d.txt" % (nprocs or 1))
        compute = ("compute pf all primary/fabric min_contacts 2 intervals 1 slices 3\n"
                   "fix sv all ave/time 1 1 1 %s file %s"
                   % (" ".join("c_pf[%d]" % i for i in range(first, first + n)), out))
        classes = run_column(args, chk, "column_slices_%d" % (nprocs or 1), compute,
                             nprocs=nprocs, processors=proc)
        if classes is None or not os.path.isfile(out):
            return
        chk.check("slices 3 on %d rank(s): the column's classes as without slices"
                  % (nprocs or 1), classes == {1: (2, 1), 2: (2, 1), 3: (2, 1), 4: (0, 0)},
                  classes)
        row = [float(v) for v in su.outputs.data_rows(out)[-1][1:]]
        got[nprocs or 1] = [{e.name: row[k * len(slices) + e.position - 1] for e in slices}
                            for k in range(3)]
    one = got[1]
    a_z = 7.5 * math.sqrt(2.0 / 3.0 * (4.0 / 9 + 1.0 / 9 + 1.0 / 9))  # F = e_z e_z
    want = [(-1e-5, 1, 25, 100, 0, 2, 0.5), (None, 2, 50, 50, 50, 1, 1.0),
            (5.95e-3, 1, 25, 100, 0, 2, 0.5)]
    bad = []
    for k, (z, grains, mass, prim, loose, coord, ends) in enumerate(want):
        s = one[k]
        for name, value, w in (("slice_particles", s["slice_particles"], grains),
                               ("slice_mass_percent", s["slice_mass_percent"], mass),
                               ("slice_primary_percent", s["slice_primary_percent"], prim),
                               ("slice_loose_percent_by_number",
                                s["slice_loose_percent_by_number"], loose),
                               ("slice_coordination", s["slice_coordination"], coord),
                               ("slice_fabric_contacts", s["slice_fabric_contacts"], ends),
                               ("slice_fabric_anisotropy", s["slice_fabric_anisotropy"], a_z),
                               ("slice_force_anisotropy", s["slice_force_anisotropy"], 0.0)):
            if abs(value - w) > 1e-4 * max(1.0, abs(w)):
                bad.append("slice %d %s: %g, expected %g" % (k + 1, name, value, w))
    if abs(one[0]["slice_bottom"] + 1e-5) > 1e-9 or abs(one[2]["slice_top"] - 5.95e-3) > 1e-9:
        bad.append("extent %g to %g, expected -1e-5 to 5.95e-3"
                   % (one[0]["slice_bottom"], one[2]["slice_top"]))
    chk.check("slices 3: each slice's grains, mass, primary and loose shares, "
              "coordination, contacts and anisotropies as worked out", not bad, "\n".join(bad))
    if 2 in got:
        diff = max(abs(a[k] - b[k]) / max(1.0, abs(a[k]))
                   for a, b in zip(got[1], got[2]) for k in a)
        chk.check("slices 3: 1 and 2 ranks (cut through the column) give the same "
                  "entries (largest relative difference %.2g)" % diff, diff < 1e-9)


def check_docs_quote_layout(args, chk):
    """The command page's output tables name every entry of the header, in
    its position."""
    vec, cols = layout(args.source)
    with open(os.path.join(args.source, "docs", "compute_primary_fabric.md")) as f:
        doc = f.read()
    missing = []
    per = su.outputs.fabric_peratom(args.source)
    slices = su.outputs.read_table(os.path.join(args.source, su.outputs.FABRIC_HEADER),
                                   "FABRIC_SLICE_ENTRIES")
    for table, entries in (("vector", vec), ("array", cols), ("per-atom", per),
                           ("slices", slices)):
        for pos, name, meaning in entries:
            row = "| %d | `%s` | %s |" % (pos, name, meaning)
            if row not in doc:
                missing.append("%s: %s" % (table, row))
    chk.check("docs/compute_primary_fabric.md quotes fabric_outputs.h "
              "(position, name, meaning of every entry)", not missing,
              "\n".join(missing))


BASE = "compute pf all primary/fabric min_contacts 2 intervals 1"
ITERATE = "compute pf all primary/fabric min_contacts 2 prune iterate intervals 1"
WANT = {1: (2, 1), 2: (2, 1), 3: (2, 1), 4: (0, 0)}  # id: (contacts, class)


def dangling_iterated(got):
    """B loose, then A loose too; the column stays primary."""
    return (got.get(4, (0, 9))[1] == 0 and got.get(5, (0, 9))[1] == 0
            and all(got[i][1] == 1 for i in (1, 2, 3)))


# The column scenes: (run name, compute, nprocs, processors, free grains,
# what the check says, what {id: (contacts, class)} must satisfy).
COLUMN_CASES = [
    ("column", BASE, None, "", FREE,
     "column spheres have 2 loaded contacts and are primary; the free sphere has none and is loose",
     lambda got: got == WANT),
    ("column_min3", "compute pf all primary/fabric intervals 1", None, "", FREE,
     "with min_contacts 3 (the paper's rule) all four are loose",
     lambda got: all(c == 0 for (_, c) in got.values())),
    ("column_2ranks", BASE, 2, "1 1 2", FREE,
     "2 ranks cut through the column: same contacts and classes", lambda got: got == WANT),
    ("column_iterate_2ranks", ITERATE, 2, "1 1 2", FREE,
     "prune iterate on 2 ranks: the column stays primary (walls hold it)",
     lambda got: got == WANT),
    # prune once vs iterate: a dangling pair on the bottom wall (ids 4, 5).
    ("dangling_once", BASE, None, "", DANGLING,
     "prune once: A (wall + B) is primary, B (A only) is loose",
     lambda got: got.get(4) == (2, 1) and got.get(5) == (1, 0)),
    ("dangling_iterate_1", ITERATE, None, "", DANGLING,
     "prune iterate on 1 rank(s): B loose, then A loose too; the column stays primary",
     dangling_iterated),
    ("dangling_iterate_2", ITERATE, 2, "1 1 2", DANGLING,
     "prune iterate on 2 rank(s): B loose, then A loose too; the column stays primary",
     dangling_iterated),
    # store_every: the pair style stores contact forces on multiples of N
    # only; evaluated on such a step (step 0) the answer is the same.
    ("column_store_every", BASE + " store_every 10", None, "", FREE,
     "store_every 10, evaluated at step 0: same contacts and classes", lambda got: got == WANT),
]


def check_columns(args, chk):
    """The column scenes of COLUMN_CASES; then store_every evaluated off its
    steps."""
    for name, compute, nprocs, processors, free, what, ok in COLUMN_CASES:
        got = run_column(args, chk, name, compute, nprocs=nprocs, processors=processors, free=free)
        if got is not None:
            chk.check(what, ok(got), got)
    # ... and on another step it stops with an error instead of reading an
    # empty contact list (the dump asks for it at step 1).
    expect_error(args, chk, "store_every 10 evaluated at step 1",
                 column_text(BASE + " store_every 10", FREE, os.path.join(args.work, "sev.dump"))
                 .replace("run 0", "run 3"), "evaluated at step 1, but the pair style stores "
                 "contact forces only on multiples of 10")


def check_max_iterations(args, chk):
    """prune iterate with max_iterations 1 on the dangling pair: pass 1
    makes A loose, a further pass finds nothing, so it converged (no
    warning) and the entry prune_passes counts the one pass; on 1 and 2
    ranks alike."""
    fields = [entry("loose_particles", args.source), entry("prune_passes", args.source)]
    for nprocs, proc in ((None, ""), (2, "1 1 2")):
        name = "dangling_max1_%s" % (nprocs or 1)
        text = column_text(ITERATE.replace("iterate", "iterate max_iterations 1"), DANGLING,
                           os.path.join(args.work, name + ".dump"), proc)
        text = re.sub(r"thermo_style custom .*", "thermo_style custom step " + " ".join(fields), text)
        res = su.run_launcher(args, su.write_file(os.path.join(args.work, "in." + name), text),
                              nprocs=nprocs)
        got = thermo_values(res.output, fields)
        chk.check("prune iterate, max_iterations 1, %d rank(s): converged (no "
                  "warning), 2 loose, 1 pass" % (nprocs or 1),
                  res.returncode == 0 and "did not converge" not in res.text
                  and got and got[fields[0]] == 2 and got[fields[1]] == 1,
                  res.describe())


# Bad input: each gives an ERROR naming the value or what is allowed.
# (what, the compute command, what its ERROR must contain)
BAD_COMPUTES = [
    ("min_contacts 0", BASE.replace("min_contacts 2", "min_contacts 0"), "at least 1"),
    ("negative threshold", BASE + " force_threshold absolute -1", "must not be negative"),
    ("negative relative threshold", BASE + " force_threshold relative -0.1", "must not be negative"),
    ("unknown threshold mode", BASE + " force_threshold mean 1", "absolute or relative"),
    ("unknown prune", BASE + " prune twice", "use once or iterate"),
    ("unknown keyword", BASE + " colour red", "unknown keyword 'colour'"),
    ("wall fix that does not exist", BASE + " walls wb nowall", "'nowall' does not exist"),
    ("wall fix that is not a granular wall", BASE + " walls wb nve", "not a granular wall"),
    ("intervals that do not match the specimen", BASE.replace("intervals 1", "intervals 3"),
     "1 distinct particle diameters but intervals 3"),
    ("a PSD that does not match the specimen",
     BASE.replace("intervals 1", "psd %s intervals 5" % os.path.join(su.DATA_DIR, "psd_ok_small.txt")),
     "fit no size interval"),
    ("intervals 0", BASE.replace("intervals 1", "intervals 0"), "1..100"),
    ("oz_tolerance 1", BASE + " oz_tolerance 1", "oz_tolerance 1 must lie in [0, 1)"),
    ("oz_tolerance not a number", BASE + " oz_tolerance tenth", "'tenth' is not a number"),
    ("store_every 0", BASE + " store_every 0", "store_every 0 must lie in 1..1000000000"),
    ("store_every not an integer", BASE + " store_every 2.5", "'2.5' is not an integer"),
    ("unknown weight", BASE + " weight density", "use mass or volume"),
]

PAIR = "pair_style gran model hooke/stiffness tangential history\npair_coeff * *\n"

# A wall without stored contacts, a non-granular style, no pair style:
# (what, the change to the good scene, what its ERROR must contain).
BAD_SCENES = [
    ("granular wall without store_force_contact_stress",
     lambda t: t.replace("zplane 0.0 store_force_contact_stress yes", "zplane 0.0"),
     "store_force_contact_stress yes"),
    ("non-granular atom style (checked before the pair style)",
     lambda t: t.replace("atom_style      granular", "atom_style      atomic")
                .replace("set atom * diameter 0.002 density 2650", "mass * 1")
                .replace(PAIR, "")
                .split("fix wb")[0] + "{compute}\n".format(compute=BASE) + "run 0\n",
     "requires atom_style granular"),
    ("no granular pair style before the compute",
     lambda t: t.replace(PAIR, "").replace("fix nve all nve/sphere", PAIR + "fix nve all nve/sphere"),
     "granular pair style"),
]


def check_bad_input(args, chk):
    dump = os.path.join(args.work, "bad.dump")
    for what, compute, expect in BAD_COMPUTES:
        expect_error(args, chk, what, column_text(compute, FREE, dump), expect)
    for what, change, expect in BAD_SCENES:
        expect_error(args, chk, what, change(column_text(BASE, FREE, dump)), expect)


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    check_columns(args, chk)
    check_outputs(args, chk)
    check_weight(args, chk)
    check_docs_quote_layout(args, chk)
    check_slices(args, chk)
    check_max_iterations(args, chk)
    check_bad_input(args, chk)
    chk.finish()


if __name__ == "__main__":
    main()
