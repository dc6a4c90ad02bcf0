#!/bin/bash
# The main job: install what is missing, build, and run the oedometer scene on
# 2 MPI ranks at its defaults, the recommended setting of docs/user_guide.md:
# Hertz-Mindlin contacts of quartz (E 70 GPa, Poisson 0.25) at 100 kPa, side
# 7.7 (53,237 grains, where the answer has stopped moving with size).
# fix sequential/pack builds a Cu = 2.5 specimen, a servo lid compresses it
# without gravity to 100 kPa until the grains are at rest, and compute
# primary/fabric tells which grains carry the load. Arguments are passed on
# to LIGGGHTS and come first (e.g. -var side 3.3 for a quick look at 4,188
# grains in about a minute, -var stress 3e5 for another stress). Outputs
# (time series, per-interval table, VTK dumps for ParaView) go to
# out/oedometer/, the paper's figures as PNG to out/oedometer/ too.
# The filter keeps the scene's own lines and WARNINGs; LIGGGHTS' notes on its
# unoptimised contact models (epsd3, measured no slower: docs/benchmarks.md)
# and thermo_style changes are in out/oedometer.log.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/install_deps.sh
bash tools/build.sh
root=""; [ "$(id -u)" -eq 0 ] && root="--allow-run-as-root"
mkdir -p out
mpirun $root -np 2 build/liggghts-fabric -in input_scripts/in.oedometer -log out/oedometer.log "$@" \
  | grep --line-buffered -E "^(psd_info|MATERIAL|STIFFNESS|BEFORE LOADING|TIMESTEP|DAMPING|SERVO|KE LIMIT|LOADED|RELOAD|STOP|LID|FABRIC|WARNING)|fix sequential/pack|particles:|porosity by volume:|packed full|^ +Step +t_load|^ +[0-9]+ +[0-9.e+-]+ +[0-9.e+-]+ " \
  | awk '/^WARNING: *$/ || /\(\.\/src\// { next } /^ +Step +t_load/ { if (seen[$0]++) next } { print; fflush() }'
/usr/bin/python3 tools/plot_fabric.py out/oedometer
echo "ParaView: out/oedometer/grains_*.vtk (colour by c_pf[2]: 1 primary fabric, 0 loose), out/oedometer/contacts_*.vtp"
