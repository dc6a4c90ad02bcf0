#!/bin/bash
# Side-by-side timing, in one invocation and on 1 rank: LIGGGHTS' own route
# to a specimen (fix insert/pack at reduced radius, growth, relaxation:
# in.liggghts_route) versus fix sequential/pack building the same specimen
# (in.sequential). Same PSD, container, porosity target and material.
#
#   bench/liggghts_route/run.sh [OUTDIR]          (from anywhere)
#
# Environment (defaults in brackets):
#   EXE [build/liggghts-fabric]  PSD [input_scripts/psd/cu2.5.txt]
#   POROSITY [0.42]  SIDE [5.3] container edge in units of DMAX [1.75e-3 m]
#   PLAIN_CHUNKS [30]: also run the LIGGGHTS route without quenching, capped
#                      at this many relaxation chunks of 1000 steps (0: skip)
# Prints, per route: wall time and CPU time (user+sys) of the whole process
# (start-up included; /usr/bin/time), porosity over the container, max overlap relative to the smaller sphere of
# each pair, final kinetic energy; then the time ratio.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
cd "$root"

EXE=${EXE:-build/liggghts-fabric}
PSD=${PSD:-input_scripts/psd/cu2.5.txt}
POROSITY=${POROSITY:-0.42}
SIDE=${SIDE:-5.3}
DMAX=${DMAX:-1.75e-3}
PLAIN_CHUNKS=${PLAIN_CHUNKS:-30}
S0=0.70
OUT=${1:-out/route/run}
mkdir -p "$OUT/sequential" "$OUT/liggghts" "$OUT/liggghts_plain"

L=$(python3 -c "print('%.10g' % ($SIDE*$DMAX))")
python3 "$here/psd_intervals.py" "$PSD" 20 "$POROSITY" "$L" "$S0" \
    "$OUT/intervals.in" > "$OUT/intervals.txt"

# run DIR ARGS...: one liggghts-fabric process on 1 rank, timed
run() {
  local dir=$1; shift
  /usr/bin/time -f "%e %U %S" -o "$dir/time.txt" \
      "$EXE" "$@" -log "$dir/log.lammps" -echo none > "$dir/screen.txt" 2>&1 ||
    { echo "FAILED: $EXE $*"; tail -5 "$dir/screen.txt"; exit 1; }
}
wall() { awk '{print $1}' "$1/time.txt"; }
cpu() { awk '{print $2+$3}' "$1/time.txt"; }
field() { { grep "$2" "$1" || true; } | tail -1 | sed -n "s/.*$3 \([-0-9.eE+]*\).*/\1/p"; }

echo "container edge $L m ($SIDE x $DMAX), PSD $PSD, target porosity $POROSITY, 1 rank"
echo "$(tail -1 "$OUT/intervals.txt")"
echo "load average before: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"

# 1. fix sequential/pack
run "$OUT/sequential" -in "$here/in.sequential" -var psd "$PSD" \
    -var porosity "$POROSITY" -var L "$L" -var out "$OUT/sequential"

# 2. LIGGGHTS' route (growth, relaxation with quenching once overlaps are small)
run "$OUT/liggghts" -in "$here/in.liggghts_route" -var inc "$OUT/intervals.in" \
    -var L "$L" -var target "$POROSITY" -var s0 "$S0" -var out "$OUT/liggghts"

# 3. optional: the same route with the contact damping alone (capped)
if [ "$PLAIN_CHUNKS" -gt 0 ]; then
  run "$OUT/liggghts_plain" -in "$here/in.liggghts_route" \
      -var inc "$OUT/intervals.in" -var L "$L" -var target "$POROSITY" -var s0 "$S0" \
      -var out "$OUT/liggghts_plain" -var quench 0 -var chunk 1000 -var maxchunks "$PLAIN_CHUNKS"
fi

report() {  # name dir
  local a ke steps capped phases
  a=$(/usr/bin/python3 "$here/analyse.py" "$2/specimen.dump" "$L" 64)
  ke=$(field "$2/screen.txt" "ROUTE final" "KE")
  steps=$(field "$2/screen.txt" "ROUTE final" "step")
  capped=""
  grep -q "ROUTE CAPPED" "$2/screen.txt" 2>/dev/null && capped=" CAPPED"
  printf "%-28s %8.2f s %8.2f s  %s" "$1" "$(wall "$2")" "$(cpu "$2")" "$a"
  [ -n "$ke" ] && printf "  KE=%.3g J  steps=%s%s" "$ke" "$steps" "$capped"
  printf "\n"
  if [ -f "$2/phases.txt" ]; then
    phases=$(awk -F= '{t[$1]=$2} END {printf "insert %.2f s, grow %.2f s, relax %.2f s", t["inserted"]-t["start"], t["grown"]-t["inserted"], t["relaxed"]-t["grown"]}' "$2/phases.txt")
    echo "                             phases: $phases"
  fi
}

echo
echo "route                            wall      CPU  specimen (analyse.py: porosity over the container, central eighth, max/mean relative pair overlap, pairs > 1 %, wall overlap, contacts per sphere)"
report "fix sequential/pack" "$OUT/sequential"
grep "porosity: target\|time:" "$OUT/sequential/screen.txt" | sed 's/^ */                             fix: /'
report "LIGGGHTS insert+grow+relax" "$OUT/liggghts"
if [ "$PLAIN_CHUNKS" -gt 0 ]; then
  report "  same, no quench (capped)" "$OUT/liggghts_plain"
fi
echo
printf "time ratio LIGGGHTS route / sequential/pack: wall %.1f, CPU %.1f\n" \
    "$(echo "$(wall "$OUT/liggghts") / $(wall "$OUT/sequential")" | bc -l)" \
    "$(echo "$(cpu "$OUT/liggghts") / $(cpu "$OUT/sequential")" | bc -l)"
echo "load average after: $(cut -d' ' -f1-3 /proc/loadavg)"
echo "logs and specimens under $OUT"
