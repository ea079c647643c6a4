-- datafiles/cube_on_plane.lua — seed §5.1.4, Fig. 14 left: a unit cube standing on the plane
-- x3 = 0 (the domain R^2 x (0, inf)) under surface diffusion becomes a half sphere: the area
-- minimiser of its volume in a half space, meeting the wall at 90 degrees. The film's rim
-- slides on the wall (schemes (3.10)/(3.11)); on a plane it stays on it exactly.
-- The seed: K = 5185, J = 10240, tau = 1e-3, T = 1 (it reports the shape only). froth with these
-- defaults (5381 vertices, 73 s on 2 cores): area +0.007% of the half sphere of the same
-- volume, distances from the origin within 0.05% of its R, contact angles 89.46..90.20, volume
-- loss 0.22% (lost while the cube rounds, O(tau): 0.09% at h = 0.1 with tau = 5e-4 and a
-- slower start ramp, tests/regression/cube_on_plane_sd.lua).
--
-- Sample runs:  froth datafiles/cube_on_plane.lua
--               froth datafiles/cube_on_plane.lua h=0.1 tau=5e-4 output=
--               FROTH_SMOKE=1 froth datafiles/cube_on_plane.lua      (ctest: 3 steps)
local script = require("froth.script")
local opts = script.options({vertices = 5185, h = 0, tau = 1e-3, tau_start = 1e-8, T = 1,
                             every = 100, output = "out/cube_on_plane.pvd"}, arg)

local c = froth.cube_on_plane(opts.h > 0 and {h = opts.h} or {vertices = opts.vertices})
local info = c:info()
print(("cube on the plane x3 = 0: %d vertices, %d facets (seed: K = 5185, J = 10240)")
      :format(info.vertices, info.facets))

local drift = 0
-- tau_start: a ramp, for the box's edges
local r = c:evolve(script.evolve_options(opts, {
  flow = "sd", exact_volumes = false, tau = opts.tau, tau_start = opts.tau_start, every = opts.every,
  on_step = function(s) drift = math.max(drift, s.wall_drift) end}))

-- The half sphere of the same volume V = 2 pi R^3 / 3 has the film area 2 pi R^2.
local R, lo, hi = require("froth.measure").half_sphere_fit(c)
local ca = r.contact_angles
print(("t = %.4g after %d steps (%.1f s): %s"):format(r.t, r.steps, r.wall_s, r.stop_reason))
print(("area %.6f   half sphere of the same volume %.6f   error %+.3f%%   (seed: a half sphere)")
      :format(c:area(), 2 * math.pi * R ^ 2, 100 * (c:area() / (2 * math.pi * R ^ 2) - 1)))
print(("distance from the origin %.5f..%.5f, R = %.5f (%+.2f%%..%+.2f%%)")
      :format(lo, hi, R, 100 * (lo / R - 1), 100 * (hi / R - 1)))
print(("contact angles min %.2f  max %.2f  mean %.2f degrees (exact 90)")
      :format(ca.min, ca.max, ca.mean))
print(("volume %.6f, volume loss %.3f%%; largest wall drift %.1e (a plane: round-off)")
      :format(c:volumes()[1], 100 * r.volume_loss, drift))
print(("largest relative energy increase of a step: %.2e (stability: <= 0)")
      :format(r.max_energy_increase))
if not opts.smoke and opts.output ~= "" then print("ParaView series: " .. opts.output) end

return {result = r, cluster = c}
