-- datafiles/cylinder_in_slab.lua — seed §5.1.4, Fig. 14 right: the perturbed cylinder (5.3),
-- radius r(x3) = 1 + alpha cos(2 pi x3 / rho), rho = 4, alpha = 0.5, its ends on the planes of
-- the slab R^2 x (0, rho). Under surface diffusion it becomes a cylinder (in such a slab the
-- area minimisers of a given volume are half spheres or cylinders; Athanassenas 1987) of the
-- same volume: radius sqrt(V / (pi rho)), its ends meeting the planes at 90 degrees.
-- The seed: K = 4160, J = 8192, tau = 1e-3, T = 2. froth with these defaults (4149 vertices,
-- 106 s on 2 cores): mean radius +0.041% of sqrt(V / (pi rho)), spread (max - min) 0.125%,
-- contact angles 89.78..90.11, volume loss 0.004%.
--
-- Sample runs:  froth datafiles/cylinder_in_slab.lua
--               froth datafiles/cylinder_in_slab.lua h=0.15 output=
--               froth datafiles/cylinder_in_slab.lua rho=8 alpha=0.25 T=3   (pinches: see
--                                                    datafiles/cylinder_in_slab_pinch.lua)
--               FROTH_SMOKE=1 froth datafiles/cylinder_in_slab.lua      (ctest: 3 steps)
local script = require("froth.script")
local opts = script.options({rho = 4, alpha = 0.5, vertices = 4160, h = 0, tau = 1e-3,
                             tau_start = 1e-6, T = 2, every = 100,
                             output = "out/cylinder_in_slab.pvd"}, arg)

local size = opts.h > 0 and {h = opts.h} or {vertices = opts.vertices}
local c = froth.cylinder_in_slab{rho = opts.rho, alpha = opts.alpha, h = size.h,
                                 vertices = size.vertices}
local info = c:info()
print(("cylinder (5.3), rho = %g, alpha = %g: %d vertices, %d facets (seed: K = 4160, J = 8192)")
      :format(opts.rho, opts.alpha, info.vertices, info.facets))

local r, fit = require("froth.measure").run_in_slab(c, opts)
local exact, drift = fit.exact, r.largest_wall_drift
print(("area %.6f (the cylinder's 2 pi r rho = %.6f); volume loss %.4f%%; largest wall drift %.1e")
      :format(c:area(), 2 * math.pi * exact * opts.rho, 100 * r.volume_loss, drift))
print(("largest relative energy increase of a step: %.2e (stability: <= 0)")
      :format(r.max_energy_increase))
if not opts.smoke and opts.output ~= "" then print("ParaView series: " .. opts.output) end

return {result = r, cluster = c}
