#!/usr/bin/python3
"""Scene test: fix sequential/pack builds the same specimen on 1, 2 and 4
MPI ranks, for both arrangements.

The fix runs the packer on every rank and each rank creates the spheres in
its subdomain, with IDs in placement order, so the dumps (sorted by ID,
printed with %.17g) must agree exactly: same atom count, same IDs, same
positions, radii and interval indices (f_ID) per ID. The 2-rank runs use
`processors 2 1 1`, so the cut at x = L/2 goes through the specimen: both
ranks must own atoms. On one rank the test also checks the specimen itself:
every placed particle is an atom, the spheres lie in the container and do
not overlap, f_ID is the interval index 1..20 (one radius per interval,
radii growing with the index), and the fix's contacts before loading
(entries 7-9: % of grains with fewer than 3 contacts, contacts per grain,
% of the mass with 3 or more) equal an independent count from the dump
(grains touching within 1e-9 of the smaller radius, walls within 1e-9 of
the radius).

Specimen: PSD input_scripts/psd/cu2.5.txt (coarsest interval 1.6 mm),
porosity 0.40, a cube of 3.2 * 1.75 mm: about 4,500 particles.
"""

import os

import numpy as np

import scene_util as su

RANKS = (1, 2, 4)
ARRANGEMENTS = ("discrete", "layerwise")
INTERVALS = 20            # the fix's default
EDGE = 5.6e-3            # container edge (m): 3.5 coarsest diameters d_N of Cu 2.5
FIX = "pack"


def pack(args, root, psd, arrangement, n):
    """Packs the specimen on `n` ranks: (the run, its dump's path)."""
    d = su.fresh_dir(os.path.join(root, "%s_np%d" % (arrangement, n)))
    dump = os.path.join(d, "specimen.dump")
    inp = su.write_file(os.path.join(d, "in.pack"), su.pack_scene(
        psd, EDGE, porosity=0.40, arrangement=arrangement, seed=7,
        fix_id=FIX, extra_fix="verbose no",
        processors="2 1 1" if n == 2 else None, dump=dump))
    return su.run_launcher(args, inp, nprocs=n), dump


def check_vector(chk, arrangement, n, snap, listed, vec):
    """The fix's global vector (what scripts read) says the same as the
    dump: placed = atoms, porosity = 1 - sphere volume / V; `listed` the
    particles in the list as the fix's summary says (None: no summary)."""
    r = snap.col("radius")
    porosity = 1.0 - (4.0 / 3.0 * np.pi * r ** 3).sum() / EDGE ** 3
    chk.check("%s on %d rank(s): f_%s[1..3] = placed %s, listed %s, "
              "porosity %s (dump: %d atoms, porosity %.6f; summary "
              "lists %s)" % (arrangement, n, FIX,
                             vec and vec["placed"], vec and vec["listed"],
                             vec and vec["porosity"], snap.natoms,
                             porosity, listed),
              vec is not None and vec["placed"] == snap.natoms
              and listed is not None and vec["listed"] == listed
              and abs(vec["porosity"] - porosity) < 1e-9
              and 0.0 < vec["interior_porosity"] < 1.0
              and 0.0 < vec["wall_layer_porosity"] < 1.0
              and vec["seconds"] > 0.0)


def check_split(chk, arrangement, n, snap, text):
    """On more than one rank every rank owns atoms; on 2 ranks the cut at
    x = L/2 goes through the specimen."""
    nl = su.nlocal_stats(text)
    if n > 1:
        ave, _, least = nl if nl else (None, None, None)
        chk.check("%s on %d ranks: every rank owns atoms (Nlocal "
                  "ave/max/min %s)" % (arrangement, n, nl),
                  nl is not None and least > 0   # ave is %g:
                  and abs(ave * n - snap.natoms) <= n * max(
                      0.5, 1e-5 * snap.natoms))
    if n == 2:
        x = snap.col("x")
        left = int((x < EDGE / 2).sum())
        chk.check("%s on 2 ranks (processors 2 1 1): the specimen "
                  "spans both halves (%d atoms at x < L/2, %d at "
                  "x >= L/2)" % (arrangement, left, len(x) - left),
                  0 < left < len(x))


def run_on_ranks(args, chk, root, psd, arrangement, n):
    """The specimen packed on `n` ranks and its checks: (snapshot, the
    fix's vector), or None if the run failed."""
    res, dump = pack(args, root, psd, arrangement, n)
    ok = chk.check("%s on %d rank(s): runs to the end (%.1f s)"
                   % (arrangement, n, res.seconds),
                   res.returncode == 0 and not res.errors()
                   and os.path.isfile(dump), res.describe())
    if not ok:
        return None
    snap = su.last_snapshot(dump)
    summary = su.pack_summary(res.text)
    listed, placed, _ = summary if summary else (None, None, None)
    chk.check("%s on %d rank(s): every placed particle is an atom "
              "(summary %s, dump %d atoms)"
              % (arrangement, n, summary, snap.natoms),
              summary is not None and placed == snap.natoms
              and len(snap.rows) == snap.natoms)
    vec = su.pack_vector(res.text)
    check_vector(chk, arrangement, n, snap, listed, vec)
    check_split(chk, arrangement, n, snap, res.text)
    return snap, vec


def compare_ranks(chk, arrangement, snaps, col):
    """The specimens on 2 and 4 ranks against the one on 1: atom count, IDs
    and per ID the same values."""
    ref = snaps[1]
    ref_ids = ref.by_id()
    for n in RANKS[1:]:
        if n not in snaps:
            continue
        other = snaps[n]
        chk.check("%s: %d ranks give the same atom count as 1 (%d vs %d)"
                  % (arrangement, n, other.natoms, ref.natoms),
                  other.natoms == ref.natoms)
        ids = other.by_id()
        chk.check("%s: %d ranks give the same IDs as 1"
                  % (arrangement, n), set(ids) == set(ref_ids),
                  "only on 1 rank: %s; only on %d: %s" % (
                      sorted(set(ref_ids) - set(ids))[:10], n,
                      sorted(set(ids) - set(ref_ids))[:10]))
        compare_per_id(chk, arrangement, n, ref, other, col)


def main():
    args = su.parse_args(__doc__)
    chk = su.Checker()
    psd = os.path.join(args.source, "input_scripts", "psd", "cu2.5.txt")
    root = su.fresh_dir(os.path.join(args.work, "mpi_same_specimen"))
    col = "f_" + FIX
    specimens = {}
    for arrangement in ARRANGEMENTS:
        runs = {n: run_on_ranks(args, chk, root, psd, arrangement, n) for n in RANKS}
        snaps = {n: got[0] for n, got in runs.items() if got is not None}
        if 1 not in snaps:
            continue
        specimens[arrangement] = snaps[1]
        check_specimen(chk, arrangement, snaps[1], col, runs[1][1])
        compare_ranks(chk, arrangement, snaps, col)

    if len(specimens) == 2:
        a, b = (specimens[k] for k in ARRANGEMENTS)
        same = (a.natoms == b.natoms and
                np.array_equal(a.col("x"), b.col("x")))
        chk.check("discrete and layerwise give different specimens",
                  not same)
    chk.finish()


def compare_per_id(chk, arrangement, n, ref, other, col):
    """Positions, radii and f_ID per ID: equal to the last bit (%.17g)."""
    a, b = ref.by_id(), other.by_id()
    common = sorted(set(a) & set(b))
    for name in ("x", "y", "z", "radius", col):
        ka, kb = ref.columns.index(name), other.columns.index(name)
        va = np.array([float(a[i][ka]) for i in common])
        vb = np.array([float(b[i][kb]) for i in common])
        bad = np.nonzero(va != vb)[0]
        detail = ""
        if len(bad):
            j = bad[0]
            detail = ("%d of %d differ; first: id %d: %r on 1 rank, %r on "
                      "%d" % (len(bad), len(common), common[j],
                              a[common[j]][ka], b[common[j]][kb], n))
        chk.check("%s: %-6s per ID on %d ranks equals 1 rank exactly"
                  % (arrangement, name, n), len(common) > 0 and not len(bad),
                  detail)


def contact_counts(x, r, edge, block=512):
    """Contacts per sphere: pairs with gap < 1e-9 of the smaller radius, and
    the six faces of the cube [0, edge]^3 within 1e-9 of the radius."""
    n = len(r)
    counts = np.zeros(n, int)
    for s in range(0, n, block):
        e = min(s + block, n)
        d = np.sqrt(((x[s:e, None, :] - x[None, :, :]) ** 2).sum(-1))
        gap = d - r[s:e, None] - r[None, :]
        touch = gap < 1e-9 * np.minimum(r[s:e, None], r[None, :])
        touch[np.arange(e - s), np.arange(s, e)] = False
        counts[s:e] += touch.sum(1)
    reach = r * (1.0 + 1e-9)
    counts += ((x < reach[:, None]).sum(1) + (edge - x < reach[:, None]).sum(1))
    return counts


def check_specimen(chk, arrangement, snap, col, vec=None):
    x = np.stack([snap.col("x"), snap.col("y"), snap.col("z")], axis=1)
    r = snap.col("radius")
    if vec is not None:
        c = contact_counts(x, r, EDGE)
        m = r ** 3
        few = 100.0 * (c < 3).mean()
        held = 100.0 * m[c >= 3].sum() / m.sum()
        chk.check("%s: contacts before loading, f_%s[7..9] = %.4f %% with fewer than 3, "
                  "%.4f per grain, %.4f %% of the mass with 3 or more; counted from "
                  "the dump: %.4f, %.4f, %.4f" % (arrangement, FIX, vec["few_contacts_percent"],
                                                  vec["contacts_per_grain"], vec["held_mass_percent"],
                                                  few, c.mean(), held),
                  abs(vec["few_contacts_percent"] - few) < 1e-6
                  and abs(vec["contacts_per_grain"] - c.mean()) < 1e-6
                  and abs(vec["held_mass_percent"] - held) < 1e-6
                  and 3.0 < c.mean() < 8.0)
    tol = 1e-9 * EDGE
    inside = ((x - r[:, None] >= -tol) & (x + r[:, None] <= EDGE + tol)).all()
    chk.check("%s: all %d spheres lie inside the container"
              % (arrangement, len(r)), inside)
    ov = su.max_overlap(x, r)
    chk.check("%s: no two spheres overlap (largest relative overlap %.3g)"
              % (arrangement, ov), ov <= 1e-9)

    k = snap.col(col)
    valid = np.all((k == np.round(k)) & (k >= 1) & (k <= INTERVALS))
    chk.check("%s: %s is an interval index in 1..%d for every atom "
              "(found values %s)" % (arrangement, col, INTERVALS,
                                     short_values(k)), valid)
    if not valid:
        return
    present = sorted(set(int(v) for v in k))
    chk.check("%s: every interval 1..%d has atoms" % (arrangement, INTERVALS),
              present == list(range(1, INTERVALS + 1)),
              "present: %s" % present)
    radii = [np.unique(r[k == c]) for c in present]
    one = all(len(u) == 1 for u in radii)
    chk.check("%s: one radius per interval index" % arrangement, one,
              "radii per index: %s" % [list(u[:3]) for u in radii])
    if one:
        rr = [u[0] for u in radii]
        chk.check("%s: radius grows with the interval index" % arrangement,
                  all(p < q for p, q in zip(rr, rr[1:])),
                  "radii: %s" % rr)


def short_values(v):
    u = np.unique(v)
    s = ", ".join("%g" % t for t in u[:8])
    return s + (", ..." if len(u) > 8 else "")


if __name__ == "__main__":
    main()
