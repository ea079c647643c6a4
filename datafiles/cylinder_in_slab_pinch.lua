-- datafiles/cylinder_in_slab_pinch.lua — seed §5.1.4, Fig. 15: the perturbed cylinder (5.3)
-- with rho = 8, alpha = 0.25 in the slab R^2 x (0, 8). This cylinder is unstable (Athanassenas
-- 1987): the neck at x3 = 4 thins and the surface wants to split into two halves that would
-- each become a half sphere. The parametric method cannot pass the pinch-off; the seed
-- integrates to just before it, t ~ 1.487, and froth's topology watch stops the run there.
-- The seed: K = 4128, J = 8192, tau = 1e-3. froth with these defaults (4118 vertices, 84 s on 2
-- cores): "topology: an edge of facet 2939 of surface 1 is collapsing ... at t = 1.5005" (+0.9%),
-- the neck radius then 0.0017; at h = 0.2 (1538 vertices) t = 1.4915.
--
-- Sample runs:  froth datafiles/cylinder_in_slab_pinch.lua
--               froth datafiles/cylinder_in_slab_pinch.lua h=0.2 output=
--               FROTH_SMOKE=1 froth datafiles/cylinder_in_slab_pinch.lua      (ctest: 3 steps)
local script = require("froth.script")
local opts = script.options({rho = 8, alpha = 0.25, vertices = 4128, h = 0, tau = 1e-3,
                             tau_start = 1e-6, T = 2, every = 100,
                             output = "out/cylinder_in_slab_pinch.pvd"}, arg)

local size = opts.h > 0 and {h = opts.h} or {vertices = opts.vertices}
local c = froth.cylinder_in_slab{rho = opts.rho, alpha = opts.alpha, h = size.h,
                                 vertices = size.vertices}
local info = c:info()
print(("cylinder (5.3), rho = %g, alpha = %g: %d vertices, %d facets (seed: K = 4128, J = 8192)")
      :format(opts.rho, opts.alpha, info.vertices, info.facets))

-- the neck: the smallest distance from the x3 axis near x3 = rho / 2
local function neck()
  local _, d = require("froth.measure").axis_distances(c, function(x)
    return math.abs(x[3] - opts.rho / 2) < opts.rho / 16
  end)
  return d
end

local drift = 0
local r = c:evolve(script.evolve_options(opts, {
  flow = "sd", exact_volumes = false, tau = opts.tau, tau_start = opts.tau_start, every = opts.every,
  on_step = function(s) drift = math.max(drift, s.wall_drift) end}))

local t_stop = r.event and r.event.t or r.t
print(("stopped at t = %.5g after %d steps (%.1f s)   (seed: just before the pinch-off at t ~ "
       .. "1.487; %+.1f%%)"):format(t_stop, r.steps, r.wall_s, 100 * (t_stop / 1.487 - 1)))
print("stop reason: " .. r.stop_reason)
print(("neck radius %.4f (initially %.4f); volume loss %.4f%%; largest wall drift %.1e")
      :format(neck(), 1 - opts.alpha, 100 * r.volume_loss, drift))
print(("largest relative energy increase of a step: %.2e (stability: <= 0)")
      :format(r.max_energy_increase))
if not opts.smoke and opts.output ~= "" then print("ParaView series: " .. opts.output) end

return {result = r, cluster = c}
