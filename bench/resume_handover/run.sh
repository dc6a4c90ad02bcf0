#!/bin/bash
# A resumed job against the run without a checkpoint: how much of the lid's
# load the hand-over to LIGGGHTS' servo keeps (results/rest/resume_handover).
# Cu 3.5 DA, side 3.3, the scene's defaults (Hertz quartz, 100 kPa), seed 1,
# one rank: a job ends after 2 blocks (4,000 steps, the lid still rising),
# and the next block (to 6,000) is run three ways from that checkpoint:
#   restored  - the scene's hand-over (the servo's integral put back)
#   zero      - the integral restarted from zero (checkpoint.in's lid speed
#               and stress error set to 0)
#   whole     - no checkpoint: one job of 3 blocks
# Usage, from the repository root: bash bench/resume_handover/run.sh [OUT]
# (OUT defaults to out/resume_handover); writes OUT/blocks.csv.
set -e
OUT=${1:-out/resume_handover}
SCENE=input_scripts/in.oedometer
LMP=build/liggghts-fabric
ARGS="-var psd input_scripts/psd/cu3.5.txt -var side 3.3"
rm -rf "$OUT" && mkdir -p "$OUT"
cp "$SCENE" "$OUT/in.oedometer"   # LIGGGHTS reads its script as it goes
S="$OUT/in.oedometer"
echo "first job: 2 blocks, then a checkpoint"
$LMP -in $S $ARGS -var out "$OUT/split" -var checkpoint 2 > "$OUT/split.log"
cp -r "$OUT/split" "$OUT/restored"
cp -r "$OUT/split" "$OUT/zero"
sed -i 's/^variable lid_v_ck .*/variable lid_v_ck equal 0/; s/^variable e_ck .*/variable e_ck equal 0/' "$OUT/zero/checkpoint.in"
for k in restored zero; do
  echo "resumed ($k): one block"
  $LMP -in $S $ARGS -var out "$OUT/$k" -var checkpoint 1 -var resume 1 > "$OUT/$k.log"
done
echo "without a checkpoint: 3 blocks"
$LMP -in $S $ARGS -var out "$OUT/whole" -var checkpoint 3 > "$OUT/whole.log"
/usr/bin/python3 tools/series_csv.py --from 4000 whole="$OUT/whole/fabric_series.txt" \
    restored="$OUT/restored/fabric_series.txt" zero="$OUT/zero/fabric_series.txt" > "$OUT/blocks.csv"
cat "$OUT/blocks.csv"
