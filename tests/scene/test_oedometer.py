#!/usr/bin/python3
"""Scene test: the oedometer scene end to end, on a specimen of 2,420 grains
(Cu = 2.5, discrete arrangement, porosity 0.35: the scene's defaults, except
side 2.75, which still holds the coarsest interval's grains, and linear
springs of kn 2e7 N/m, whose wall forces the recount below forms in closed
form; at rest after 60,000 steps, half a minute).

1. The run ends at rest (the stop rule's three conditions: kinetic energy,
   lid stress over the whole last block, steady primary fraction), with the
   lid stress within 5 % of the 100 kPa target (the servo settles instead of
   swinging).
2. An independent recount (no code shared with the compute) finds the same
   primary fabric: precision and recall of the compute's primary set, grain
   by grain, both at least 99 % (most grains are loose with no contact at
   all, so agreement over all grains would say little), and the same global
   figures (entries 1-4, 10-13 of the global vector in fabric_global.txt).
   The recount uses the compute's definition of a contact's normal force,
   F.n with n from the partner to the grain: for grain contacts from the
   text contact dump (compute pair/gran/local on 1 rank, so complete); for
   wall contacts from the grain positions, the container edge and the lid
   height (the overlap), the grain's mass and velocity, as LIGGGHTS'
   hooke/stiffness model forms it: kn overlap - gamman m v.n (the walls at
   rest: the scene analyses its final state with the lid held still). A
   contact needs a positive overlap (grains that exactly touch a wall are no
   contact, as for two grains) and is loaded when its normal force exceeds
   1e-3 of the mean (the compute's default). Both dumps are written with 17
   digits: loaded overlaps are about 1e-9 m, below the 6 digits of %g.
3. The same final state, read from the restart file on 1 rank and on 2 ranks
   with `processors 2 1 1` (the cut goes through the specimen), gets the same
   classes grain by grain, and the same classes as the run itself.
4. The scene writes the compute's whole outputs as
   compute_primary_fabric/fabric_outputs.h defines them (tools/outputs.py
   reads it): fabric_global.txt a row of the step and the fixed entries
   plus two per direction bin (the scene's one copy of the fixed count, 31,
   agrees with the header), fabric_intervals.txt a row per interval (the
   scene's `intervals`, 20) of the row number and the array's columns.
   The entries the scene reads by position (the time series, the FABRIC
   line that tools/oedometer_runs.py reads, the step-0 values of the fix)
   are the ones their names in the two headers say.
5. tools/plot_fabric.py draws the paper's figures from the run's output
   without a warning (no column or vector entry missing).
"""
import os
import re
import subprocess

import numpy as np

import scene_util as su

STRESS = 100e3
KN = 2e7

RESTART = """\
{preamble}read_restart    {restart}
neighbor        5e-5 bin
neigh_modify    delay 0
fix m_kn  all property/global kn peratomtypepair 3 2e7 2e7 2e7 2e7 2e7 2e7 2e7 2e7 2e7
fix m_kt  all property/global kt peratomtypepair 3 2e7 2e7 2e7 2e7 2e7 2e7 2e7 2e7 2e7
fix m_gn  all property/global gamman peratomtypepair 3 {gn} {gn_wall} {gn} {gn_wall} {gn} {gn} {gn} {gn} {gn}
fix m_gt  all property/global gammat peratomtypepair 3 {gt} {gt_wall} {gt} {gt_wall} {gt} {gt} {gt} {gt} {gt}
fix m_mu  all property/global coefficientFriction peratomtypepair 3 0.4 0.4 0.4 0.4 0.4 0.4 0.4 0.4 0.4
fix m_rmu all property/global coefficientRollingFriction peratomtypepair 3 0.8 0.4 0.4 0.4 0.8 0.8 0.4 0.8 0.8
fix m_rst all property/global rollingStiffness scalar 1.0
fix m_rvd all property/global coefficientRollingViscousDamping peratomtypepair 3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3 0.3
pair_style      gran model hooke/stiffness tangential history rolling_friction epsd3
pair_coeff      * *
variable wm string "model hooke/stiffness tangential history rolling_friction epsd3"
fix w_x0  all wall/gran ${{wm}} primitive type 3 xplane 0.0  store_force_contact_stress yes
fix w_x1  all wall/gran ${{wm}} primitive type 3 xplane {L} store_force_contact_stress yes
fix w_y0  all wall/gran ${{wm}} primitive type 3 yplane 0.0  store_force_contact_stress yes
fix w_y1  all wall/gran ${{wm}} primitive type 3 yplane {L} store_force_contact_stress yes
fix w_top all wall/gran ${{wm}} primitive type 3 zplane {L} store_force_contact_stress yes
fix lid   all mesh/surface file {mesh} type 2 scale {L} move {hL} {hL} {zlid}
fix w_lid all wall/gran ${{wm}} mesh n_meshes 1 meshes lid store_force_contact_stress yes
compute pf all primary/fabric
fix integr all nve/sphere
timestep 1e-9
dump d all custom 1 {dump} id {columns}
dump_modify d sort id
run 0
"""


# What in.oedometer reads by position: (line pattern, the names of its
# c_pf[N] and f_pack[N] in order of appearance)
SCENE_POSITIONS = [
    (r"^variable loose_pct .*", ["loose_percent_by_number"], ["few_contacts_percent"]),
    (r"^variable primary_pct .*", ["primary_percent_by_mass"], ["held_mass_percent"]),
    (r"^variable contacts .*", ["coordination"], ["contacts_per_grain"]),
    (r"^fix series .*", ["overlapping_zone_percent"], []),
    (r'^print "FABRIC: .*', ["loose_percent_by_number", "primary_percent_by_mass", "r1", "r2",
                             "overlapping_zone_percent"], []),
    (r'^if .* "print .BEFORE LOADING: .*', [], ["contacts_per_grain", "few_contacts_percent",
                                                 "held_mass_percent"]),
    (r'^print "CHECKPOINT: after .*', ["primary_percent_by_mass"], []),
]


def check_scene_positions(args, chk):
    """The scene's c_pf[N] and f_pack[N] name the entries it means."""
    outputs = su.outputs
    text = su.oedometer_text(args.source)
    pf = {e.position: e.name for e in outputs.fabric_vector(args.source)}
    pack = {e.position: e.name for e in outputs.pack_vector(args.source)}
    wrong = []
    for pattern, want_pf, want_pack in SCENE_POSITIONS:
        line = re.search(pattern, text, re.M)
        got_pf = [pf.get(int(n)) for n in re.findall(r"c_pf\[(\d+)\]", line.group(0))] if line else None
        got_pack = [pack.get(int(n)) for n in re.findall(r"f_pack\[(\d+)\]", line.group(0))] if line else None
        if got_pf != want_pf or got_pack != want_pack:
            wrong.append("%s: c_pf %s f_pack %s, meant %s %s" % (pattern, got_pf, got_pack, want_pf, want_pack))
    chk.check("in.oedometer's c_pf[N] and f_pack[N] are the entries of fabric_outputs.h and "
              "pack_outputs.h it means", not wrong, "\n".join(wrong))


def run_scene(args, chk):
    """1. The scene's run: it ends at rest, the lid stress near the
    target; the run and its output folder (None if it did not run) and the
    STOP line's lid stress."""
    out = os.path.join(args.work, "run")
    res = su.run_launcher(args, os.path.join(args.source, "input_scripts", "in.oedometer"),
                          variables={"out": out, "every": 2000, "side": 2.75, "kn": KN},
                          log=os.path.join(args.work, "oedometer.log"),
                          cwd=args.source, timeout=600)
    if not chk.check("the oedometer scene runs (%.0f s)" % res.seconds,
                     res.returncode == 0, res.describe()):
        chk.finish()
    stop = [l for l in res.text.splitlines() if l.startswith("STOP:")]
    chk.check("it stops at rest", stop and stop[-1].startswith("STOP: at rest")
              and "kinetic energy" in stop[-1] and "unbalanced-force ratio" in stop[-1], stop)
    m = re.search(r"lid stress ([-0-9.eE+]+) Pa", stop[-1] if stop else "")
    sigma = float(m.group(1)) if m else float("nan")
    chk.check("lid stress %.0f Pa within 5 %% of %.0f Pa" % (sigma, STRESS),
              abs(sigma / STRESS - 1) < 0.05)
    return res, out, sigma


def check_series_rest(chk, out, sigma):
    """The outputs the tools read by name: the series' columns are
    outputs.SERIES_COLUMNS, rest.txt is fix servo/rest's vector."""
    try:
        series = su.outputs.read_series(os.path.join(out, "fabric_series.txt"))
        rest = su.outputs.read_rest(os.path.join(out, "rest.txt"))
        ok = (rest is not None and rest["phase_name"] == "at rest"
              and int(series["step"][-1]) == int(rest["steps"])
              and abs(rest["rest_stress"] / sigma - 1) < 1e-5)
        why = (list(series), rest)
    except ValueError as e:
        ok, why = False, str(e)
    chk.check("fabric_series.txt has the columns of outputs.SERIES_COLUMNS, its last row the "
              "step of rest.txt (fix servo/rest's vector: at rest, the STOP line's stress)", ok, why)


def particle_contacts(out):
    """The grain contacts of final_contacts.txt, read by name: (ids as an
    n x 2 array, normal force F.n with n from the second grain to the
    first)."""
    c = su.outputs.read_contacts(os.path.join(out, "final_contacts.txt"))
    branch = np.stack([c["x1"] - c["x2"], c["y1"] - c["y2"], c["z1"] - c["z2"]], axis=1)
    force = np.stack([c["fx"], c["fy"], c["fz"]], axis=1)
    fn = np.einsum("ij,ij->i", force, branch) / np.linalg.norm(branch, axis=1)
    return np.stack([c["id1"], c["id2"]], axis=1).astype(int), fn


def wall_contacts(g, L, zlid, gn_wall, gn_grain):
    """Per wall (x 0, x L, y 0, y L, top L, the lid), each grain's normal
    force from the overlap and its velocity: F.n = kn overlap - gamman m
    v.n, n from the wall to the grain; nan where there is no overlap. The
    lid's contacts damp with gn_wall, the fixed walls' with the grains' G_n."""
    x, y, z, r = g["x"], g["y"], g["z"], g["radius"]
    vel = np.stack([g["vx"], g["vy"], g["vz"]], axis=1)
    walls = [(x, (1, 0, 0)), (L - x, (-1, 0, 0)), (y, (0, 1, 0)),
             (L - y, (0, -1, 0)), (L - z, (0, 0, -1)), (z - zlid, (0, 0, 1))]
    fn_w = []
    for k, (gap, n) in enumerate(walls):
        overlap = r - gap
        vn = vel @ np.array(n, float)
        damp = gn_wall if k == 5 else gn_grain
        fn_w.append(np.where(overlap > 0, KN * overlap - damp * g["mass"] * vn, np.nan))
    return fn_w


def recount(args, out, text):
    """2. The independent recount of the final state (final.dump and
    final_contacts.txt, columns by name): a dict of the grains (ids, the
    compute's class, mass), the contacts' forces, the mean, the threshold,
    the loaded contacts and the recount's class per grain."""
    lid = re.search(r"LID: z_lid ([-0-9.eE+]+) m, container edge ([-0-9.eE+]+) m", text)
    zlid, L = float(lid.group(1)), float(lid.group(2))
    snap = su.last_snapshot(os.path.join(out, "final.dump"))
    g = {c: snap.col(c) for c in ("x", "y", "z", "radius", "mass", "vx", "vy", "vz")}
    ids = snap.col("id", int)
    cls = snap.col(su.outputs.PRIMARY, lambda v: int(float(v)))
    pairs, fn_pp = particle_contacts(out)
    gn_wall = float(re.search(r"^variable gn_wall\s+index\s+(\S+)",
                              su.oedometer_text(args.source), re.M).group(1))
    gn_grain = float(re.search(r"DAMPING: G_n = ([-0-9.eE+]+) 1/s", text).group(1))
    fn_w = wall_contacts(g, L, zlid, gn_wall, gn_grain)
    wall_forces = np.concatenate([f[~np.isnan(f)] for f in fn_w])
    mean = (fn_pp.sum() + wall_forces.sum()) / (len(fn_pp) + len(wall_forces))
    thr = 1e-3 * max(mean, 0.0)
    index = {i: k for k, i in enumerate(ids)}
    loaded = np.zeros(len(ids), int)
    nloaded = 0
    for (a, b), f in zip(pairs, fn_pp):
        if f > thr:
            loaded[index[a]] += 1
            loaded[index[b]] += 1
            nloaded += 1
    for f in fn_w:
        hit = np.nan_to_num(f, nan=-np.inf) > thr
        loaded += hit.astype(int)
        nloaded += int(hit.sum())
    return {"ids": ids, "cls": cls, "mass": g["mass"], "n_pp": len(fn_pp),
            "n_wall": len(wall_forces), "mean": mean, "thr": thr, "nloaded": nloaded,
            "recount": (loaded >= 3).astype(int), "zlid": zlid, "L": L, "gn_wall": gn_wall}


def check_recount(chk, rc):
    """2. The compute's primary set against the recount's, grain by grain."""
    cls, rec = rc["cls"], rc["recount"]
    both = int(np.sum((rec == 1) & (cls == 1)))
    precision = both / max(1, int(cls.sum()))     # of the compute's primary
    recall = both / max(1, int(rec.sum()))        # of the recount's primary
    chk.note("%d grains, %d particle contacts, %d wall contacts, mean normal force %.4g N; "
             "primary: compute %d, recount %d, both %d"
             % (len(rc["ids"]), rc["n_pp"], rc["n_wall"], rc["mean"], cls.sum(), rec.sum(), both))
    # grain for grain: the recount's wall forces are rebuilt from the linear
    # model and may differ from the stored ones in the last digits, which no
    # grain's class depends on here (measured: 136 primary, all 136 shared)
    chk.check("primary fabric: precision %.2f %% and recall %.2f %% of the compute's "
              "primary set against the recount (both 100 %%)"
              % (100 * precision, 100 * recall),
              precision == 1 and recall == 1 and rec.sum() > 10)
    chk.check("the specimen carries load: some grains are primary fabric", cls.sum() > 10)


def check_files_layout(args, chk, out):
    """4. fabric_global.txt and fabric_intervals.txt have the layout of
    fabric_outputs.h (the intervals' first column is fix ave/time's row
    number)."""
    outputs = su.outputs
    gl = outputs.data_rows(os.path.join(out, "fabric_global.txt"))
    want_len = outputs.fabric_vector_size(9, args.source)
    chk.check("fabric_global.txt: step + %d entries (%d fixed in fabric_outputs.h + 2 x 9 "
              "direction bins), got %d" % (want_len, len(outputs.fabric_vector(args.source)),
                                           len(gl[-1]) - 1),
              len(gl[-1]) == 1 + want_len)
    blocks = outputs.vector_blocks(os.path.join(out, "fabric_intervals.txt"))
    last = blocks[-1][1] if blocks else []
    ncols = len(outputs.fabric_array(args.source))
    chk.check("fabric_intervals.txt: 20 rows of the row number and the %d columns of "
              "fabric_outputs.h" % ncols,
              len(last) == 20 and all(len(r) == 1 + ncols for r in last)
              and [r[0] for r in last] == list(range(1, 21)))


def check_global_figures(args, chk, out, rc):
    """2. The compute's global figures (fabric_global.txt, by the names of
    fabric_outputs.h) against the recount: the classes exactly (to the 6
    digits of the file); the force sums to the rebuilt wall forces'
    accuracy."""
    v = su.outputs.read_global(os.path.join(out, "fabric_global.txt"), args.source)
    pos = su.outputs.index(su.outputs.fabric_vector(args.source))
    rec, mass, n = rc["recount"], rc["mass"], len(rc["ids"])
    contacts = rc["n_pp"] + rc["n_wall"]
    want = [("particles", n, 0),
            ("loose_particles", n - rec.sum(), 0),
            ("loose_percent_by_number", 100 * (1 - rec.mean()), 1e-4),
            ("primary_percent_by_mass", 100 * mass[rec == 1].sum() / mass.sum(), 1e-4),
            ("contacts", contacts, 0.005 * contacts),
            ("loaded_contacts", rc["nloaded"], 0.01 * rc["nloaded"]),
            ("mean_normal_force", rc["mean"], 0.01 * rc["mean"]),
            ("threshold_force", rc["thr"], 0.01 * rc["thr"])]
    bad = ["fabric_global.txt is missing or short"] if v is None else [
        "%s (entry %d): compute %.6g, recount %.6g" % (name, pos[name] + 1, v[pos[name]], e)
        for name, e, tol in want if not abs(v[pos[name]] - e) <= tol + 1e-6 * abs(e)]
    chk.check("global figures agree with the recount: particles, loose, loose %, "
              "primary % by mass, contacts, loaded contacts, mean normal force, "
              "threshold", not bad, "\n".join(bad))


def classes_on_ranks(args, chk, out, text, rc, nprocs, processors):
    """3. The final state read back from the restart file on `nprocs`
    ranks: {id: class}, or None if the run failed."""
    dmp = re.search(r"DAMPING: G_n = ([-0-9.eE+]+) 1/s, G_t = ([-0-9.eE+]+) 1/s", text)
    ranks = nprocs or 1
    dump = os.path.join(args.work, "state_%s.dump" % ranks)
    L, gn_wall = rc["L"], rc["gn_wall"]
    inp = su.write_file(os.path.join(args.work, "in.state_%s" % ranks), RESTART.format(
        preamble=su.preamble(processors=processors), restart=os.path.join(out, "final.restart"),
        gn=dmp.group(1), gt=dmp.group(2), gn_wall=su.num(gn_wall), gt_wall=su.num(0.5 * gn_wall),
        L=su.num(L), hL=su.num(L / 2), zlid=su.num(rc["zlid"]),
        mesh=os.path.join(args.source, "input_scripts", "meshes", "lid.stl"), dump=dump,
        columns=" ".join(su.outputs.peratom_name(c) for c in ("loaded_contacts", "primary"))))
    r2 = su.run_launcher(args, inp, nprocs=nprocs, timeout=300)
    if not chk.check("final state read back on %d rank(s)" % ranks, r2.returncode == 0,
                     r2.describe()):
        return None
    s = su.last_snapshot(dump)
    return dict(zip(s.col("id", int), s.col(su.outputs.PRIMARY, lambda v: int(float(v)))))


def check_ranks(args, chk, out, text, rc):
    """3. The same state on 1 and 2 ranks (processors 2 1 1), and as the
    run itself has it."""
    one = classes_on_ranks(args, chk, out, text, rc, None, None)
    two = classes_on_ranks(args, chk, out, text, rc, 2, "2 1 1")
    if one is None or two is None:
        return
    same = sum(one[i] == two.get(i) for i in one)
    chk.check("1 and 2 ranks (processors 2 1 1): same class for %d of %d grains"
              % (same, len(one)), same == len(one) and len(two) == len(one))
    rerun = sum(one.get(i) == k for i, k in zip(rc["ids"], rc["cls"]))
    chk.check("read back on 1 rank vs the run itself: same class for %d of %d grains"
              % (rerun, len(rc["ids"])), rerun == len(rc["ids"]))


def check_plots(args, chk, out):
    """5. The paper's figures from this run: every figure drawn, no column
    or entry missing (the series' title line, the global vector's layout)."""
    plot = subprocess.run(["/usr/bin/python3", os.path.join(args.source, "tools", "plot_fabric.py"), out],
                          capture_output=True, text=True, timeout=300)
    pngs = [f for f in os.listdir(out) if f.startswith("fig") and f.endswith(".png")]
    chk.check("tools/plot_fabric.py draws the 7 figures without a warning (%d PNG)" % len(pngs),
              plot.returncode == 0 and "warning" not in plot.stderr + plot.stdout and len(pngs) == 7,
              plot.stderr[-1500:])


def main():
    args = su.parse_args(__doc__)
    su.fresh_dir(args.work)
    chk = su.Checker()
    check_scene_positions(args, chk)
    res, out, sigma = run_scene(args, chk)
    check_series_rest(chk, out, sigma)
    rc = recount(args, out, res.text)
    check_recount(chk, rc)
    check_files_layout(args, chk, out)
    check_global_figures(args, chk, out, rc)
    check_ranks(args, chk, out, res.text, rc)
    check_plots(args, chk, out)
    chk.finish()


if __name__ == "__main__":
    main()
