-- datafiles/quadruple_bubble.lua — seed §5.1.3, Fig. 13: two unit cubes and two cuboids of
-- twice the volume (9 films, 8 triple lines, 4 quadruple points) under surface diffusion. The
-- cluster rounds off; the triple lines meet at the quadruple points at angles approaching
-- arccos(-1/3) = 109.47 degrees. The seed: K = 7305, tau = 1e-4, T = 1.
--
-- Sample runs:  froth datafiles/quadruple_bubble.lua vertices=2500 tau=5e-4
--               FROTH_SMOKE=1 froth datafiles/quadruple_bubble.lua   (ctest: 3 steps)
local script = require("froth.script")
local opts = script.options({vertices = 7300, tau = 1e-4, T = 1, history = "out/quadruple_bubble"}, arg)

local c = froth.quadruple_bubble{vertices = opts.vertices}
local info = c:info()
print(("quadruple bubble: %d vertices, %d surfaces, %d triple lines, %d quadruple points")
      :format(info.vertices, info.surfaces, info.triple_lines, info.quadruple_points))
local q0 = c:report().quadruple_angles
-- The box edges make the first steps violent: start with tiny steps growing to tau (without
-- this ramp the volume loss is about 3%).
local r = c:evolve(script.evolve_options(opts, {flow = "sd", exact_volumes = false, tau = opts.tau, tau_start = 1e-8}))
print(("t = %g after %d steps (%.1f s); energy %.6f; volume loss %.3f%%")
      :format(r.t, r.steps, r.wall_s, r.energy, 100 * r.volume_loss))
print(("line angles at the quadruple points: %.2f .. %.2f at the start, %.2f .. %.2f now (109.47)")
      :format(q0.min, q0.max, r.quadruple_angles.min, r.quadruple_angles.max))
print(("film angles %.2f .. %.2f (120)"):format(r.angles.min, r.angles.max))
