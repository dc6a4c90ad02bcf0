#!/bin/bash
# Installs, from Debian 12's packages, whatever the project needs and this
# machine lacks. Needs root (or sudo) and apt. With --render also ParaView
# (pvpython, for tools/render_fabric.py; about 450 MB, so not by default).
set -euo pipefail
packages=(liggghts libliggghts-dev liggghts-doc libopenmpi-dev openmpi-bin
          libeigen3-dev libgtest-dev cmake g++ make python3-numpy
          python3-matplotlib python3-scipy xvfb libcgal-dev)
if [ "${1:-}" = "--render" ]; then
  packages+=(paraview)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg -s "$p" >/dev/null 2>&1 || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  sudo=""; [ "$(id -u)" -ne 0 ] && sudo="sudo"
  echo "installing: ${missing[*]}"
  $sudo apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq "${missing[@]}" >/dev/null
fi
