// Surface Evolver side of the statics benchmark (statics.sh): a static equilibrium at fixed
// volumes from the cells of a datafile (two_cubes.fe, three_cells.fe or their _3 versions with
// every face cut into 3 x 3), refined LEVELS times; prints "EVOLVER level vertices clock area"
// after each level. statics.sh replaces the placeholders with sed, as run.sh does for
// sphere_mcf.cmd:
//   TARGETS  nothing, or `set body[2] target 2` for the (1, 2) double bubble
//   PRE      the relaxation of the unrefined datafile, e.g. `U; g 200` (conjugate gradient
//            on, 200 steps): the triple bubble needs it, or its Hessian steps are not positive
//            definite and diverge (statics.sh header)
//   LEVELS   the number of refinements
//   STEP     the commands of one level, e.g. `r; u; V; g 3; hessian` (refine, equiangulate,
//            vertex-average, 3 gradient steps, one Hessian step)
// By hand, from the repository root:
//   sed 's/TARGETS//; s/PRE/U; g 200/; s/LEVELS/4/; s/STEP/r; u; V; g 3; hessian/' bench/evolver/statics.cmd > /tmp/s.cmd
//   timeout 120 evolver -x -f /tmp/s.cmd bench/evolver/three_cells.fe | grep '^EVOLVER'
TARGETS
PRE
lev := 1
while lev <= LEVELS do { STEP; printf "EVOLVER %d %d %.3f %.13f\n", lev, vertex_count, clock, total_area; lev += 1 }
q
q
