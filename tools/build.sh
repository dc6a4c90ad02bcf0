#!/bin/bash
# Configures and builds into build/ (the plugin library, build/liggghts-fabric,
# the tests and the benchmark).
set -euo pipefail
cd "$(dirname "$0")/.."
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build build -j"$(nproc)"
