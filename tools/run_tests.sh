#!/bin/bash
# Builds and runs every test: the unit tests of the cores and the scene tests
# that run LIGGGHTS through the launcher (on 1, 2 and 4 MPI ranks).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh
bash tools/build.sh
cd build && ctest --output-on-failure -j1
