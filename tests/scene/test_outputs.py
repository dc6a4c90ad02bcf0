#!/usr/bin/python3
"""Test of tools/outputs.py, the one reader of the project's outputs: every
layout it reads, on small real files in tests/scene/data/outputs (no
LIGGGHTS run; --launcher is not used).

The files are cut from the oedometer scene of test_oedometer_hold (side
3.3, the lid held after rest) and from test_outlet (two ranks): the scene's
fabric_series.txt, hold_series.txt, fabric_global.txt,
fabric_intervals.txt and rest.txt as written; final.dump (dump custom) and
final_contacts.txt (dump local) cut to their first 6 and 5 rows (the count
line set to match); csd_all.txt of compute constriction/size cut to every
600th row (its comment still counts the whole file's 2542); left.txt.0/.1
of fix massflow/mesh on two ranks; thermo.out, lines of the screen of
test_seepage's scene (its loading, the specimen at rest, the seepage
stage's two runs), each thermo block with the thermo_style line that
printed it; the files of bench/pore_flow_bench on 66 equal spheres
(`export 4 0.4 1`, then `solve` with 1 Pa and 1e-3 Pa s), cut to the box
and 4 spheres, the first 5 cells and 4 forces, and the first 4 cells of
bench/pore_flow_vs_yade/yade_flow.py on the same spheres.

Each reader must give, by name, the value the file holds in that column
(literals below, copied from the files), and must refuse a file whose
column line is not the one its table names: a reader that took a column
by its position, or one that took a renamed layout, fails here.
"""
import os
import shutil

import numpy as np

import scene_util as su

outputs = su.outputs
DATA = os.path.join(su.DATA_DIR, "outputs")


def data(name):
    return os.path.join(DATA, name)


def raises(fn, *a):
    try:
        fn(*a)
    except ValueError as e:
        return str(e)
    return None


def check_tables(chk, source):
    for name, entries in (("fabric vector", outputs.fabric_vector(source)),
                          ("fabric per-atom", outputs.fabric_peratom(source)),
                          ("fabric array", outputs.fabric_array(source)),
                          ("pack vector", outputs.pack_vector(source)),
                          ("constriction vector", outputs.constriction_vector(source)),
                          ("constriction slice", outputs.constriction_slice_entries(source)),
                          ("rest vector", outputs.rest_vector(source)),
                          ("pore flow vector", outputs.pore_flow_vector(source))):
        chk.check("%s: %d entries numbered 1..n with names" % (name, len(entries)),
                  len(entries) > 0 and all(e.name for e in entries))
    chk.check("the class column is %s, c_pf[I] of the per-atom table's 'primary'"
              % outputs.PRIMARY, outputs.PRIMARY == outputs.peratom_name("primary", "pf", source))
    # compute constriction/size with slices 2: the slices after the fixed
    # entries, by name in both readers
    fixed = len(outputs.constriction_vector(source))
    per = len(outputs.constriction_slice_entries(source))
    vec = list(range(1, fixed + 2 * per + 1))
    rows = outputs.constriction_slices(vec, source)
    named = dict(zip((e.name for e in outputs.constriction_vector(source, 2)), vec))
    chk.check("constriction slices: 2 slices of %d entries after the %d fixed ones, by name"
              % (per, fixed), len(rows) == 2 and rows[1]["slice_control"] ==
              named["slice2_control"] == fixed + per
              + outputs.constriction_slice_entries(source)[3].position
              and rows[0]["slice_bottom"] == fixed + 1 and outputs.constriction_slices(
                  vec[:fixed], source) == [], rows)
    chk.check("constriction slices: a vector cut mid-slice is refused",
              raises(outputs.constriction_slices, vec[:-1], source) is not None)
    names = [e.name for e in outputs.pack_vector(source)]
    text = "noise\nPACK_VECTOR %s\n" % " ".join(str(i) for i in range(1, len(names) + 1))
    got = outputs.pack_vector_values(text, source)
    chk.check("pack_vector_values names entry I of the printed line by the table's I-th name",
              got is not None and all(got[n] == i for i, n in enumerate(names, 1)), got)


def check_dumps(chk, work):
    snap = outputs.last_snapshot(data("final.dump"))
    chk.check("final.dump: step 20500, 6 atoms, columns by name",
              snap.timestep == 20500 and snap.natoms == 6 and len(snap.rows) == 6
              and snap.box[0] == (-0.000529133, 0.00582046))
    chk.check("final.dump: radius, %s and mass of the third grain by name" % outputs.PRIMARY,
              snap["radius"][2] == 0.00011442760140256923 and snap[outputs.PRIMARY][2] == 0
              and snap["mass"][2] == 0.0016439697594998451
              and list(snap.col("id", int)) == [1, 2, 3, 4, 5, 6], snap.rows[2])
    d = outputs.dump_last(data("final.dump"))
    chk.check("dump_last: the same columns as a dict",
              sorted(d) == sorted(snap.columns) and np.array_equal(d["z"], snap["z"]))
    r = snap["radius"] ** 3
    want = 100.0 * r[snap[outputs.PRIMARY] == 1].sum() / r.sum()
    chk.check("primary_volume_percent %.6f = by hand %.6f"
              % (outputs.primary_volume_percent(d), want),
              abs(outputs.primary_volume_percent(d) - want) < 1e-12 and 0 < want < 100)
    chk.check("material_mass: the coarsest grain keeps its mass, the rest scale by r^3",
              abs(outputs.material_mass(d)[5] - d["mass"][5]) < 1e-18)
    chk.check("a dump without the column: ValueError naming it",
              "c_pf[9]" in (raises(snap.col, "c_pf[9]") or ""))
    # two snapshots and a third cut short: read_dump keeps the two, in order
    with open(data("final.dump")) as f:
        text = f.read()
    later = text.replace("ITEM: TIMESTEP\n20500", "ITEM: TIMESTEP\n20600", 1)
    both = su.write_file(os.path.join(work, "two.dump"),
                         text + later + "\n".join(text.splitlines()[:12]) + "\n")
    snaps = outputs.read_dump(both)
    chk.check("read_dump: every complete snapshot in order, the one cut short dropped (%s)"
              % [s.timestep for s in snaps], [s.timestep for s in snaps] == [20500, 20600])
    bad = su.write_file(os.path.join(work, "bad.dump"), text.replace("ITEM: BOX BOUNDS", "ITEM: BOX"))
    chk.check("read_dump: a malformed header is a ValueError", raises(outputs.read_dump, bad))


def check_contacts(chk, work):
    c = outputs.read_contacts(data("final_contacts.txt"))
    chk.check("final_contacts.txt: 5 contacts, ids, periodic flag and force by name",
              list(c["id1"]) == [1, 3, 249, 249, 212] and list(c["id2"]) == [2, 4, 934, 1039, 1039]
              and not c["periodic"].any() and c["fz"][1] == -0.21572392808049901
              and c["x2"][0] == 0.00018530571391238377, c)
    snap = outputs.last_snapshot(data("final.dump"))
    x = {int(i): (a, b, z) for i, a, b, z in zip(snap["id"], snap["x"], snap["y"], snap["z"])}
    chk.check("final_contacts.txt: the first contact's centres are grains 1 and 2 of final.dump",
              x[1] == (c["x1"][0], c["y1"][0], c["z1"][0])
              and x[2] == (c["x2"][0], c["y2"][0], c["z2"][0]))
    with open(data("final_contacts.txt")) as f:
        other = su.write_file(os.path.join(work, "other_contacts.txt"),
                              f.read().replace("c_cpgl[", "c_other["))
    chk.check("read_contacts: other columns are a ValueError",
              raises(outputs.read_contacts, other))
    chk.check("constriction local column 'radius' of compute cs is c_cs[7]",
              outputs.constriction_local_name("radius", "cs") == "c_cs[7]")


def check_constriction_and_outlet(chk, work):
    csd = outputs.read_csd(data("csd_all.txt"))
    chk.check("csd_all.txt: 5 rows, the columns by name",
              len(csd["diameter"]) == 5 and csd["diameter"][1] == 7.06856327e-05
              and csd["percent_finer_by_number"][1] == 23.642801
              and csd["percent_finer_by_diameter_cubed"][1] == 2.146765, csd)
    with open(data("csd_all.txt")) as f:
        renamed = su.write_file(os.path.join(work, "renamed_csd.txt"),
                                f.read().replace("percent_finer_by_number", "percent_by_number"))
    chk.check("read_csd: another column line is a ValueError", raises(outputs.read_csd, renamed))
    out = outputs.read_outlet(data("left.txt"))
    chk.check("left.txt.0/.1 (two ranks): ids 1-4 sorted, diameters by name",
              list(out["id"]) == [1, 2, 3, 4]
              and list(out["diameter"]) == [0.0008, 0.0012, 0.0016, 0.0019], out)
    chk.check("VTK array c_pf[1-3] holds %s as component 1" % outputs.PRIMARY,
              outputs.vtk_component("c_pf[1-3]", outputs.PRIMARY) == 1
              and outputs.vtk_component("c_other[1-3]", outputs.PRIMARY) is None
              and outputs.vtk_component("c_pf[3-5]", outputs.PRIMARY) is None)


def check_scene_files(chk, work, source):
    s = outputs.read_series(data("fabric_series.txt"))
    chk.check("fabric_series.txt: the second row by name",
              s["step"][1] == 2000 and s["lid_stress"][1] == 99363.1
              and s["primary_mass_pct"][1] == 53.6917 and s["coordination"][1] == 0.845033)
    h = outputs.read_series(data("hold_series.txt"), outputs.HOLD_SERIES_COLUMNS)
    chk.check("hold_series.txt: the first row by name",
              h["step"][0] == 10500 and h["lid_stress"][0] == 99253.1
              and h["primary_mass_pct"][0] == 46.1658)
    chk.check("read_series: the series under the hold's columns is a ValueError",
              raises(outputs.read_series, data("fabric_series.txt"), outputs.HOLD_SERIES_COLUMNS))
    rest = outputs.read_rest(data("rest.txt"), source)
    chk.check("rest.txt: step 20500, phase 'at rest', entries by name (%s)" % rest,
              rest is not None and rest["step"] == 20500 and rest["phase_name"] == "at rest"
              and rest["rest_stress"] == 99253.1 and rest["steps_relaxed"] == 2000)
    g = outputs.read_global(data("fabric_global.txt"), source)
    at = outputs.index(outputs.fabric_vector(source))
    chk.check("fabric_global.txt: the last row's entries by name",
              g is not None and g[at["particles"]] == 4188 and g[at["loose_particles"]] == 3713
              and g[at["primary_percent_by_mass"]] == 45.8433)
    iv = outputs.read_intervals(data("fabric_intervals.txt"), source)
    cols = outputs.fabric_array(source)
    chk.check("fabric_intervals.txt: the last block's columns by name, %d intervals"
              % len(iv["diameter"]),
              iv["step"] == 20500 and len(iv["diameter"]) == 20
              and all(len(iv[e.name]) == 20 for e in cols)
              and iv["diameter"][19] == 0.00160343 and iv["particles"][19] == 1
              and iv["primary_percent_of_interval"][18] == 100)


def check_thermo(chk):
    with open(data("thermo.out")) as f:
        text = f.read()
    load, rest, vol, seep = [l for l in text.splitlines() if l.startswith("thermo_style")]
    chk.check("thermo_word: prefix dropped, cut to 8 characters, LAMMPS' names",
              [outputs.thermo_word(k) for k in ("f_seep_now[1]", "v_sigma_lid", "c_pf[1][8]",
                                                "ke", "atoms", "c_pf[4]")]
              == ["seep_now", "sigma_li", "pf[1][8]", "KinEng", "Atoms", "pf[4]"])
    rows = outputs.read_thermo(text, load)
    chk.check("thermo.out, the loading: 2 rows (steps 0, 4000) by the script's keywords, "
              "the LOADED line in the block skipped (%s)" % [r["step"] for r in rows],
              [r["step"] for r in rows] == [0, 4000]
              and rows[1]["v_sigma_lid"] == 100770.8 and rows[1]["v_sigma_avg"] == 100422.98
              and rows[1]["v_primary_pct"] == 50.458306 and rows[1]["f_qs"] == 0.01132015
              and rows[0]["v_contacts"] == 5.3698663 and rows[0]["cpu"] == 0, rows)
    runs = outputs.read_thermo(text, load, runs=True)
    chk.check("runs=True: one list per run (2 runs of 1 row)", [len(b) for b in runs] == [1, 1])
    r = outputs.read_thermo(text, rest)
    chk.check("thermo.out, at rest: c_pf[4] 46.165812 at step 10500",
              len(r) == 1 and r[0]["step"] == 10500 and r[0]["c_pf[4]"] == 46.165812
              and r[0]["c_pf[5]"] == 0.50405922, r)
    v = outputs.read_thermo(text, vol)
    chk.check("thermo.out: c_vol_loose0 (header 'vol_loos') by its keyword",
              len(v) == 1 and v[0]["atoms"] == 4188 and v[0]["c_vol_loose0"] == 5.0653322e-08
              and v[0]["c_vol_sum"] == 9.4091365e-08, v)
    s = outputs.read_thermo(text, seep, runs=True)
    chk.check("thermo.out, the seepage stage: 2 runs of 2 rows; f_seep_now[1] and [2], both "
              "printed as 'seep_now', apart by the keywords",
              [len(b) for b in s] == [2, 2] and s[0][0]["f_seep_now[1]"] == -4.4408921e-14
              and s[0][0]["f_seep_now[2]"] == -2.220446e-14
              and s[1][1]["v_sigma_top"] == 99986.11 and s[1][1]["step"] == 12500, s)
    first = outputs.thermo_row(text, seep, 11500)
    chk.check("thermo_row: the first run that prints step 11500 (cpu 2.9050204); "
              "None for a step not printed",
              first is not None and first["cpu"] == 2.9050204
              and outputs.thermo_row(text, seep, 7) is None, first)
    chk.check("another style of as many columns, or the keywords in another order, "
              "reads no row",
              outputs.read_thermo(text, "step atoms c_vol_sum c_other") == []
              and outputs.read_thermo(text, "step atoms c_vol_loose0 c_vol_sum") == [])
    cut = text[:text.rindex("   12500 ")]
    chk.check("a run cut short (no Loop time) keeps the rows it printed (3 of 4)",
              len(outputs.read_thermo(cut, seep)) == 3)
    nan = text.replace("99986.11", "-nan")
    got = outputs.read_thermo(nan, seep)[-1]["v_sigma_top"]
    chk.check("a non-finite value is read as such (nan), for a test of finiteness",
              got != got, got)
    chk.check("thermo_keywords: not custom, or not from step, is a ValueError",
              raises(outputs.thermo_keywords, "thermo_style one")
              and raises(outputs.thermo_keywords, "atoms step")
              and outputs.thermo_keywords(seep + " # note") == seep.split()[2:])


def check_bench(chk):
    box, sph = outputs.read_bench_spheres(data("bench_spheres.txt"))
    chk.check("bench_spheres.txt: the box and 4 spheres by name",
              box["xlo"] == 0 and box["zhi"] == 0.004 and len(sph["x"]) == 4
              and sph["z"][1] == 0.0035 and sph["y"][1] == 0.0005 and sph["radius"][3] == 0.0005,
              (box, sph))
    c = outputs.read_bench_table(data("bench_cells.txt"), outputs.BENCH_CELL_COLUMNS)
    kinds = [outputs.BENCH_PORE_KINDS[int(k)] for k in c["kind"]]
    chk.check("bench_cells.txt: 5 cells, pressure, kind and pore by name; the fourth "
              "cell merged into the third's pore (%s)" % kinds,
              len(c["x"]) == 5 and c["pressure"][0] == 0.971923767764 and c["z"][0] == 0.0005
              and kinds == ["unknown", "inflow", "unknown", "unknown", "inflow"]
              and list(c["pore"]) == [0, 1, 2, 2, 4], c)
    f = outputs.read_bench_table(data("bench_forces.txt"), outputs.BENCH_FORCE_COLUMNS)
    chk.check("bench_forces.txt: 4 forces by name",
              len(f["fz"]) == 4 and f["fz"][1] == 3.14226084606e-07
              and f["fx"][0] == -3.58995101761e-08, f)
    y = outputs.read_bench_table(data("yade_cells.txt"), outputs.YADE_CELL_COLUMNS)
    chk.check("yade_cells.txt: FlowEngine's centres and pressures by name",
              len(y["x"]) == 4 and y["pressure"][0] == 0.32198384966
              and y["y"][0] == 0.00187867901305 and y["pressure"][3] == 1, y)
    chk.check("a file of another width is a ValueError (ours read as yade's, the "
              "forces as cells), and so is a spheres file without its box",
              raises(outputs.read_bench_table, data("bench_cells.txt"), outputs.YADE_CELL_COLUMNS)
              and raises(outputs.read_bench_table, data("bench_forces.txt"),
                         outputs.BENCH_CELL_COLUMNS)
              and raises(outputs.read_bench_spheres, data("bench_cells.txt")))


def main():
    args = su.parse_args(__doc__)
    work = su.fresh_dir(args.work)
    chk = su.Checker()
    check_tables(chk, args.source)
    check_dumps(chk, work)
    check_contacts(chk, work)
    check_constriction_and_outlet(chk, work)
    check_scene_files(chk, work, args.source)
    check_thermo(chk)
    check_bench(chk)
    chk.finish()


if __name__ == "__main__":
    main()
