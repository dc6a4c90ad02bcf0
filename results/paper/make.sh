#!/bin/bash
# Regenerates results/paper from scratch: the eight models at the paper's
# kind of contacts (linear springs, kappa 1963) under the former
# kinetic-energy rule (rest_tol 0, zeta 1 of the linear model), side 7.7,
# seeds 1-3. Run from the repository root. About 25 core-hours (LA Cu 3.5:
# about 2.7 hours a seed on 2 ranks, in jobs of 10 blocks).
set -euo pipefail
cd "$(dirname "$0")/../.."
py=/usr/bin/python3
K="kappa=1963 overlap_max=0.2"
$py tools/oedometer_study.py --sides 7.7 --soils cu2.0 cu2.5 cu3.0 --rules discrete \
    --seeds 1 2 3 --jobs 2 --ranks 1 --var $K --out out/paper_da
$py tools/oedometer_study.py --sides 7.7 --soils cu3.5 --rules discrete \
    --seeds 1 2 3 --jobs 2 --ranks 1 --var $K ke_vrms=4e-4 checkpoint=10 --out out/paper_da
$py tools/oedometer_study.py --sides 7.7 --soils cu2.0 cu2.5 cu3.0 --rules layerwise \
    --seeds 1 2 3 --jobs 2 --ranks 1 --var $K --out out/paper_la
$py tools/oedometer_study.py --sides 7.7 --soils cu3.5 --rules layerwise \
    --seeds 1 2 3 --jobs 1 --ranks 2 --var $K ke_vrms=4e-4 kp=0.1 checkpoint=10 --out out/paper_la
cp out/paper_da/study.csv results/paper/da_side7.7.csv
cp out/paper_la/study.csv results/paper/la_side7.7.csv
$py tools/validation_report.py --study out/paper_da out/paper_la --side 7.7 \
    --label kappa1963_converged --out results/paper \
    --matrix results/paper/da_side7.7.csv results/paper/la_side7.7.csv
# ranks
$py tools/oedometer_study.py --sides 7.7 --soils cu2.0 cu2.5 --rules discrete --seeds 1 \
    --jobs 1 --ranks 2 --var $K --out out/paper_r2
$py tools/oedometer_study.py --sides 7.7 --soils cu2.0 --rules discrete --seeds 1 \
    --jobs 1 --ranks 4 --var $K --out out/paper_r4
cat out/paper_r2/study.csv > results/paper/kappa1963_side7.7_ranks.csv
tail -n +2 out/paper_r4/study.csv >> results/paper/kappa1963_side7.7_ranks.csv
# by height (one call per study: --csv writes its rows)
$py tools/fabric_layers.py out/paper_la/runs/LA_cu2.0_side7.7_seed1 out/paper_la/runs/LA_cu2.5_side7.7_seed1 \
    out/paper_da/runs/DA_cu2.0_side7.7_seed1 out/paper_da/runs/DA_cu2.5_side7.7_seed1 \
    out/paper_la/runs/LA_cu3.5_side7.7_seed*_ranks2 --slices 8 --csv results/paper/fabric_by_height.csv
# porosity 0.38
$py tools/oedometer_study.py --sides 7.7 --soils cu2.0 --rules layerwise discrete \
    --seeds 1 2 3 --jobs 1 --ranks 1 --var $K porosity=0.38 --out out/paper_n038
cp out/paper_n038/study.csv results/paper/cu2.0_porosity0.38.csv
$py tools/fabric_layers.py out/paper_n038/runs/*_seed1 --slices 8 \
    --csv results/paper/fabric_by_height_cu2.0_porosity0.38.csv
# Figs. 13 and 19 for the three finest intervals and the coarsest
$py - <<'PY'
import csv, glob, os, sys
sys.path.insert(0, "tools")
import outputs
runs = [("0.35", r) for r in sorted(glob.glob("out/paper_la/runs/LA_cu2.[05]_side7.7_seed*"))
        + sorted(glob.glob("out/paper_da/runs/DA_cu2.[05]_side7.7_seed1"))]
runs += [("0.38", r) for r in sorted(glob.glob("out/paper_n038/runs/*"))]
with open("results/paper/fines_contacts.csv", "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["run", "porosity", "interval", "diameter_mm",
                "loaded_contacts_per_particle", "primary_pct_of_interval"])
    for porosity, run in runs:
        t = outputs.read_intervals(os.path.join(run, "fabric_intervals.txt"))
        n = len(t["diameter"])
        for i in [0, 1, 2, n - 1]:
            w.writerow([os.path.basename(run), porosity, i + 1, "%.4f" % (1e3 * t["diameter"][i]),
                        "%.3f" % t["loaded_contacts_per_particle"][i],
                        "%.2f" % t["primary_percent_of_interval"][i]])
PY
# the stiffness number (side 5.5, DA) and the size at kappa 1963
st() { $py tools/oedometer_study.py --ranks 1 --jobs 2 "$@"; }
st --sides 5.5 --soils cu2.0 --rules discrete --seeds 1 2 3 --var kn=2e7 --out out/paper_kn_cu20
st --sides 5.5 --soils cu2.5 --rules discrete --seeds 1 2 3 --var kn=2e7 --out out/paper_kn_cu25
st --sides 5.5 --soils cu3.0 --rules discrete --seeds 1 2 3 --var kn=2e7 --out out/paper_kn_cu30
st --sides 5.5 --soils cu3.5 --rules discrete --seeds 1 2 3 --var kn=2e7 ke_vrms=4e-4 --out out/paper_kn_cu35
st --sides 5.5 --soils cu2.0 cu2.5 cu3.0 --rules discrete --seeds 1 --var kappa=19630 overlap_max=0.2 --out out/paper_k19630
st --sides 5.5 --soils cu2.0 cu2.5 cu3.0 --rules discrete --seeds 1 2 3 --var $K dtfac=0.2 --out out/paper_k1963_dt02
cp out/paper_kn_cu20/study.csv results/paper/stiffness/kn2e7_side5.5_cu2.0.csv
cp out/paper_kn_cu25/study.csv results/paper/stiffness/kn2e7_side5.5_cu2.5_da.csv
cp out/paper_kn_cu30/study.csv results/paper/stiffness/kn2e7_side5.5_cu3.0.csv
cp out/paper_kn_cu35/study.csv results/paper/stiffness/kn2e7_side5.5_cu3.5_ke4e-4.csv
cp out/paper_k19630/study.csv results/paper/stiffness/kappa19630_side5.5.csv
cp out/paper_k1963_dt02/study.csv results/paper/stiffness/kappa1963_side5.5_dtfac0.2.csv
st --sides 3.3 --soils cu2.0 cu2.5 --rules discrete --seeds 1 2 3 --var $K --out out/paper_s33
st --sides 5.5 --soils cu2.0 cu2.5 cu3.0 --rules discrete --seeds 1 2 3 --var $K --out out/paper_s55
st --sides 5.5 --soils cu3.5 --rules discrete --seeds 1 2 3 --var $K ke_vrms=4e-4 --out out/paper_s55_cu35
st --sides 9.9 --soils cu2.0 --rules discrete --seeds 1 2 3 --var $K --out out/paper_s99
st --sides 9.9 --soils cu2.5 --rules discrete --seeds 1 2 3 --var $K --out out/paper_s99_cu25
cp out/paper_s33/study.csv results/paper/size/kappa1963_side3.3.csv
cp out/paper_s55/study.csv results/paper/size/kappa1963_side5.5.csv
cp out/paper_s55_cu35/study.csv results/paper/size/kappa1963_side5.5_cu3.5_ke4e-4.csv
cp out/paper_s99/study.csv results/paper/size/kappa1963_side9.9.csv
cp out/paper_s99_cu25/study.csv results/paper/size/kappa1963_side9.9_cu2.5.csv
