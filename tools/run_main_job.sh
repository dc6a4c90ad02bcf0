#!/bin/bash
# The main job: install what is missing, build, and run the default scene on
# 2 MPI ranks: pack a Cu = 2.5 specimen with fix sequential/pack, print its
# summary, and write dumps for ParaView into out/pack/.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh
bash tools/build.sh
root=""; [ "$(id -u)" -eq 0 ] && root="--allow-run-as-root"
mkdir -p out
mpirun $root -np 2 build/liggghts-fabric -in input_scripts/in.pack -log out/pack.log "$@"
echo "dumps: out/pack/specimen.dump (text), out/pack/specimen_0.vtk (ParaView)"
