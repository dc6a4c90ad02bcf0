#!/bin/bash
# Builds and runs every test: the unit tests of the cores and the scene tests
# that run LIGGGHTS through the launcher (on 1, 2 and 4 MPI ranks), label by
# label (tests/CMakeLists.txt): unit, specimen, scene, study, examples.
# Prints each label's wall time at the end. JOBS (default 2) tests run at a
# time; each test has its own work folder. One label only: ctest -L LABEL in
# build/.
set -uo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh || exit 1
bash tools/build.sh || exit 1
cd build || exit 1
jobs=${JOBS:-2}
status=0
summary=""
for label in unit specimen scene study examples; do
  start=$(date +%s)
  ctest -L "^${label}\$" --output-on-failure -j"$jobs" || status=1
  summary+=$(printf '\n  %-9s %5d s' "$label" $(( $(date +%s) - start )))
done
# every test carries one of the labels above (a test without one would be skipped)
unlabelled=$(ctest -N -LE '^(unit|specimen|scene|study|examples)$' | grep -c '^ *Test *#' || true)
if [ "$unlabelled" != "0" ]; then
  echo "tests without a label: $unlabelled (tests/CMakeLists.txt)"; status=1
fi
echo "wall time per label (ctest -j$jobs):$summary"
exit $status
