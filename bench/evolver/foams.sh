#!/bin/sh
# Kelvin and Weaire-Phelan: Surface Evolver's shipped twointor.fe and phelanc.fe against
# froth.kelvin_foam and froth.weaire_phelan_foam (docs/benchmarks.md "Foams"). From the
# repository root:  sh bench/evolver/foams.sh [path/to/froth]   (about 7 minutes)
# froth runs twice: the plain steps, then with Newton's steps (c:minimize{hessian = true}).
set -e
FROTH=${1:-build/froth}
DIR=$(dirname "$0")
EX=/usr/share/doc/evolver/examples
command -v evolver >/dev/null || { echo "foams.sh: no evolver (apt-get install evolver-nox evolver-doc)"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
echo "Evolver  level  vertices  seconds (cumulative)  cost"
sed "s/NCELLS/2/g; s/BOXVOLUME/1/g" "$DIR/foams.cmd" > "$TMP/kelvin.cmd"
evolver -x -f "$TMP/kelvin.cmd" "$EX/twointor.fe" | grep '^EVFOAM' | sed 's/^/kelvin /'
sed "s/NCELLS/8/g; s/BOXVOLUME/8/g" "$DIR/foams.cmd" > "$TMP/wp.cmd"
evolver -x -f "$TMP/wp.cmd" "$EX/phelanc.fe" | grep '^EVFOAM' | sed 's/^/weaire_phelan /'
"$FROTH" "$DIR/../bench_foams.lua" h=0.3,0.15,0.08,0.04
"$FROTH" "$DIR/../bench_foams.lua" h=0.3,0.15,0.08,0.04 hessian=1
