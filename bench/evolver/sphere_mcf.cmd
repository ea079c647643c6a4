// Surface Evolver: mean curvature flow of a sphere. The unit cube (cube.fe) refined 4 times
// and minimised at volume 1 gives the sphere (3074 vertices, R0 ~ 0.621); then the volume
// constraint is dropped and `g` steps with area_normalization and the fixed scale SCALE
// (an explicit Euler step of V = -H) run to t = 0.05. Prints the mean distance from the
// centroid against the exact R(t) = sqrt(R0^2 - 4t). run.sh replaces SCALE.
r; r; r; g 50; hessian; hessian; r; g 20; hessian; hessian
procedure radius() { cx := avg(vertex, x); cy := avg(vertex, y); cz := avg(vertex, z); rad := avg(vertex, sqrt((x-cx)^2+(y-cy)^2+(z-cz)^2)) }
radius()
R0 := rad
unset body target
area_normalization
m SCALE
t0 := clock
tt := 0
steps := 0
while tt < 0.05 - SCALE/2 do { g 1; tt += SCALE; steps += 1 }
radius()
printf "EVMCF %d %d %.3f %.6f %.6f %.3e %.8f\n", vertex_count, steps, clock - t0, rad, sqrt(R0^2 - 4*tt), (rad - sqrt(R0^2 - 4*tt))/sqrt(R0^2 - 4*tt), R0
q
q
