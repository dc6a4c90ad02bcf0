#!/bin/bash
# Layer-wise Cu 3.5 at the scene's defaults (Hertz quartz, 100 kPa,
# ke_vrms 4e-4), side 5 (118,923 grains), seed 1, one rank: one job to the
# stop against jobs of 10,000 steps that each go on from the last one's
# checkpoint (results/rest/resume_handover). The two runs are identical to the
# first checkpoint (one rank, same seed), so the block after each resume is
# compared with the same block of the uninterrupted run. One run per core,
# about 1.5 hours on 2 cores. Resumable: given again, each study goes on.
# Usage, from the repository root: bash bench/resume_handover/la35_side5.sh [OUT]
# (OUT defaults to out/resume_la35); writes OUT/la35_side5.csv.
set -e
OUT=${1:-out/resume_la35}
mkdir -p "$OUT"
STUDY="/usr/bin/python3 tools/oedometer_study.py --sides 5 --soils cu3.5 --rules layerwise --seeds 1 --jobs 1 --ranks 1"
$STUDY --var ke_vrms=4e-4 --out "$OUT/whole" > "$OUT/whole.log" 2>&1 &
$STUDY --var ke_vrms=4e-4 checkpoint=5 --out "$OUT/jobs" > "$OUT/jobs.log" 2>&1
wait
/usr/bin/python3 tools/series_csv.py whole="$OUT/whole/runs/LA_cu3.5_side5_seed1/fabric_series.txt" \
    jobs="$OUT/jobs/runs/LA_cu3.5_side5_seed1/fabric_series.txt" > "$OUT/la35_side5.csv"
tail -n 4 "$OUT/whole.log" "$OUT/jobs.log"
