#!/bin/sh
# froth against Surface Evolver (Debian's evolver-nox: apt-get install evolver-nox) on two
# problems with exact answers; see docs/benchmarks.md "Surface Evolver". Usage, from the
# repository root:  sh bench/evolver/run.sh [path/to/froth]   (about 1 minute)
set -e
FROTH=${1:-build/froth}
DIR=$(dirname "$0")
command -v evolver >/dev/null || { echo "run.sh: no evolver (apt-get install evolver-nox)"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

echo "== Double bubble, volumes (1, 1), from two unit cubes: area error against 3 (9 pi)^(1/3)"
echo "Evolver  level  vertices  seconds (cumulative)  area  error"
evolver -x -f "$DIR/double_bubble.cmd" "$DIR/two_cubes.fe" | grep '^EVOLVER'
"$FROTH" "$DIR/double_bubble.lua"

echo
echo "== Mean curvature flow of a sphere to t = 0.05: R(t) against sqrt(R0^2 - 4t)"
echo "Evolver  vertices  steps  seconds  R  exact  error  R0   (one line per scale)"
for scale in 1e-4 2e-4 3e-4; do
  echo "scale $scale:"
  sed "s/SCALE/$scale/g" "$DIR/sphere_mcf.cmd" > "$TMP/mcf.cmd"
  evolver -x -f "$TMP/mcf.cmd" "$DIR/cube.fe" | grep '^EVMCF'
done
"$FROTH" "$DIR/sphere_mcf.lua"
