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
of fix massflow/mesh on two ranks.

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
                          ("rest vector", outputs.rest_vector(source)),
                          ("pore flow vector", outputs.pore_flow_vector(source))):
        chk.check("%s: %d entries numbered 1..n with names" % (name, len(entries)),
                  len(entries) > 0 and all(e.name for e in entries))
    chk.check("the class column is %s, c_pf[I] of the per-atom table's 'primary'"
              % outputs.PRIMARY, outputs.PRIMARY == outputs.peratom_name("primary", "pf", source))
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


def main():
    args = su.parse_args(__doc__)
    work = su.fresh_dir(args.work)
    chk = su.Checker()
    check_tables(chk, args.source)
    check_dumps(chk, work)
    check_contacts(chk, work)
    check_constriction_and_outlet(chk, work)
    check_scene_files(chk, work, args.source)
    chk.finish()


if __name__ == "__main__":
    main()
