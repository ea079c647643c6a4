// Surface Evolver: Kelvin (twointor.fe) or Weaire-Phelan (phelanc.fe) from its shipped
// examples, at 4 refinement levels: refine, 20 gradient steps, 2 Hessian steps; prints level,
// vertices, cumulative seconds and the cost 2 A / N / V^(2/3) (A the film area per period, N
// cells of mean volume V). NCELLS and BOXVOLUME are set by bench/evolver/foams.sh.
lev := 1
g 10
while lev <= 4 do { r; g 20; hessian; hessian; printf "EVFOAM %d %d %.3f %.8f\n", lev, vertex_count, clock, 2 * total_area / NCELLS / (BOXVOLUME / NCELLS)^(2/3); lev += 1 }
q
q
