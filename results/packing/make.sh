#!/bin/bash
# Regenerates results/packing from scratch. Run from the repository root:
#   bash results/packing/make.sh [pack_range] [layerwise] [random_reference]
# (no argument: all three; random_reference takes about 70 minutes, the
# others a few minutes on one core). The packers' wall times in the text
# files move with the machine's load; everything else is deterministic.
set -euo pipefail
cd "$(dirname "$0")/../.."
py=/usr/bin/python3
P=build/bench/pack_range
S="input_scripts/psd/cu2.0.txt input_scripts/psd/cu2.5.txt input_scripts/psd/cu3.0.txt input_scripts/psd/cu3.5.txt"
parts="${*:-pack_range layerwise random_reference}"
cmake --build build --target pack_range > /dev/null
if [[ " $parts " == *" pack_range "* ]]; then
  $P $S --targets 0.33,0.34,0.35,0.36,0.38,0.40,0.42,0.45 --rules discrete \
      > results/packing/pack_range/targets_8_all_soils_side6_seed1.txt
  $P input_scripts/psd/cu2.0.txt input_scripts/psd/cu2.5.txt --rules discrete \
      > results/packing/pack_range/grid_cu2.0_cu2.5_side6_seed1.txt
  $P $S --targets 0.25,0.35 --rules layerwise > results/packing/pack_range/layerwise_side6_seed1.txt
fi
if [[ " $parts " == *" layerwise "* ]]; then
  $P $S tests/unit/data/gap_graded.txt tests/unit/data/broad_cu6.txt \
      --side 6 --targets 0.35 --no-full --profile 6 > results/packing/layerwise/side6_seed1.txt
  $P input_scripts/psd/cu2.0.txt --side 8 --targets 0.35 --no-full --profile 8 \
      > results/packing/layerwise/cu2.0_side8_seed1.txt
  $P input_scripts/psd/cu2.0.txt --targets 0.35,0.36,0.37,0.38,0.40 --rules layerwise --profile 6 \
      > results/packing/layerwise/cu2.0_targets_side6_seed1.txt
fi
if [[ " $parts " == *" random_reference "* ]]; then
  # one folder for every soil: the bench gathers OUT/assortativity.csv
  $py bench/random_reference/run.py --soils cu2.0 --side 6 --out out/random_reference
  $py bench/random_reference/run.py --soils cu2.5 --side 5 --out out/random_reference
  $py bench/random_reference/run.py --soils cu3.0 --side 4 --phi 0.76 --out out/random_reference
  cp out/random_reference/assortativity.csv results/packing/random_reference/random_reference.csv
fi
