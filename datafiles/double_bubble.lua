-- datafiles/double_bubble.lua — the default scene (seed §5.1.1, Fig. 4).
-- The unit ball cut into two half balls relaxes under isotropic surface diffusion to the
-- standard double bubble: two spherical caps and a flat wall meeting at 120 degrees, the
-- volumes 2 pi/3 each kept, the area decreasing to 3 (9 pi)^(1/3) V^(2/3) = 14.960902.
-- The seed: K = 3267 vertices, tau = 1e-3, T = 1, maximum volume loss 0.11%. Then the same
-- equilibrium by c:minimize{} (no dynamics, volumes exact), with the pressures.
--
-- Sample runs:  froth datafiles/double_bubble.lua
--               froth datafiles/double_bubble.lua h=0.1 T=0.5 output=
--               FROTH_SMOKE=1 froth datafiles/double_bubble.lua      (ctest: 3 steps)
local script = require("froth.script")
local opts = script.options({h = 0.08, tau = 1e-3, T = 1, every = 100,
                             output = "out/double_bubble.pvd"}, arg)

-- 1. Build: gmsh meshes the two half balls with conforming nodes on the triple line.
local c = froth.double_bubble{h = opts.h}
local info = c:info()
print(("double bubble: %d vertices, %d facets, %d surfaces, %d triple line, %d bodies")
      :format(info.vertices, info.facets, info.surfaces, info.triple_lines, info.bodies))

-- 2. Evolve by surface diffusion (3.6), checking the energy at every step (Theorem 3.2).
local worst_increase = 0
local result = c:evolve(script.evolve_options(opts, {
  flow = "sd", exact_volumes = false, tau = opts.tau, every = opts.every,
  on_step = function(s)
    worst_increase = math.max(worst_increase, (s.energy - s.energy_before) / s.energy_before)
  end}))

-- 3. Compare with the standard double bubble of the same volumes.
local V = c:volumes()
local exact = 3 * (9 * math.pi) ^ (1 / 3) * ((V[1] + V[2]) / 2) ^ (2 / 3)
print(("t = %.4g after %d steps (%.1f s, %.1f s in the solver)")
      :format(result.t, result.steps, result.wall_s, result.solve_s))
print(("area    %.6f   exact standard double bubble %.6f   error %+.3f%%")
      :format(result.energy, exact, 100 * (result.energy - exact) / exact))
print(("volumes %.6f  %.6f   max volume loss %.3f%%   (seed: 0.11%%)")
      :format(V[1], V[2], 100 * result.volume_loss))
print(("angles at the triple line: min %.2f  max %.2f  mean %.2f degrees (exact 120)")
      :format(result.angles.min, result.angles.max, result.angles.mean))
print(("largest relative energy increase of a step: %.2e (stability: <= 0)"):format(worst_increase))
if not opts.smoke and opts.output ~= "" then print("ParaView series: " .. opts.output) end

-- 4. The same equilibrium without dynamics, as Surface Evolver finds it: minimize from the
-- start at the exact initial volumes (c:minimize holds them to round-off).
local m = froth.double_bubble{h = opts.h}
local V0 = m:volumes()
local eq = m:minimize{tol = opts.smoke and 1e-2 or 1e-6}
local exact0 = 3 * (9 * math.pi) ^ (1 / 3) * ((V0[1] + V0[2]) / 2) ^ (2 / 3)
print(("minimize: %s after %d iterations (%.2f s): area %.6f   error %+.3f%%   volume error %.1e")
      :format(eq.stop_reason, eq.iterations, eq.wall_s, eq.energy,
              100 * (eq.energy - exact0) / exact0, eq.volume_error))
print(("          pressures %.5f %.5f   (2 / r of the exact caps: %.5f)")
      :format(eq.pressures[1], eq.pressures[2],
              require("froth.measure").standard_double_bubble(V0[1], V0[2]).p1))

return {result = result, exact = exact, worst_increase = worst_increase, cluster = c,
        equilibrium = eq}
