"""The outputs of our styles, read from the one table each defines them in,
for every tool and test:

  compute primary/fabric  compute_primary_fabric/fabric_outputs.h
                          FABRIC_VECTOR_ENTRIES (global vector, entries
                          1..31, then two per direction bin) and
                          FABRIC_ARRAY_COLUMNS (global array, one row per
                          size interval)
  fix sequential/pack     fix_sequential_pack/pack_outputs.h
                          PACK_VECTOR_ENTRIES (global vector), then
                          PACK_PROFILE_ENTRIES per height layer
                          (kProfileLayers, specimen_measure.h)
  compute constriction/size
                          compute_constriction_size/constriction_outputs.h
                          CONSTRICTION_VECTOR_ENTRIES (global vector), then
                          with keyword slices S CONSTRICTION_SLICE_ENTRIES
                          per height slice
  fix pore/flow           fix_pore_flow/pore_flow_outputs.h
                          PORE_FLOW_VECTOR_ENTRIES (global vector)

Each table is one X(position, name, "meaning") per line, positions from 1
as c_ID[I] and f_ID[I] count them. Also here: the output files of
input_scripts/in.oedometer that hold these outputs (fabric_global.txt,
fabric_intervals.txt, rest.txt, the series), read by position and named by
the tables; LAMMPS text dumps (read_dump: dump custom and dump local,
columns by the names of their own column line), final_contacts.txt
(CONTACT_COLUMNS), compute constriction/size's csd file and local array,
the outlet's file of fix massflow/mesh, the lines of an input script
that print the fix's vector, LIGGGHTS' thermo output (read_thermo:
each column by the keyword of the thermo_style line that printed it), and
the files of bench/pore_flow_bench and bench/pore_flow_vs_yade/yade_flow.py
(spheres, cells, forces). No tool or test reads a column of these files by
its position anywhere else.

Standard library and numpy only; import it as `import outputs` with tools/
on sys.path (the scene tests get it from --source).
"""
import os
import re
from collections import namedtuple

import numpy as np

ROOT = os.path.abspath(os.path.join(os.path.dirname(os.path.abspath(__file__)), os.pardir))
FABRIC_HEADER = os.path.join("compute_primary_fabric", "fabric_outputs.h")
PACK_HEADER = os.path.join("fix_sequential_pack", "pack_outputs.h")
PACK_MEASURE_HEADER = os.path.join("fix_sequential_pack", "specimen_measure.h")
CONSTRICTION_HEADER = os.path.join("compute_constriction_size", "constriction_outputs.h")
REST_HEADER = os.path.join("fix_quasi_static", "rest_outputs.h")

Entry = namedtuple("Entry", "position name meaning")


def read_table(path, macro):
    """The entries of the X-macro table `macro` in the header `path`: a list
    of Entry(position, name, meaning), checked to be numbered 1..n."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    head = "#define %s(X)" % macro
    if head not in text:
        raise ValueError("%s: no table %s" % (path, macro))
    body = text.split(head, 1)[1].split("\n\n", 1)[0]
    entries = [Entry(int(p), n, m) for p, n, m in
               re.findall(r'X\((\d+), (\w+), "([^"]*)"\)', body)]
    if [e.position for e in entries] != list(range(1, len(entries) + 1)):
        raise ValueError("%s: %s is not numbered 1..n" % (path, macro))
    return entries


def fabric_vector(source=ROOT):
    """compute primary/fabric: the fixed entries of the global vector (the
    direction bins follow them)."""
    return read_table(os.path.join(source, FABRIC_HEADER), "FABRIC_VECTOR_ENTRIES")


def fabric_peratom(source=ROOT):
    """compute primary/fabric: the columns of the per-atom array."""
    return read_table(os.path.join(source, FABRIC_HEADER), "FABRIC_PERATOM_COLUMNS")


def peratom_name(name, compute_id="pf", source=ROOT):
    """The dump column of per-atom column `name` of compute primary/fabric
    `compute_id`, as LIGGGHTS names it: c_ID[I]."""
    pos = {e.name: e.position for e in fabric_peratom(source)}
    if name not in pos:
        raise ValueError("compute primary/fabric has no per-atom column %s (%s)"
                         % (name, ", ".join(pos)))
    return "c_%s[%d]" % (compute_id, pos[name])


# the dump column of the class (1 primary, 0 loose) of the scenes' compute pf
PRIMARY = peratom_name("primary")


def fabric_array(source=ROOT):
    """compute primary/fabric: the columns of the global array."""
    return read_table(os.path.join(source, FABRIC_HEADER), "FABRIC_ARRAY_COLUMNS")


def pack_profile_layers(source=ROOT):
    """fix sequential/pack: the layers of its profile by height,
    kProfileLayers of fix_sequential_pack/specimen_measure.h."""
    path = os.path.join(source, PACK_MEASURE_HEADER)
    with open(path, encoding="utf-8") as f:
        found = re.search(r"constexpr int kProfileLayers = (\d+);", f.read())
    if not found:
        raise ValueError("%s: no kProfileLayers" % path)
    return int(found.group(1))


def pack_vector(source=ROOT):
    """fix sequential/pack: the entries of the global vector: those of
    PACK_VECTOR_ENTRIES, then per quantity of PACK_PROFILE_ENTRIES one
    entry per height layer, floor first, named layer<L>_<name> (the
    header's layout)."""
    path = os.path.join(source, PACK_HEADER)
    entries = read_table(path, "PACK_VECTOR_ENTRIES")
    layers = pack_profile_layers(source)
    for q in read_table(path, "PACK_PROFILE_ENTRIES"):
        for layer in range(1, layers + 1):
            entries.append(Entry(len(entries) + 1, "layer%d_%s" % (layer, q.name),
                                 q.meaning.replace("{layer}", str(layer))
                                 .replace("{layers}", str(layers))))
    return entries


def constriction_vector(source=ROOT, slices=0):
    """compute constriction/size: the entries of the global vector; with
    keyword slices S (slices=S) then those of CONSTRICTION_SLICE_ENTRIES
    per height slice, the lowest first, named slice<s>_<name> without the
    table's 'slice_' (slice_control of slice 2: slice2_control)."""
    path = os.path.join(source, CONSTRICTION_HEADER)
    entries = read_table(path, "CONSTRICTION_VECTOR_ENTRIES")
    for s in range(1, slices + 1):
        for e in constriction_slice_entries(source):
            name = e.name[len("slice_"):] if e.name.startswith("slice_") else e.name
            entries.append(Entry(len(entries) + 1, "slice%d_%s" % (s, name), e.meaning))
    return entries


def constriction_slice_entries(source=ROOT):
    """compute constriction/size: the entries of one height slice (keyword
    slices), CONSTRICTION_SLICE_ENTRIES."""
    return read_table(os.path.join(source, CONSTRICTION_HEADER),
                      "CONSTRICTION_SLICE_ENTRIES")


def constriction_slices(vector, source=ROOT):
    """The height slices of compute constriction/size in a whole global
    vector (entry I at index I-1): a list of {name of
    CONSTRICTION_SLICE_ENTRIES: value}, the lowest slice first; their
    number follows from the length ([] without slices). ValueError if the
    length is not the fixed entries and a whole number of slices."""
    fixed = len(constriction_vector(source))
    entries = constriction_slice_entries(source)
    k = len(entries)
    rest = len(vector) - fixed
    if rest < 0 or rest % k:
        raise ValueError("a vector of %d entries is not compute constriction/size's "
                         "%d and %d per slice" % (len(vector), fixed, k))
    return [{e.name: float(vector[fixed + s * k + e.position - 1]) for e in entries}
            for s in range(rest // k)]


def index(entries):
    """{name: 0-based position}."""
    return {e.name: e.position - 1 for e in entries}


def fabric_vector_size(direction_bins, source=ROOT):
    """Length of the compute's global vector with M direction bins: the
    fixed entries, then (fraction, mean normal force) per bin."""
    return len(fabric_vector(source)) + 2 * direction_bins


def direction_bins(vector, source=ROOT):
    """(fraction, mean normal force) arrays of the direction bins of a whole
    global vector (their number follows from its length)."""
    fixed = len(fabric_vector(source))
    m = (len(vector) - fixed) // 2
    bins = np.asarray(vector[fixed:fixed + 2 * m], float).reshape(m, 2)
    return bins[:, 0], bins[:, 1]


# ---- the scenes' output files ---------------------------------------------

def data_rows(path):
    """The rows of numbers of a fix ave/time file (comments skipped)."""
    with open(path) as f:
        return [l.split() for l in f if l.strip() and not l.lstrip().startswith("#")]


def vector_blocks(path):
    """A fix ave/time file in mode vector: [(step, rows as lists of floats)],
    an incomplete last block (a run still writing) dropped."""
    lines = data_rows(path)
    blocks, i = [], 0
    while i < len(lines):
        w = lines[i]
        if len(w) != 2:
            raise ValueError("%s: expected a block header 'step nrows', got '%s'"
                             % (path, " ".join(w)))
        step, nrows = int(float(w[0])), int(float(w[1]))
        rows = lines[i + 1:i + 1 + nrows]
        if len(rows) < nrows:
            break
        blocks.append((step, [[float(x) for x in r] for r in rows]))
        i += 1 + nrows
    return blocks


def read_intervals(path, source=ROOT):
    """The last block of fabric_intervals.txt (the compute's global array,
    one row per interval, after the row number) as {column name: array},
    names from fabric_outputs.h, plus 'step' and 'nblocks'; None without a
    complete block."""
    blocks = vector_blocks(path)
    if not blocks:
        return None
    step, rows = blocks[-1]
    cols = fabric_array(source)
    if not rows or min(len(r) for r in rows) < 1 + len(cols):
        raise ValueError("%s: the last block (step %d) does not have the row "
                         "number and the %d columns of the compute's array"
                         % (path, step, len(cols)))
    arr = np.array([r[:1 + len(cols)] for r in rows])
    out = {e.name: arr[:, e.position] for e in cols}
    out["step"], out["nblocks"] = step, len(blocks)
    return out


def read_global(path, source=ROOT):
    """The last global vector of compute primary/fabric in fabric_global.txt
    (fix ave/time in scalar mode: rows 'step v1 v2 ...'), as a numpy array
    (entry I at index I-1); None if the file is missing, holds no row, or
    holds something shorter than the fixed entries."""
    if not os.path.exists(path):
        return None
    rows = data_rows(path)
    if not rows or len(rows[-1]) < 1 + len(fabric_vector(source)):
        return None
    return np.array([float(v) for v in rows[-1][1:]])


# ---- fix sequential/pack's vector in an input script -----------------------

def pack_vector_print(fix_id, source=ROOT):
    """Input lines that print the fix's global vector as one line,
    'PACK_VECTOR v1 v2 ...' (read back by pack_vector_values)."""
    n = len(pack_vector(source))
    text = "".join("variable        pv%d equal f_%s[%d]\n" % (i, fix_id, i)
                   for i in range(1, n + 1))
    return text + ('print           "PACK_VECTOR %s"\n'
                   % " ".join("${pv%d}" % i for i in range(1, n + 1)))


def pack_vector_values(text, source=ROOT):
    """The fix's global vector as printed by pack_vector_print(): a dict by
    name (the last such line of `text`), or None."""
    found = re.findall(r"^PACK_VECTOR (.*)$", text, re.M)
    if not found:
        return None
    names = [e.name for e in pack_vector(source)]
    return dict(zip(names, (float(v) for v in found[-1].split())))


# ---- LAMMPS text dumps (dump custom, dump local) ----------------------------

class Snapshot:
    """One snapshot of a LAMMPS text dump: `timestep`, `natoms` (the atoms
    of a dump custom, the entries of a dump local), `box` [(lo, hi)] * 3,
    `columns` (the names of its ITEM: ATOMS or ITEM: ENTRIES line, e.g.
    'id', 'radius', 'c_pf[2]') and `rows` (each row's tokens as printed).
    Read a column by its name: snap["radius"] or snap.col("id", int)."""

    def __init__(self, timestep, natoms, box, columns, rows):
        self.timestep = timestep
        self.natoms = natoms
        self.box = box
        self.columns = columns
        self.rows = rows

    def index(self, name):
        """The 0-based position of column `name`; ValueError naming the
        columns the dump has if it has no such column."""
        if name not in self.columns:
            raise ValueError("the dump has no column %s (it has %s)"
                             % (name, " ".join(self.columns)))
        return self.columns.index(name)

    def col(self, name, dtype=float):
        """Column `name` as a numpy array (dtype float, or a function of
        the printed token such as int)."""
        k = self.index(name)
        if dtype is float:
            return np.array([r[k] for r in self.rows], dtype=float)
        return np.array([dtype(r[k]) for r in self.rows])

    def __getitem__(self, name):
        return self.col(name)

    def __contains__(self, name):
        return name in self.columns

    def keys(self):
        return list(self.columns)

    def by_id(self):
        """{id: row tokens}."""
        k = self.index("id")
        return {int(r[k]): r for r in self.rows}

    def as_dict(self):
        """{column name: numpy array of floats}."""
        data = np.array(self.rows, dtype=float).reshape(len(self.rows), len(self.columns))
        return {name: data[:, j] for j, name in enumerate(self.columns)}


def read_dump(path):
    """All snapshots of a LAMMPS text dump (dump custom: ITEM: ATOMS, or
    dump local: ITEM: ENTRIES), in order, as Snapshot objects whose columns
    are looked up by the names of the dump's own column line. An incomplete
    last snapshot (a run still writing) is dropped; ValueError on anything
    else that is not a dump snapshot."""
    with open(path) as f:
        lines = f.read().splitlines()
    snaps, i = [], 0
    while i < len(lines):
        if not lines[i].startswith("ITEM: TIMESTEP"):
            i += 1
            continue
        head = lines[i:i + 9]
        if len(head) < 9:
            break
        if not (head[2].startswith("ITEM: NUMBER OF ")
                and head[4].startswith("ITEM: BOX BOUNDS")
                and (head[8].startswith("ITEM: ATOMS") or head[8].startswith("ITEM: ENTRIES"))):
            raise ValueError("%s: line %d: not the header of a dump snapshot "
                             "(TIMESTEP, NUMBER OF ATOMS/ENTRIES, BOX BOUNDS, "
                             "ATOMS/ENTRIES)" % (path, i + 1))
        n = int(head[3])
        box = [tuple(float(v) for v in head[5 + a].split()[:2]) for a in range(3)]
        columns = head[8].split()[2:]
        rows = [l.split() for l in lines[i + 9:i + 9 + n]]
        if len(rows) < n or any(len(r) != len(columns) for r in rows):
            if i + 9 + n >= len(lines):
                break       # the last snapshot, cut short
            raise ValueError("%s: the snapshot of step %s has rows that do not "
                             "hold its %d columns" % (path, head[1], len(columns)))
        snaps.append(Snapshot(int(head[1]), n, box, columns, rows))
        i += 9 + n
    return snaps


def last_snapshot(path):
    """The last complete snapshot of a text dump (read_dump); ValueError
    if it holds none."""
    snaps = read_dump(path)
    if not snaps:
        raise ValueError("%s: no complete dump snapshot" % path)
    return snaps[-1]


def dump_last(path):
    """The last snapshot of a LAMMPS text dump (dump custom, e.g. the scene's
    final.dump) as {column name: numpy array}, by the names of its ITEM:
    ATOMS line."""
    return last_snapshot(path).as_dict()


def vtk_component(array_name, column):
    """The component of a VTK point array of dump custom/vtk that holds dump
    column `column`: the dump writes the columns c_ID[1] .. c_ID[n] as one
    array 'c_ID[1-n]' of n components, so vtk_component('c_pf[1-3]',
    'c_pf[2]') is 1; a one-column array named `column` is component 0;
    None if the array does not hold the column."""
    if array_name == column:
        return 0
    m = re.match(r"^(\w+)\[(\d+)-(\d+)\]$", array_name)
    c = re.match(r"^(\w+)\[(\d+)\]$", column)
    if not m or not c or m.group(1) != c.group(1):
        return None
    lo, hi, k = int(m.group(2)), int(m.group(3)), int(c.group(2))
    return k - lo if lo <= k <= hi else None


# final_contacts.txt of in.oedometer (input_scripts/oedometer/finish.in):
# dump local of compute pair/gran/local `pos id force` (id cpgl), columns
# c_cpgl[1..12] in LIGGGHTS' order: the two centres, the two ids, the
# periodic flag (1: the pair crosses a periodic face), the force on the first.
CONTACT_COLUMNS = ("x1", "y1", "z1", "x2", "y2", "z2", "id1", "id2", "periodic",
                   "fx", "fy", "fz")


def read_contacts(path, compute_id="cpgl"):
    """The last snapshot of final_contacts.txt as {name of CONTACT_COLUMNS:
    numpy array}; ValueError if its columns are not c_ID[1..12]."""
    snap = last_snapshot(path)
    want = ["c_%s[%d]" % (compute_id, k) for k in range(1, len(CONTACT_COLUMNS) + 1)]
    if snap.columns != want:
        raise ValueError("%s: columns %s, expected %s (tools/outputs.py)"
                         % (path, " ".join(snap.columns), " ".join(want)))
    return {name: snap.col(column) for name, column in zip(CONTACT_COLUMNS, want)}


def primary_volume_percent(snapshot):
    """The primary fabric's share of the grains' volume, % (c_pf[2] 1:
    primary), from a dump_last snapshot with radius and c_pf[2]: the share
    by mass of grains of one material whatever their masses were scaled to."""
    v = snapshot["radius"] ** 3
    return 100.0 * v[snapshot[PRIMARY] == 1].sum() / v.sum()


def material_mass(snapshot):
    """Each grain's mass as its material has it, from a snapshot with radius
    and mass: its volume times the density of the coarsest grain. The
    scene's grains are of one material, and its `dt_gain` makes the finest
    ones denser to lengthen the time step (the coarsest keep their mass), so
    the dumped masses are the integrator's, not the soil's."""
    r, m = snapshot["radius"], snapshot["mass"]
    k = int(np.argmax(r))
    return m[k] * (r / r[k]) ** 3


# ---- the oedometer scene's time series ---------------------------------------

# fabric_series.txt, one row per block of in.oedometer: (the word of the
# file's column line, the name the tools use). The scene's title2 must
# name exactly these columns (tests/scene/test_oedometer.py checks it).
SERIES_COLUMNS = (
    ("step", "step"),
    ("KE_translation(J)", "ke_translation"),
    ("sigma_lid_block_mean(Pa)", "lid_stress"),
    ("stress_error_block_rms", "stress_error_rms"),
    ("loose%number", "loose_number_pct"),
    ("primary%mass", "primary_mass_pct"),
    ("coordination", "coordination"),
    ("OZ%mass", "oz_mass_pct"),
    ("unbalanced_force_ratio", "unbalanced_force_ratio"),
)


# hold_series.txt (in.oedometer -var hold N): one row every relax_every
# steps of the hold, the first the stress at rest.
HOLD_SERIES_COLUMNS = (
    ("step", "step"),
    ("t_hold(s)", "t_hold"),
    ("sigma_lid(Pa)", "lid_stress"),
    ("KE_translation(J)", "ke_translation"),
    ("primary%mass", "primary_mass_pct"),
    ("unbalanced_force_ratio", "unbalanced_force_ratio"),
)


def series_header(path):
    """The column words of a series file's '# step ...' line, or None."""
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                break
            words = line[1:].split()
            if words and words[0] == "step":
                return words
    return None


def read_series(path, columns=SERIES_COLUMNS):
    """fabric_series.txt (or, with columns=HOLD_SERIES_COLUMNS,
    hold_series.txt) as {name: numpy array}, names of the table (the first
    row of fabric_series.txt is before loading: the packer's geometric
    contacts). ValueError if the file's column line is not the table's or
    it holds no row."""
    words = series_header(path)
    want = [w for w, _ in columns]
    if words != want:
        raise ValueError("%s: columns %s, expected %s (tools/outputs.py)"
                         % (path, words, want))
    rows = [[float(x) for x in r] for r in data_rows(path)]
    if not rows or min(len(r) for r in rows) != len(want):
        raise ValueError("%s: no rows of %d numbers" % (path, len(want)))
    a = np.array(rows)
    return {name: a[:, i] for i, (_, name) in enumerate(columns)}


# ---- fix servo/rest ---------------------------------------------------------

REST_PHASES = ("loading", "relaxing", "at rest", "maximum loading time",
               "maximum relaxation")


def rest_vector(source=ROOT):
    """fix servo/rest: the entries of the global vector."""
    return read_table(os.path.join(source, REST_HEADER), "SERVO_REST_VECTOR_ENTRIES")


def read_rest(path, source=ROOT):
    """The protocol's result, rest.txt (fix servo/rest's vector written by
    fix ave/time in mode vector when the loading ends), as {entry name:
    value} with names from rest_outputs.h, plus 'step' and 'phase_name';
    None if the file is missing or holds no complete block."""
    if not os.path.exists(path):
        return None
    blocks = vector_blocks(path)
    if not blocks:
        return None
    step, rows = blocks[-1]
    entries = rest_vector(source)
    if len(rows) != len(entries):
        raise ValueError("%s: %d rows, fix servo/rest has %d entries"
                         % (path, len(rows), len(entries)))
    out = {e.name: rows[e.position - 1][1] for e in entries}
    out["step"] = step
    out["phase_name"] = REST_PHASES[int(out["phase"])]
    return out


# ---- compute constriction/size's files ------------------------------------

# the columns of the local array (compute_constriction_size.cpp, fill_local;
# docs/compute_constriction_size.md): one row per constriction
CONSTRICTION_LOCAL_COLUMNS = ("x", "y", "z", "nx", "ny", "nz", "radius")


def constriction_local_name(name, compute_id):
    """The dump local column of local-array column `name` of compute
    constriction/size `compute_id`: c_ID[I]."""
    if name not in CONSTRICTION_LOCAL_COLUMNS:
        raise ValueError("compute constriction/size has no local column %s (%s)"
                         % (name, ", ".join(CONSTRICTION_LOCAL_COLUMNS)))
    return "c_%s[%d]" % (compute_id, CONSTRICTION_LOCAL_COLUMNS.index(name) + 1)


# the file of its keyword csd (write_csd): the cumulative CSD, one row per
# constriction, under the column line '# diameter percent_finer_by_number
# percent_finer_by_diameter_cubed'
CSD_COLUMNS = ("diameter", "percent_finer_by_number", "percent_finer_by_diameter_cubed")


def read_csd(path):
    """A csd file of compute constriction/size as {name of CSD_COLUMNS:
    numpy array} (empty arrays without constrictions); ValueError if its
    column line is not the table's."""
    with open(path) as f:
        lines = f.read().splitlines()
    heads = [l[1:].split() for l in lines if l.startswith("#")]
    if list(CSD_COLUMNS) not in heads:
        raise ValueError("%s: no column line '# %s' (tools/outputs.py)"
                         % (path, " ".join(CSD_COLUMNS)))
    rows = [[float(v) for v in l.split()] for l in lines
            if l.strip() and not l.startswith("#")]
    if any(len(r) != len(CSD_COLUMNS) for r in rows):
        raise ValueError("%s: rows that are not %d numbers" % (path, len(CSD_COLUMNS)))
    a = np.array(rows, dtype=float).reshape(len(rows), len(CSD_COLUMNS))
    return {name: a[:, j] for j, name in enumerate(CSD_COLUMNS)}


# ---- the suffusion test's outlet (examples/in.outlet) ----------------------

# the columns of fix massflow/mesh's file (examples/in.outlet), as its
# column line '# ID diameter x y z u v w ...' names them
OUTLET_COLUMNS = ("id", "diameter", "x", "y", "z", "u", "v", "w")


def read_outlet(path):
    """The grains fix massflow/mesh wrote as they left through the outlet
    (its `file` keyword: PATH on one rank, PATH.N on N ranks; columns
    OUTLET_COLUMNS), as {"id": array, "diameter": array} sorted by ID;
    empty arrays if no grain left."""
    import glob
    files = [path] if os.path.exists(path) else sorted(glob.glob(path + ".*"))
    k_id, k_d = OUTLET_COLUMNS.index("id"), OUTLET_COLUMNS.index("diameter")
    rows = []
    for f in files:
        rows += [r for r in data_rows(f) if len(r) > k_d]
    rows.sort(key=lambda r: int(r[k_id]))
    return {"id": np.array([int(r[k_id]) for r in rows], dtype=int),
            "diameter": np.array([float(r[k_d]) for r in rows])}


# ---- fix pore/flow ----------------------------------------------------------

PORE_FLOW_HEADER = os.path.join("fix_pore_flow", "pore_flow_outputs.h")


def pore_flow_vector(source=ROOT):
    """fix pore/flow: the entries of the global vector."""
    return read_table(os.path.join(source, PORE_FLOW_HEADER),
                      "PORE_FLOW_VECTOR_ENTRIES")


# ---- the seepage test (input_scripts/oedometer/seepage.in) -----------------

# suffusion.txt: one row per stage of the scene's seepage test, these
# columns (the file's column line names them; read_suffusion checks it).
SUFFUSION_COLUMNS = (
    ("gradient", "gradient"),
    ("pressure_drop(Pa)", "pressure_drop"),
    ("steps", "steps"),
    ("eroded_pct_of_specimen", "eroded_pct"),
    ("eroded_pct_of_loose", "eroded_loose_pct"),
    ("stage_eroded_pct", "stage_eroded_pct"),
    ("grains_eroded", "grains_eroded"),
    ("primary_pct_by_mass", "primary_pct"),
    ("porosity", "porosity"),
    ("lid_stress(Pa)", "lid_stress"),
    ("permeability(m2)", "permeability"),
)


def read_suffusion(path):
    """A run's suffusion.txt as {name: numpy array} (names of
    SUFFUSION_COLUMNS, one entry per stage, in the order run) plus
    'gradient_text': the gradients as the scene wrote them (the stage's
    eroded_i<gradient>.txt). ValueError if the column line is not the
    table's."""
    words = None
    with open(path) as f:
        for line in f:
            if line.startswith("#") and line[1:].split()[:1] == ["gradient"]:
                words = line[1:].split()
    want = [w for w, _ in SUFFUSION_COLUMNS]
    if words != want:
        raise ValueError("%s: columns %s, expected %s (tools/outputs.py)" % (path, words, want))
    rows = data_rows(path)
    if any(len(r) != len(want) for r in rows):
        raise ValueError("%s: a row without the %d columns" % (path, len(want)))
    out = {name: np.array([float(r[i]) for r in rows]) for i, (_, name) in enumerate(SUFFUSION_COLUMNS)}
    out["gradient_text"] = [r[0] for r in rows]
    return out


def eroded_file(run, gradient_text):
    """The outlet file of one stage of the seepage test."""
    return os.path.join(run, "eroded_i%s.txt" % gradient_text)


# ---- LIGGGHTS thermo output (the screen or the log) ------------------------

# The header words LIGGGHTS prints for the thermo_style keywords that are not
# a compute, fix or variable (LAMMPS' thermo.cpp); any other keyword prints
# as itself.
THERMO_BUILTIN_WORDS = {
    "step": "Step", "elapsed": "Elapsed", "elaplong": "Elaplong", "dt": "Dt",
    "time": "Time", "cpu": "CPU", "tpcpu": "T/CPU", "spcpu": "S/CPU",
    "cpuremain": "CPULeft", "part": "Part", "atoms": "Atoms", "temp": "Temp",
    "press": "Press", "pe": "PotEng", "ke": "KinEng", "etotal": "TotEng",
    "enthalpy": "Enthalpy", "evdwl": "E_vdwl", "ecoul": "E_coul",
    "epair": "E_pair", "ebond": "E_bond", "eangle": "E_angle",
    "edihed": "E_dihed", "eimp": "E_impro", "emol": "E_mol", "elong": "E_long",
    "etail": "E_tail", "vol": "Volume", "density": "Density",
}
# LIGGGHTS cuts every header word to this many characters
THERMO_WORD_CHARS = 8


def thermo_keywords(columns):
    """The keywords of a thermo_style custom command: `columns` is the
    script's line ('thermo_style custom step atoms f_flow[1] ...'), the
    keywords as one string ('step atoms f_flow[1]') or a list of them.
    ValueError unless it is a custom style whose first keyword is step."""
    words = columns.split("#", 1)[0].split() if isinstance(columns, str) else list(columns)
    if words[:1] == ["thermo_style"]:
        if words[1:2] != ["custom"]:
            raise ValueError("thermo_style %s: only a custom style lists its keywords"
                             % " ".join(words[1:2]))
        words = words[2:]
    if words[:1] != ["step"]:
        raise ValueError("thermo keywords %s: the first must be step (the header line "
                         "starts with Step)" % words)
    return words


def thermo_word(keyword):
    """The header word LIGGGHTS prints for a thermo_style keyword: c_ID[I],
    f_ID[I] and v_NAME without their prefix, the others by their LAMMPS
    names (ke: KinEng), all cut to THERMO_WORD_CHARS characters
    ('f_seep_now[1]': 'seep_now', 'v_sigma_lid': 'sigma_li')."""
    if keyword[:2] in ("c_", "f_", "v_"):
        word = keyword[2:]
    else:
        word = THERMO_BUILTIN_WORDS.get(keyword, keyword)
    return word[:THERMO_WORD_CHARS]


def _thermo_numbers(words, n):
    """The floats of a thermo row of n columns (the step an integer), or
    None. nan and inf are numbers here: a test of finiteness needs them."""
    if len(words) != n or not re.match(r"^\d+$", words[0]):
        return None
    try:
        return [float(w) for w in words]
    except ValueError:
        return None


def read_thermo(text, columns, runs=False):
    """The thermo rows of a LIGGGHTS screen output or log `text` printed
    by the thermo_style custom of `columns` (thermo_keywords: the script's
    line or its keywords), each a dict {keyword: float}, e.g.
    row["f_flow[3]"], row["c_pf[4]"], row["step"]: every run's block in
    order (runs=True: a list per block).

    The names are the script's keywords, not the header's words: LIGGGHTS
    prints c_ID[I], f_ID[I] and v_NAME without the prefix and cut to 8
    characters, so 'f_seep_now[1]' and 'f_seep_now[2]' both print as
    'seep_now', 'v_sigma_lid' as 'sigma_li' and 'c_pf[4]' as 'pf[4]',
    whatever thermo_modify format says; a header word cannot name a column,
    the keyword the script gave can, and it is what a test and the pages
    write. The header serves to find the blocks: a block is a line whose
    words are those the keywords print as (thermo_word), in order; so the
    rows of another thermo_style (other keywords, or as many others) are
    never read under these names. Its rows are the lines of as many numbers
    (the first an integer step) up to 'Loop time', the next header or an
    ERROR; lines between (a WARNING) are skipped, and a run cut short keeps
    the rows it printed. thermo_modify line one only (the default)."""
    keys = thermo_keywords(columns)
    head = [thermo_word(k).lower() for k in keys]
    blocks, rows = [], None
    for line in text.splitlines():
        words = line.split()
        if words[:1] == ["Step"]:
            rows = [] if [w.lower() for w in words] == head else None
            if rows is not None:
                blocks.append(rows)
        elif rows is not None:
            if line.startswith("Loop time") or line.startswith("ERROR"):
                rows = None
                continue
            numbers = _thermo_numbers(words, len(keys))
            if numbers is not None:
                rows.append(dict(zip(keys, numbers)))
    return blocks if runs else [r for b in blocks for r in b]


def thermo_row(text, columns, step):
    """The first row of read_thermo(text, columns) at `step` (the first run
    that prints it), or None."""
    for row in read_thermo(text, columns):
        if row["step"] == step:
            return row
    return None


# ---- the files of bench/pore_flow_bench (bench/pore_flow_bench.cpp) --------

# These are a project program's outputs without a column line, so their
# layouts are named here, from the program's writer: `export` writes a
# spheres file (read back by `solve`, by bench/pore_flow_vs_yade/yade_flow.py
# and written by tests/scene/test_pore_flow.py): the box on its first line,
# then one sphere per line.
BENCH_BOX_COLUMNS = ("xlo", "ylo", "zlo", "xhi", "yhi", "zhi")
BENCH_SPHERE_COLUMNS = ("x", "y", "z", "radius")
# `solve` writes CELLS, one row per cell of the triangulation in its order:
# the centre, the pressure, the pore's kind (core/pore_flow.h PoreKind, as
# an integer: BENCH_PORE_KINDS) and the pore's first cell (the row's own
# index unless the cell was merged into another's pore) ...
BENCH_CELL_COLUMNS = ("x", "y", "z", "pressure", "kind", "pore")
BENCH_PORE_KINDS = ("unknown", "inflow", "outflow", "solid")
# ... and FORCES, the fluid force on each sphere, in the spheres file's order.
BENCH_FORCE_COLUMNS = ("fx", "fy", "fz")
# yade_flow.py writes FlowEngine's cells as the centre and the pressure.
YADE_CELL_COLUMNS = BENCH_CELL_COLUMNS[:4]


def _number_rows(path, width):
    """The rows of a file of numbers as an array of `width` columns;
    ValueError naming the row that has another count."""
    rows = data_rows(path)
    for k, r in enumerate(rows):
        if len(r) != width:
            raise ValueError("%s: row %d holds %d numbers, the layout %d (tools/outputs.py)"
                             % (path, k + 1, len(r), width))
    return np.array(rows, dtype=float).reshape(len(rows), width)


def read_bench_table(path, columns):
    """A file of pore_flow_bench (or yade_flow.py) of the layout `columns`
    (BENCH_CELL_COLUMNS, YADE_CELL_COLUMNS, BENCH_FORCE_COLUMNS) as {name:
    numpy array}. The files have no column line, so the layout is checked
    by its width: ValueError on a row of another count."""
    a = _number_rows(path, len(columns))
    return {name: a[:, j] for j, name in enumerate(columns)}


def read_bench_spheres(path):
    """A spheres file of pore_flow_bench: ({name of BENCH_BOX_COLUMNS: float},
    {name of BENCH_SPHERE_COLUMNS: numpy array})."""
    with open(path) as f:
        lines = [l for l in f.read().splitlines() if l.strip()]
    box = lines[0].split() if lines else []
    if len(box) != len(BENCH_BOX_COLUMNS):
        raise ValueError("%s: the first line is not the box (%s)"
                         % (path, " ".join(BENCH_BOX_COLUMNS)))
    rows = [l.split() for l in lines[1:]]
    if any(len(r) != len(BENCH_SPHERE_COLUMNS) for r in rows):
        raise ValueError("%s: a sphere row that is not %s"
                         % (path, " ".join(BENCH_SPHERE_COLUMNS)))
    a = np.array(rows, dtype=float).reshape(len(rows), len(BENCH_SPHERE_COLUMNS))
    return (dict(zip(BENCH_BOX_COLUMNS, (float(v) for v in box))),
            {name: a[:, j] for j, name in enumerate(BENCH_SPHERE_COLUMNS)})
