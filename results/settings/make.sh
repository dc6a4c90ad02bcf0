#!/bin/bash
# Regenerates results/settings from scratch (Hertz quartz, 100 kPa, the
# former kinetic-energy rule: zeta 0.6, rest_tol 0, dt_gain 1). Run from
# the repository root. About 12 core-hours.
set -euo pipefail
cd "$(dirname "$0")/../.."
py=/usr/bin/python3
E="zeta=0.6 rest_tol=0 dt_gain=1"
# the chart: each factor moved alone (bench/oedometer_chart/run.py names them)
$py bench/oedometer_chart/run.py --set quartz --jobs 2 --out results/settings/chart --runs out/settings_chart
# the contact law and the step
$py tools/oedometer_study.py --sides 7.7 --soils cu2.5 --rules discrete --seeds 1 2 3 --jobs 2 \
    --ranks 1 --var $E --out out/settings_hertz
cp out/settings_hertz/study.csv results/settings/contacts/hertz_cu2.5_side7.7.csv
$py tools/oedometer_study.py --sides 7.7 --soils cu2.5 --rules discrete --seeds 1 2 3 --jobs 2 \
    --ranks 1 --var $E kappa=3957 overlap_max=0.2 --out out/settings_k3957
cp out/settings_k3957/study.csv results/settings/contacts/linear_kappa3957_cu2.5_side7.7.csv
$py tools/oedometer_study.py --sides 7.7 --soils cu2.0 --rules discrete --seeds 1 2 3 --jobs 2 \
    --ranks 1 --var $E --out out/settings_dt04
$py tools/oedometer_study.py --sides 7.7 --soils cu2.0 --rules discrete --seeds 1 2 3 --jobs 2 \
    --ranks 1 --var $E dtfac=0.2 --out out/settings_dt02
{ cat out/settings_dt04/study.csv; tail -n +2 out/settings_dt02/study.csv; } \
    > results/settings/contacts/dtfac_cu2.0_side7.7.csv
# the specimen size
$py tools/oedometer_study.py --sides 3.3 --soils cu2.0 cu2.5 --rules discrete layerwise \
    --seeds 1 2 3 --jobs 2 --ranks 1 --var $E --out out/settings_side3.3
cp out/settings_side3.3/study.csv results/settings/size/quick_look_side3.3.csv
$py tools/oedometer_study.py --sides 9.9 --soils cu2.0 --rules discrete layerwise \
    --seeds 1 2 3 --jobs 2 --ranks 1 --var $E --out out/settings_side9.9
cp out/settings_side9.9/study.csv results/settings/size/hertz_side9.9.csv
