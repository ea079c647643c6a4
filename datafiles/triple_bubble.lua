-- datafiles/triple_bubble.lua — seed §5.1.2, Fig. 11: the unit ball in three 120-degree
-- wedges relaxes under surface diffusion to the standard triple bubble: 6 films, 4 triple lines
-- meeting at 120 degrees, 2 quadruple points where the lines meet at arccos(-1/3) = 109.47.
-- Exact area 13.128168 V^(2/3) (16.400196 for V = 4 pi/9). The seed: K = 6534, tau = 1e-4,
-- T = 1, volume loss 0.03%.
--
-- Sample runs:  froth datafiles/triple_bubble.lua                  (the seed's run, a few minutes)
--               froth datafiles/triple_bubble.lua vertices=2000 tau=2.5e-4
--               FROTH_SMOKE=1 froth datafiles/triple_bubble.lua    (ctest: 3 steps)
local script = require("froth.script")
local opts = script.options({vertices = 6500, tau = 1e-4, T = 1, history = "out/triple_bubble"}, arg)

-- 1. Build: three analytic sphere wedges, fragmented by gmsh.
local c = froth.triple_bubble{vertices = opts.vertices}
local info = c:info()
print(("triple bubble: %d vertices, %d surfaces, %d triple lines, %d quadruple points, %d bodies")
      :format(info.vertices, info.surfaces, info.triple_lines, info.quadruple_points, info.bodies))

-- 2. Surface diffusion; the W^h conditions at the quadruple points need no user input.
-- tau_start: a ramp from the 90-degree junctions of the start
local r = c:evolve(script.evolve_options(opts, {flow = "sd", exact_volumes = false, tau = opts.tau, tau_start = 1e-7}))

-- 3. Compare with the standard triple bubble of the same volumes.
local V = c:volumes()
local exact = 13.128168244433 * ((V[1] + V[2] + V[3]) / 3) ^ (2 / 3)
print(("t = %g after %d steps (%.1f s, %d factorisations)"):format(r.t, r.steps, r.wall_s,
      r.factorizations))
print(("area %.6f, standard triple bubble %.6f: %+.3f%%"):format(r.energy, exact,
      100 * (r.energy - exact) / exact))
print(("film angles %.2f .. %.2f (120); line angles at the quadruple points %.2f .. %.2f (109.47)")
      :format(r.angles.min, r.angles.max, r.quadruple_angles.min, r.quadruple_angles.max))
print(("volume loss %.3f%% (seed: 0.03%%); energy history: %s.csv, %s.svg")
      :format(100 * r.volume_loss, opts.history, opts.history))
