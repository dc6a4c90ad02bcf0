#!/bin/bash
# Prints the cost of one evaluation of compute primary/fabric in DEM steps:
# (time with the compute every step - time without) / evaluations,
# divided by the time per step without it. Run from the repository root.
set -euo pipefail
steps=${STEPS:-2000}
run() { build/liggghts-fabric -in bench/compute_cost/in.compute_cost -log none -var every "$1" -var steps "$steps" \
        | awk '/^Loop time of/ {t=$4; for (i=1;i<NF;i++) if ($(i+1) ~ /^atoms/) n=$i} END {print t, n}'; }
read -r t0 n <<<"$(run 0)"
read -r t1 _ <<<"$(run 1)"
evals=$steps
awk -v t0="$t0" -v t1="$t1" -v n="$n" -v s="$steps" -v e="$evals" 'BEGIN {
  step = t0 / s; eval = (t1 - t0) / e;
  printf "atoms %d, %d steps: %.3f s without, %.3f s with an evaluation every step\n", n, s, t0, t1;
  printf "one DEM step: %.3g s (%.3f us per particle-step)\n", step, 1e6 * step / n;
  printf "one evaluation: %.3g s = %.2f DEM steps\n", eval, eval / step;
  for (k = 100; k <= 10000; k *= 10)
    printf "evaluated every %5d steps: %.2f %% of the run\n", k, 100 * eval / (k * step + eval);
}'
