#!/bin/bash
# Statics benchmark: froth's c:minimize{} against Surface Evolver (Debian's evolver-nox 2.70:
# apt-get install evolver-nox) on three static equilibria at fixed volumes, both timed as whole
# processes (startup, meshing and output included), best of REPEAT (default 3) runs. For each
# problem and target relative area error (1e-3, 3e-4, 1e-4) each program runs at the cheapest
# resolution that reaches the target, and one table row gives vertices, seconds and achieved
# error of each, the ratio of the seconds froth / Evolver, and froth's volume error (Evolver
# holds its volumes as constraints, to about 1e-12). Not part of CI. Usage, from the repository
# root (a few minutes; one process at a time):
#   bash bench/evolver/statics.sh [path/to/froth]          (default build/froth)
#   REPEAT=5 bash bench/evolver/statics.sh build/froth
#   bash bench/evolver/statics.sh build/froth --reference  (also re-derives the references, ~1 min)
# FROTH_LUA_DIR defaults to the repository's lua/ (a froth binary outside the build tree needs it).
#
# Problems (files beside this script):
#   db11    two unit cubes (two_cubes.fe; froth.fragment of the same boxes), volumes (1, 1):
#           the standard double bubble, exact area 3 (9 pi)^(1/3) = 9.1394216780693.
#   db12    the same cubes at volumes (1, 2) (Evolver `set body[2] target 2` before refining,
#           froth c:set_volume(2, 2)): the standard double bubble of (1, 2), exact area
#           11.8542931280002 (double_bubble_exact.lua has the derivation and the (1, 1) check).
#   triple  three cells of volume 1 (three_cells.fe): the unit cubes [0,1]^3, [1,2]x[0,1]x[0,1]
#           and the slab [0,2]x[0,1]x[1,1.5] on them; each touches the other two (4 triple
#           lines, 2 quadruple points, as the standard triple bubble). No closed form; reference
#           13.1281682, Richardson-extrapolated from Evolver's levels 5 and 6 (below).
#
# References. Evolver's level-L areas A_L converge as h^2 (successive differences fall by 4.0),
# so (4 A_6 - A_5) / 3 removes the leading error. With this script's Evolver schedule that
# gives 9.1394216014 and 11.8542930006 for db11 and db12 (relative errors -8e-9 and -1.1e-8
# against the exact areas, where A_6 itself is 1.1e-5 and 1.2e-5 too high), and for triple
# A_5 = 13.1286535202431, A_6 = 13.1282894768364 (155332 vertices; two more Hessian steps
# change it by 1e-14), extrapolated 13.1281681290; another schedule (`r; u; g 10;
# hessian_seek; hessian; hessian` per level) gives A_6 = 13.1282913281303 and 13.1281683568.
# Reference: 13.1281682, uncertain by about 2e-8 relative. (A_6 itself would bias every
# error by -9e-6, 9% of the 1e-4 target.) Printed by --reference, which runs
#   statics.cmd with LEVELS = 6, STEP = "r; u; V; g 3; hessian".
#
# Evolver: statics.cmd, 200 conjugate gradient steps on the unrefined cells, then per level
# one of the schedules in EV_STEPS; the script runs each schedule once to level EV_MAX (5),
# takes the lowest level whose area reaches the target, times processes that stop at that
# level, and keeps the faster schedule. Tried while choosing (noisy timings, under load):
#   "r; g 30; hessian; hessian" (run.sh's): 3-4x slower at level 5, no better per level;
#     on the triple it diverges (Hessian not positive definite) without the initial g 200.
#   "r; g 5; hessian; hessian", "r; u; g 10; hessian_seek; hessian", "r; u; V; hessian;
#     hessian" and two Hessian steps instead of one: no faster; one Hessian step per level
#     after 3 g steps has converged (a second moves the area by < 1e-9 relative).
# Fewer g steps before the Hessian leave worse meshes (hessian moves vertices only normally),
# so the level-L area depends on the schedule: levels 3, 4, 5 reach 1e-3, 3e-4, 1e-4 here.
#
# froth: statics_froth.lua problem=P h=H tol=T, c:minimize{tol = T} on the gmsh mesh of size H.
# (h, tol) per target, chosen by a search (h in 0.14 .. 0.03, tol in 1e-1, 3e-2, 1e-2, 3e-3;
# statics_froth.lua takes comma lists): the cheapest whose error is below the target, with
# a few per cent of margin. gmsh's vertex count is not monotone in h (h = 0.11 gives 1333
# vertices, 0.1 gives 1323). The errors they reach (same machine, gmsh 4.x):
#   db11    1e-3: h 0.12  tol 3e-2  1072 v  9.15e-4   (0.13: 1.12e-3)
#           3e-4: h 0.065 tol 1e-2  3351 v  2.85e-4   (0.07: 3.23e-4)
#           1e-4: h 0.037 tol 1e-2  9950 v  9.50e-5   (0.038: 1.01e-4)
#   db12    1e-3: h 0.11  tol 3e-2  1333 v  8.69e-4   (0.12 tol 3e-2: 1.09e-3)
#           3e-4: h 0.055 tol 3e-2  4661 v  2.55e-4   (0.06 tol 1e-2: 3.09e-4)
#           1e-4: h 0.033 tol 1e-2 12316 v  9.68e-5   (0.035: 1.09e-4)
#   triple  1e-3: h 0.11  tol 3e-2  1892 v  8.17e-4   (0.12 tol 1e-2: 1.003e-3)
#           3e-4: h 0.06  tol 1e-2  5459 v  2.77e-4   (0.065 tol 1e-2: 3.21e-4)
#           1e-4: h 0.035 tol 1e-2 15817 v  9.72e-5   (0.037 tol 1e-2: 1.07e-4)
# A smaller tol than these buys little area (the residual's tail is slow, see docs) and costs
# up to 100x the iterations; a smaller h is the cheaper way to a smaller error.
set -eu
FROTH=${1:-build/froth}
REFERENCE=${2:-}
DIR=$(cd "$(dirname "$0")" && pwd)
REPEAT=${REPEAT:-3}
EV_MAX=${EV_MAX:-5}
EV_STEPS=("r; u; V; g 3; hessian" "r; g 3; hessian")
export FROTH_LUA_DIR=${FROTH_LUA_DIR:-$DIR/../../lua}
command -v evolver >/dev/null || { echo "statics.sh: no evolver (apt-get install evolver-nox)"; exit 1; }
[ -x "$FROTH" ] || { echo "statics.sh: no froth executable at $FROTH"; exit 1; }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

TARGETS="1e-3 3e-4 1e-4"
PROBLEMS="db11 db12 triple"
declare -A FE=([db11]=two_cubes.fe [db12]=two_cubes.fe [triple]=three_cells.fe)
declare -A EV_TARGETS=([db11]="" [db12]="set body[2] target 2" [triple]="")
declare -A REF=([db11]=9.1394216780693 [db12]=11.8542931280002 [triple]=13.1281682)
# froth's (h, tol) per problem and target, from the search above
declare -A FROTH_H=([db11,1e-3]=0.12 [db11,3e-4]=0.065 [db11,1e-4]=0.037
                    [db12,1e-3]=0.11 [db12,3e-4]=0.055 [db12,1e-4]=0.033
                    [triple,1e-3]=0.11 [triple,3e-4]=0.06 [triple,1e-4]=0.035)
declare -A FROTH_TOL=([db11,1e-3]=3e-2 [db11,3e-4]=1e-2 [db11,1e-4]=1e-2
                      [db12,1e-3]=3e-2 [db12,3e-4]=3e-2 [db12,1e-4]=1e-2
                      [triple,1e-3]=3e-2 [triple,3e-4]=1e-2 [triple,1e-4]=1e-2)

now() { date +%s.%N; }
# best_of OUT cmd...: runs cmd REPEAT times (stdout to OUT, stderr to OUT.err), prints the
# fastest wall time in seconds; fails if any run fails.
best_of() {
  local out=$1 best="" t0 t1 i
  shift
  for ((i = 0; i < REPEAT; i++)); do
    t0=$(now)
    "$@" > "$out" 2> "$out.err" || { echo "statics.sh: failed: $* (see below)" >&2; cat "$out.err" >&2; return 1; }
    t1=$(now)
    best=$(awk -v a="$t0" -v b="$t1" -v best="$best" 'BEGIN { t = b - a; if (best == "" || t < best) best = t; print best }')
  done
  echo "$best"
}
# evolver_cmd problem levels step > file
evolver_cmd() {
  sed -e "s/TARGETS/${EV_TARGETS[$1]}/" -e "s/LEVELS/$2/" -e "s/STEP/$3/" "$DIR/statics.cmd"
}
relerr() { awk -v a="$1" -v r="$2" 'BEGIN { printf "%.3e", (a - r) / r }'; }
below() { awk -v e="$1" -v t="$2" 'BEGIN { exit !((e < 0 ? -e : e) <= t) }'; }

if [ "$REFERENCE" = "--reference" ]; then
  echo "== References: Evolver to level 6 (${EV_STEPS[0]}), Richardson (4 A_6 - A_5) / 3"
  for p in $PROBLEMS; do
    evolver_cmd "$p" 6 "${EV_STEPS[0]}" > "$TMP/ref.cmd"
    timeout 120 evolver -x -f "$TMP/ref.cmd" "$DIR/${FE[$p]}" > "$TMP/ref.out" 2>&1 || true
    grep '^EVOLVER' "$TMP/ref.out" | awk -v p="$p" -v ref="${REF[$p]}" '
      { a[$2] = $5; v[$2] = $3 }
      END { if (!(5 in a) || !(6 in a)) { print p ": level 6 did not finish (timeout 120 s?)"; exit }
            r = (4 * a[6] - a[5]) / 3
            printf "%-6s A_5 %.13f  A_6 %.13f (%d vertices)  extrapolated %.10f  used %s (%+.1e)\n",
                   p, a[5], a[6], v[6], r, ref, (r - ref) / ref }'
  done
  echo
fi

echo "statics.sh: $(date -u '+%Y-%m-%d %H:%M UTC'), froth $FROTH, best of $REPEAT runs, load average at the start: $(cut -d' ' -f1-3 /proc/loadavg)"
echo
echo "| problem | target | froth h | tol | vertices | froth s | froth error | volume error | Evolver level | schedule | vertices | Evolver s | Evolver error | froth/Evolver |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|---:|"
for p in $PROBLEMS; do
  # Evolver: per schedule, the lowest level that reaches each target (one run to EV_MAX)
  declare -A EV_LEVEL=()
  for k in "${!EV_STEPS[@]}"; do
    evolver_cmd "$p" "$EV_MAX" "${EV_STEPS[$k]}" > "$TMP/sel.cmd"
    timeout 120 evolver -x -f "$TMP/sel.cmd" "$DIR/${FE[$p]}" > "$TMP/sel.out" 2>&1 || true
    for t in $TARGETS; do
      EV_LEVEL[$k,$t]=$(grep '^EVOLVER' "$TMP/sel.out" | awk -v r="${REF[$p]}" -v t="$t" '
        { e = ($5 - r) / r; if (e < 0) e = -e; if (e <= t && !found) { print $2; found = 1 } }')
    done
  done
  for t in $TARGETS; do
    h=${FROTH_H[$p,$t]} tol=${FROTH_TOL[$p,$t]}
    fs=$(best_of "$TMP/froth.out" timeout 600 "$FROTH" "$DIR/statics_froth.lua" problem="$p" h="$h" tol="$tol")
    read -r _ _ _ _ fv _ _ farea _ fverr fstop < <(grep '^FROTH '"$p" "$TMP/froth.out")
    ferr=$(relerr "$farea" "${REF[$p]}")
    below "$ferr" "$t" || ferr="$ferr (!)"
    [ "$fstop" = converged ] || ferr="$ferr ($fstop)"
    # Evolver: time each schedule at its level, keep the fastest
    es="" el="-" ek="" ev="-" eerr="did not reach"
    for k in "${!EV_STEPS[@]}"; do
      lev=${EV_LEVEL[$k,$t]:-}
      [ -n "$lev" ] || continue
      evolver_cmd "$p" "$lev" "${EV_STEPS[$k]}" > "$TMP/ev$k.cmd"
      s=$(best_of "$TMP/ev.out" timeout 120 evolver -x -f "$TMP/ev$k.cmd" "$DIR/${FE[$p]}")
      if [ -z "$es" ] || awk -v a="$s" -v b="$es" 'BEGIN { exit !(a < b) }'; then
        es=$s el=$lev ek=$k
        read -r _ _ ev _ earea < <(grep '^EVOLVER' "$TMP/ev.out" | tail -1)
        eerr=$(relerr "$earea" "${REF[$p]}")
      fi
    done
    ratio=$( [ -n "$es" ] && awk -v a="$fs" -v b="$es" 'BEGIN { printf "%.2f", a / b }' || echo "-")
    printf "| %s | %s | %s | %s | %s | %.3f | %s | %s | %s | %s | %s | %s | %s | %s |\n" "$p" "$t" \
      "$h" "$tol" "$fv" "$fs" "$ferr" "$fverr" "$el" "${ek:+${EV_STEPS[$ek]}}" "$ev" \
      "${es:+$(printf %.3f "$es")}" "$eerr" "$ratio"
  done
  unset EV_LEVEL
done
echo
echo "load average at the end: $(cut -d' ' -f1-3 /proc/loadavg)"
