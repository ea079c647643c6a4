-- datafiles/drop_on_sphere_wall.lua — a drop on a curved wall (the seed's (3.11) with
-- D = {|x| > R}; not one of its experiments): the half ball of radius r = 0.7 sheared onto the
-- sphere |x| = R = 2, first meeting it at 90 - asin(r / R) = 69.5 degrees. Under surface
-- diffusion it becomes the spherical cap of its volume meeting the wall at 90 degrees: the
-- sphere of radius a centred at (0, 0, sqrt(R^2 + a^2)), which cuts the wall orthogonally.
-- The rim moves in the wall's tangent planes (the linearised constraint), so it drifts off the
-- sphere by O(tau^2); project=1 moves it back after every step (not part of the scheme).
-- froth with these defaults (3156 vertices, 38 s on 2 cores): contact angles 89.74..90.08,
-- fitted sphere radius +0.02% of the orthogonal cap of the same volume (distances within
-- 0.03%), center height 2.09848 vs sqrt(R^2 + a^2) = 2.09841, volume -0.027% (the lid is the
-- sphere patch inside the rim), wall drift 4.0e-5.
--
-- Sample runs:  froth datafiles/drop_on_sphere_wall.lua
--               froth datafiles/drop_on_sphere_wall.lua h=0.1 project=1 output=
--               FROTH_SMOKE=1 froth datafiles/drop_on_sphere_wall.lua      (ctest: 3 steps)
local script = require("froth.script")
local opts = script.options({R = 2, r = 0.7, vertices = 3000, h = 0, tau = 1e-3,
                             tau_start = 1e-6, T = 1, project = 0, every = 100,
                             output = "out/drop_on_sphere_wall.pvd"}, arg)
local R = opts.R

local size = opts.h > 0 and {h = opts.h} or {vertices = opts.vertices}
local c = froth.drop_on_sphere_wall{R = R, r = opts.r, h = size.h, vertices = size.vertices}
local info = c:info()
print(("drop of radius %g on the sphere wall |x| = %g: %d vertices, %d facets")
      :format(opts.r, R, info.vertices, info.facets))

-- froth's volume: the lid is the patch of the sphere inside the rim (the sphere wall's own lid
-- flux), so this is the volume between film and wall.
local V0 = c:volumes()[1]

local drift = 0
local r = c:evolve(script.evolve_options(opts, {
  flow = "sd", exact_volumes = false, tau = opts.tau, tau_start = opts.tau_start, project = opts.project == 1,
  every = opts.every, on_step = function(s) drift = math.max(drift, s.wall_drift) end}))

local measure = require("froth.measure")
local z0, a, lo, hi = measure.axial_sphere_fit(c)
local predicted = measure.orthogonal_cap_radius(R, V0)
local V1 = c:volumes()[1]
local ca = r.contact_angles

print(("t = %.4g after %d steps (%.1f s): %s%s"):format(r.t, r.steps, r.wall_s, r.stop_reason,
      opts.project == 1 and " (projected onto the wall after every step)" or ""))
print(("contact angles min %.2f  max %.2f  mean %.2f degrees (exact 90)")
      :format(ca.min, ca.max, ca.mean))
print(("fitted sphere: radius %.5f (distances %+.2f%%..%+.2f%%), center height %.5f; orthogonal "
       .. "to the wall: sqrt(R^2 + a^2) = %.5f"):format(a, 100 * (lo / a - 1), 100 * (hi / a - 1),
      z0, math.sqrt(R * R + a * a)))
print(("radius of the orthogonal cap of the same volume %.5f (fitted %+.2f%%)")
      :format(predicted, 100 * (a / predicted - 1)))
print(("volume %.6f -> %.6f (%+.3f%%)"):format(V0, V1, 100 * (V1 / V0 - 1)))
print(("wall drift: largest over the steps %.2e, now %.2e"):format(drift, r.wall_drift))
print(("largest relative energy increase of a step: %.2e (stability: <= 0%s)")
      :format(r.max_energy_increase, opts.project == 1 and "; not guaranteed with projection" or ""))
if not opts.smoke and opts.output ~= "" then print("ParaView series: " .. opts.output) end

return {result = r, cluster = c}
