-- datafiles/cuboid_in_slab.lua — seed §5.1.4: a 1 x 1 x 8 cuboid standing in the slab
-- R^2 x (0, 8), its ends on the planes, under surface diffusion becomes a cylinder of the same
-- volume, radius sqrt(V / (pi rho)): constant in x3, so each section is a square becoming a
-- circle (by about t = 0.1). The seed gives no K or T; froth: about 4100 vertices like the
-- seed's other slab runs, T = 0.5. The cylinder is far beyond its stability limit (length
-- pi r = 1.77 < 8): the mesh's asymmetries grow from it, and a long run ends pinched like
-- datafiles/cylinder_in_slab_pinch.lua (by T = 1 at h = 0.2 the radii spread 1.1%). froth with
-- these defaults (4145 vertices, 31 s on 2 cores): mean radius +0.137% of sqrt(V / (pi rho)),
-- spread 0.19%, contact angles 89.73..90.16, volume loss 0.10%.
--
-- Sample runs:  froth datafiles/cuboid_in_slab.lua
--               froth datafiles/cuboid_in_slab.lua h=0.1 T=0.2 output=
--               FROTH_SMOKE=1 froth datafiles/cuboid_in_slab.lua      (ctest: 3 steps)
local script = require("froth.script")
local opts = script.options({a = 1, b = 1, rho = 8, vertices = 4100, h = 0, tau = 1e-3,
                             tau_start = 1e-6, T = 0.5, every = 50,
                             output = "out/cuboid_in_slab.pvd"}, arg)

local size = opts.h > 0 and {h = opts.h} or {vertices = opts.vertices}
local c = froth.cuboid_in_slab{size = {opts.a, opts.b, opts.rho}, h = size.h,
                               vertices = size.vertices}
local info = c:info()
print(("%g x %g x %g cuboid in the slab 0 < x3 < %g: %d vertices, %d facets")
      :format(opts.a, opts.b, opts.rho, opts.rho, info.vertices, info.facets))

local r = require("froth.measure").run_in_slab(c, opts)
local drift = r.largest_wall_drift
print(("volume loss %.4f%%; largest wall drift %.1e"):format(100 * r.volume_loss, drift))
print(("largest relative energy increase of a step: %.2e (stability: <= 0)")
      :format(r.max_energy_increase))
if not opts.smoke and opts.output ~= "" then print("ParaView series: " .. opts.output) end

return {result = r, cluster = c}
