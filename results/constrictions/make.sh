#!/bin/bash
# Regenerates results/constrictions from scratch. Run from the repository
# root, after the studies it reads: out/paper_da and out/paper_la
# (results/paper/make.sh) and out/models_energy_rule
# (MODELS_ENERGY_RULE=1 bash results/models/make.sh).
set -euo pipefail
cd "$(dirname "$0")/../.."
py=/usr/bin/python3
# the cost of one CSD at 1e4-1e6 grains (the packer's specimens, Cu 2.5)
cmake --build build --target constriction_bench
build/bench/constriction_bench input_scripts/psd/cu2.5.txt 1e6 > results/constrictions/bench_cu2.5.txt
# the verdict of each run (one rank; each writes verdict.csv rows and fig_RUN.png)
for study in out/paper_da out/paper_la; do
  $py tools/constriction_verdict.py --study $study --dest out/verdict_$(basename $study)
done
mkdir -p results/constrictions/side7.7
{ head -1 out/verdict_paper_da/verdict.csv; tail -qn +2 out/verdict_paper_da/verdict.csv out/verdict_paper_la/verdict.csv; } \
    > results/constrictions/side7.7/verdict.csv
cp out/verdict_paper_da/fig_*seed1*.png out/verdict_paper_la/fig_*.png results/constrictions/side7.7/
$py tools/constriction_verdict.py --study out/models_energy_rule --dest results/constrictions/hertz_side7.7
