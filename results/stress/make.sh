#!/bin/bash
# Regenerates results/stress from scratch: Cu 2.0 and 2.5, both rules,
# seeds 1-3, at 10 kPa-1 MPa, Hertz quartz under the former kinetic-energy
# rule (zeta 0.6, rest_tol 0, dt_gain 1), side 7.7, one rank per run.
# Run from the repository root. About 14 core-hours.
set -euo pipefail
cd "$(dirname "$0")/../.."
py=/usr/bin/python3
E="zeta=0.6 rest_tol=0 dt_gain=1"
args=()
for S in 1e4 3e4 1e5 3e5 1e6; do
  extra=""
  [ "$S" = 1e6 ] && extra="ramp=0.03"
  $py tools/oedometer_study.py --sides 7.7 --soils cu2.0 cu2.5 --rules discrete layerwise \
      --seeds 1 2 3 --jobs 2 --ranks 1 --var $E stress=$S $extra --out out/stress/s$S
  args+=("$S=out/stress/s$S")
done
$py tools/stress_curve.py "${args[@]}" \
    --linear results/paper/da_side7.7.csv results/paper/la_side7.7.csv --kappa 1963 \
    --soils cu2.0 cu2.5 --out results/stress
# the ramp at 1 MPa: Cu 2.0 DA seed 1 without it, Cu 2.5 DA seed 1 twice as long
$py tools/oedometer_study.py --sides 7.7 --soils cu2.0 --rules discrete --seeds 1 --jobs 1 \
    --ranks 1 --var $E stress=1e6 --out out/stress/ramp0
$py tools/oedometer_study.py --sides 7.7 --soils cu2.5 --rules discrete --seeds 1 --jobs 1 \
    --ranks 1 --var $E stress=1e6 ramp=0.06 --out out/stress/ramp06
{ echo "stress_Pa,ramp_s,$(head -1 out/stress/ramp0/study.csv)"
  tail -n +2 out/stress/ramp0/study.csv | sed 's/^/1e6,0,/'
  grep -h "^DA_cu2.0_side7.7_seed1," out/stress/s1e6/study.csv | sed 's/^/1e6,0.03,/'
  grep -h "^DA_cu2.5_side7.7_seed1," out/stress/s1e6/study.csv | sed 's/^/1e6,0.03,/'
  tail -n +2 out/stress/ramp06/study.csv | sed 's/^/1e6,0.06,/'; } > results/stress/ramp_check.csv
