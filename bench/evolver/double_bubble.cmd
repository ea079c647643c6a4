// Surface Evolver: the double bubble from two unit cubes (two_cubes.fe), at 5 refinement
// levels: refine, 30 gradient steps, 2 Hessian steps; prints vertices, cumulative seconds, area
// and its error against the standard double bubble of volumes (1, 1), 3 (9 pi)^(1/3).
exact := 9.139421678069
lev := 1
while lev <= 5 do { r; g 30; hessian; hessian; printf "EVOLVER %d %d %.3f %.10f %.3e\n", lev, vertex_count, clock, total_area, (total_area - exact)/exact; lev += 1 }
q
q
