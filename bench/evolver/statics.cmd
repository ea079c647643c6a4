// Surface Evolver side of the statics benchmark (statics.sh): a static equilibrium at fixed
// volumes from the cells of two_cubes.fe or three_cells.fe, refined LEVELS times; prints
// "EVOLVER level vertices clock area" after each level. statics.sh replaces the placeholders
// (sed, as run.sh does for sphere_mcf.cmd): TARGETS = nothing, or `set body[2] target 2` for
// the (1, 2) double bubble; LEVELS; STEP = the commands of one level, e.g.
// `r; u; V; g 3; hessian` (refine, equiangulate, vertex-average, 3 conjugate gradient steps,
// one Hessian step). By hand:
//   sed 's/TARGETS//; s/LEVELS/4/; s/STEP/r; u; V; g 3; hessian/' bench/evolver/statics.cmd > /tmp/s.cmd
//   timeout 120 evolver -x -f /tmp/s.cmd bench/evolver/three_cells.fe | grep '^EVOLVER'
// The 200 conjugate gradient steps on the unrefined cells first are needed by the triple bubble:
// without them its Hessian steps are not positive definite and diverge (statics.sh header).
TARGETS
U
g 200
lev := 1
while lev <= LEVELS do { STEP; printf "EVOLVER %d %d %.3f %.13f\n", lev, vertex_count, clock, total_area; lev += 1 }
q
q
