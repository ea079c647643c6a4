// Surface Evolver: mean curvature flow of the unit sphere at 10242 vertices (issue 16's
// comparison): ico.fe (the icosahedron on the constraint x^2 + y^2 + z^2 = 1) refined 5 times,
// 20480 facets, every vertex on the sphere; then the constraint and the volume are dropped and
// `g` steps with area_normalization and the fixed scale SCALE (an explicit Euler step of
// V = -H; 1e-4 is the largest that keeps this mesh intact) run to t = 0.1. Prints the error
// |(R0^2 - R(T)^2) / (4 T) - 1| with R from the volume. run.sh replaces SCALE.
r; r; r; r; r
printf "EVSETUP %d vertices %d facets volume %.10f\n", vertex_count, facet_count, body[1].volume
unset vertex constraint 1
unset edge constraint 1
unset facet constraint 1
unset body target
V0 := body[1].volume
R0 := (3*V0/(4*pi))^(1/3)
area_normalization
m SCALE
t0 := clock
tt := 0
steps := 0
while tt < 0.1 - SCALE/2 do { g 1; tt += SCALE; steps += 1 }
RT := (3*body[1].volume/(4*pi))^(1/3)
printf "EVMCF %d %d %.3f %.8f %.8f %.3e\n", vertex_count, steps, clock - t0, R0, RT, abs((R0^2 - RT^2)/(4*tt) - 1)
q
q
