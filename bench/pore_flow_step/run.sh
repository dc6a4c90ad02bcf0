#!/bin/bash
# Prints the cost of one solve of fix pore/flow in DEM steps on the same
# specimen (about 1e4 grains at side 4): (loop time with the flow solved
# twice in the run - loop time without) / 2, against the time per step
# without it. The solve at the run's setup is outside the loop time. Run
# from the repository root; NP=2 runs both on 2 MPI ranks, LAUNCHER=path
# another build of liggghts-fabric.
set -euo pipefail
steps=${STEPS:-200}
side=${SIDE:-4.0}
np=${NP:-1}
bin=${LAUNCHER:-build/liggghts-fabric}
launch=("$bin")
[ "$np" -gt 1 ] && launch=(mpirun --allow-run-as-root --oversubscribe -np "$np" "$bin")
run() { "${launch[@]}" -in bench/pore_flow_step/in.pore_flow_step -log none -var every "$1" \
          -var steps "$steps" -var side "$side" \
        | awk '/^Loop time of/ {t=$4; for (i=1;i<NF;i++) if ($(i+1) ~ /^atoms/) n=$i} END {print t, n}'; }
read -r t0 n <<<"$(run 0)"
read -r t1 _ <<<"$(run $((steps / 2)))"
awk -v t0="$t0" -v t1="$t1" -v n="$n" -v s="$steps" -v p="$np" 'BEGIN {
  step = t0 / s; solve = (t1 - t0) / 2;
  printf "atoms %d on %d rank(s), %d steps: %.3f s without the flow, %.3f s with 2 solves\n", n, p, s, t0, t1;
  printf "one DEM step: %.3g s; one solve: %.3g s = %.0f DEM steps\n", step, solve, solve / step;
  for (k = 100; k <= 10000; k *= 10)
    printf "solved every %5d steps: %.0f %% of the run\n", k, 100 * solve / (k * step + solve);
}'
