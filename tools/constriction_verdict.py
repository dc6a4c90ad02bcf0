#!/usr/bin/python3
"""The suffusion verdict of compute constriction/size on the specimens of an
oedometer study (tools/oedometer_study.py): per run, the final state
(OUT/runs/NAME/final.dump, with the class c_pf[2] of compute primary/fabric)
is read into the launcher, grouped into primary (class 1) and loose (0)
grains, and compute constriction/size gives the CSD of the primary fabric
(loose group: the verdict, with D_c35 by number and by area; psd: the
classical criteria) and of the whole specimen. Writes, into --dest:
  verdict.csv           one row per run
  csd_NAME.txt          the two cumulative CSDs (files of the compute)
  fig_NAME.png          PSD, PFD, LPD and the two CSDs on one size axis

    /usr/bin/python3 tools/constriction_verdict.py --study out/small \
        --launcher build/liggghts-fabric --dest results/constrictions/small
"""
import argparse
import csv
import os
import re
import subprocess
import sys

import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import outputs  # noqa: E402  (the compute's output table)
from soils import psd_path  # noqa: E402

ROOT = os.path.abspath(os.path.join(os.path.dirname(__file__), ".."))
# The compute's global vector, by the names of constriction_outputs.h.
ENTRIES = outputs.constriction_vector(ROOT)
NV = len(ENTRIES)


def write_data(path, g):
    cls = g[outputs.PRIMARY]
    d = 2.0 * g["radius"]
    rho = outputs.material_mass(g) / (np.pi / 6.0 * d ** 3)
    lo = min(g[a].min() - g["radius"].max() for a in "xyz") - 1e-3
    hi = max(g[a].max() + g["radius"].max() for a in "xyz") + 1e-3
    with open(path, "w") as f:
        f.write("grains of an oedometer run: type 1 primary, 2 loose\n\n"
                "%d atoms\n2 atom types\n\n" % len(d))
        for a in "xyz":
            f.write("%.17g %.17g %slo %shi\n" % (lo, hi, a, a))
        f.write("\nAtoms\n\n")
        for k in range(len(d)):
            f.write("%d %d %.17g %.17g %.17g %.17g %.17g\n" % (
                int(g["id"][k]), 1 if cls[k] == 1 else 2, d[k], rho[k],
                g["x"][k], g["y"][k], g["z"][k]))


SCRIPT = """units si
atom_style granular
atom_modify map array sort 0 0.0
boundary f f f
newton off
communicate single vel yes
read_data grains.data
group primary type 1
group loose type 2
compute cp primary constriction/size loose loose psd {psd} csd csd_primary.txt
compute ca all constriction/size psd {psd} csd csd_all.txt
compute cq primary constriction/size loose loose control_by area
thermo_style custom step {cp}
thermo_modify format float %.17g
run 0
thermo_style custom step {ca}
thermo_modify format float %.17g
run 0
thermo_style custom step {cq}
thermo_modify format float %.17g
run 0
"""


def keywords(cid):
    """The thermo keywords of compute `cid`'s whole vector, c_ID[1..NV]."""
    return ["c_%s[%d]" % (cid, e.position) for e in ENTRIES]


def vectors(text):
    """{compute ID: {entry name: value}} of the vectors of cp, ca and cq in
    the launcher's output, each from the last row of its thermo_style, read
    by its keywords (outputs.read_thermo); a compute without a row is left
    out."""
    out = {}
    for cid in ("cp", "ca", "cq"):
        rows = outputs.read_thermo(text, ["step"] + keywords(cid))
        if rows:
            out[cid] = {e.name: rows[-1]["c_%s[%d]" % (cid, e.position)] for e in ENTRIES}
    return out


def read_psd(path):
    pts = np.array([[float(v) for v in l.split()[:2]] for l in open(path)
                    if l.strip() and not l.lstrip().startswith("#")])
    return pts[:, 0], pts[:, 1]


def cumulative(d, m, total):
    o = np.argsort(d)
    return d[o], 100.0 * np.cumsum(m[o]) / total


def figure(path, name, psd, g, csd_p, csd_a, vp):
    fig, ax = plt.subplots(figsize=(6.4, 4.2))
    ax.plot(psd[0] * 1e3, psd[1], "k-", lw=2, label="PSD (input)")
    total = g["mass"].sum()
    d = 2.0 * g["radius"]
    prim = g[outputs.PRIMARY] == 1
    for sel, lab, st in ((prim, "PFD (primary)", "b-"), (~prim, "LPD (loose)", "r-")):
        x, y = cumulative(d[sel], g["mass"][sel], total)
        ax.step(x * 1e3, y, st, where="post", label=lab)
    for c, lab, st in ((csd_p, "CSD primary fabric", "g--"), (csd_a, "CSD whole specimen", "m:")):
        if len(c["diameter"]):
            ax.plot(c["diameter"] * 1e3, c["percent_finer_by_number"], st,
                    label=lab + " (by number)")
    ax.axvline(vp["control"] * 1e3, color="g", lw=0.8)
    ax.axvline(vp["percolation"] * 1e3, color="g", lw=0.8, ls="-.")
    ax.set_xscale("log")
    ax.set_xlabel("diameter (mm); green lines: D_c35 and percolation opening of the primary fabric")
    ax.set_ylabel("% finer (PSD, PFD, LPD: of the mass)")
    ax.set_ylim(0, 100)
    ax.set_title(title(name))
    ax.legend(fontsize=7, loc="upper left")
    ax.grid(alpha=0.3, which="both")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def title(name):
    """The figure's title: the run's name, with its side if the name gives
    one (side3.3: a cube 3.3 coarsest diameters wide)."""
    m = re.search(r"side(\d+(\.\d+)?)", name)
    return "%s (side %s)" % (name, m.group(1)) if m else name


def load_csd(path):
    """A csd file of the compute: {name of outputs.CSD_COLUMNS: array}."""
    return outputs.read_csd(path)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--study", required=True)
    ap.add_argument("--launcher", default=os.path.join(ROOT, "build", "liggghts-fabric"))
    ap.add_argument("--dest", required=True)
    a = ap.parse_args()
    # each run's compute works in a folder of its own: a relative path is the caller's
    a.launcher = os.path.abspath(a.launcher)
    if not os.access(a.launcher, os.X_OK):
        sys.exit("constriction_verdict: --launcher %s: no such executable (build it with "
                 "bash tools/build.sh)" % a.launcher)
    os.makedirs(a.dest, exist_ok=True)
    runs = sorted(os.listdir(os.path.join(a.study, "runs")))
    # each run's soil as the study tool wrote it (its PSD file is the soil's)
    with open(os.path.join(a.study, "study.csv")) as f:
        soil_of = {r["name"]: r["soil"] for r in csv.DictReader(f)}
    table = []
    for name in runs:
        run = os.path.join(a.study, "runs", name)
        dump = os.path.join(run, "final.dump")
        if not os.path.isfile(dump):
            continue
        if name not in soil_of:
            print("%s: not in %s/study.csv, skipped" % (name, a.study))
            continue
        psd = psd_path(soil_of[name], ROOT)
        g = outputs.dump_last(dump)
        work = os.path.join(a.study, "constriction", name)
        os.makedirs(work, exist_ok=True)
        write_data(os.path.join(work, "grains.data"), g)
        with open(os.path.join(work, "in.csd"), "w") as f:
            f.write(SCRIPT.format(psd=psd, cp=" ".join(keywords("cp")),
                                  ca=" ".join(keywords("ca")), cq=" ".join(keywords("cq"))))
        res = subprocess.run([a.launcher, "-in", "in.csd", "-log", "log.csd"], cwd=work,
                             capture_output=True, text=True, errors="replace")
        v = vectors(res.stdout)
        if res.returncode != 0 or len(v) != 3:
            print("%s: the launcher failed:\n%s" % (name, res.stdout[-2000:]))
            continue
        vp, va, vq = v["cp"], v["ca"], v["cq"]
        csd_p = load_csd(os.path.join(work, "csd_primary.txt"))
        csd_a = load_csd(os.path.join(work, "csd_all.txt"))
        with open(os.path.join(a.dest, "csd_%s.txt" % name), "w") as f:
            f.write("# %s: cumulative CSDs of compute constriction/size\n"
                    "# set diameter_m percent_finer_by_number percent_finer_by_d3\n" % name)
            for lab, c in (("primary", csd_p), ("all", csd_a)):
                for r in zip(*(c[n] for n in outputs.CSD_COLUMNS)):
                    f.write("%s %.9g %.6f %.6f\n" % ((lab,) + r))
        figure(os.path.join(a.dest, "fig_%s.png" % name), name, read_psd(psd), g, csd_p, csd_a, vp)
        prim = g[outputs.PRIMARY] == 1
        table.append({
            "run": name, "grains": len(prim), "primary_grains": int(prim.sum()),
            "primary_mass_percent": round(100 - vp["loose_mass_percent"], 3),
            "constrictions_primary": int(vp["constrictions"]),
            "Dc35_primary_m": "%.5g" % vp["control"],
            "percolation_primary_m": "%.5g" % vp["percolation"],
            "loose_finer_Dc35_percent": round(vp["loose_finer_control_percent"], 3),
            "loose_finer_percolation_percent": round(vp["loose_finer_percolation_percent"], 3),
            "Dc35_area_primary_m": "%.5g" % vq["control"],
            "loose_finer_Dc35_area_percent": round(vq["loose_finer_control_percent"], 3),
            "Dc35_all_m": "%.5g" % va["control"], "percolation_all_m": "%.5g" % va["percolation"],
            "kezdi_max_ratio": round(vp["kezdi_max_ratio"], 3),
            "kezdi": "stable" if vp["kezdi_max_ratio"] <= 4 else "unstable",
            "kenney_lau_min_HF": round(vp["kenney_lau_min_ratio"], 3),
            "kenney_lau": "stable" if vp["kenney_lau_min_ratio"] >= 1 else "unstable",
            "burenkova_h1": round(vp["burenkova_h1"], 3), "burenkova_h2": round(vp["burenkova_h2"], 3),
            "burenkova": "stable" if vp["burenkova_stable"] == 1 else "suffusive",
            "wan_fell_P": round(vp["wan_fell_probability"], 3),
            "wan_fell": "stable" if vp["wan_fell_probability"] <= 0.5 else "unstable",
            "wan_fell_sand_gravel_P": round(vp["wan_fell_sand_gravel_probability"], 3),
        })
        print("%-28s primary %5.1f %% by mass; Dc35 %.4g m, percolation %.4g m; loose finer: %.1f %% / %.1f %%"
              % (name, table[-1]["primary_mass_percent"], vp["control"], vp["percolation"],
                 vp["loose_finer_control_percent"], vp["loose_finer_percolation_percent"]))
    if table:
        with open(os.path.join(a.dest, "verdict.csv"), "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=list(table[0]))
            w.writeheader()
            w.writerows(table)


if __name__ == "__main__":
    main()
