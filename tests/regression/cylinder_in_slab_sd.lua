-- Regression: the seed's perturbed cylinder (5.3) with rho = 4, alpha = 0.5 between the planes
-- x3 = 0 and x3 = 4 (§5.1.4, Fig. 14 right) under surface diffusion to T = 2 becomes the
-- cylinder of its volume, radius sqrt(V / (pi rho)). h = 0.15 (1371 vertices; seed K = 4160),
-- the seed's tau = 1e-3 after a start ramp from 1e-6.
-- Required: the mean distance of the vertices from the x3 axis within 0.5% of
-- sqrt(V / (pi rho)), and every vertex within 0.5% of it (the spread max - min included); contact
-- angles 90 +- 1.5; volume loss <= 0.1%; ends on the planes (drift < 1e-12); energy
-- non-increasing; no topology event.
-- Measured when written (17 s): mean +0.12%, radii +0.05%..+0.25% (spread 0.20%), angles
-- 89.88..90.16, volume loss 0.005%. (At T = 1 the spread is still 3%; at h = 0.2 it levels
-- off at 0.45%, the mesh's own.)
local T = require("froth.test")

local rho = 4
local c = froth.cylinder_in_slab{rho = rho, alpha = 0.5, h = 0.15}
local drift = 0
local r = c:evolve{flow = "sd", tau = 1e-3, tau_start = 1e-6, T = 2, progress = false,
                   on_step = function(s) drift = math.max(drift, s.wall_drift) end}
local exact = math.sqrt(c:volumes()[1] / (math.pi * rho))
local mean, lo, hi = require("froth.measure").axis_distances(c)
local ca = r.contact_angles
print(("t = %g, %d steps, %.1f s: radius mean %.5f vs sqrt(V/(pi rho)) = %.5f (%+.3f%%), "
       .. "min %+.3f%% max %+.3f%%, contact angles %.2f..%.2f, volume loss %.4f%%, drift %.1e")
      :format(r.t, r.steps, r.wall_s, mean, exact, 100 * (mean / exact - 1),
              100 * (lo / exact - 1), 100 * (hi / exact - 1), ca.min, ca.max,
              100 * r.volume_loss, drift))
T.assert_equal(r.stop_reason, "T reached", "T = 2 reached")
T.assert_true(T.rel(mean, exact) <= 0.005, "mean radius within 0.5%", mean / exact)
T.assert_true(T.rel(lo, exact) <= 0.005 and T.rel(hi, exact) <= 0.005,
              "every vertex within 0.5% of the radius", lo / exact .. " " .. hi / exact)
T.assert_true(ca.min >= 88.5 and ca.max <= 91.5, "contact angles 90 +- 1.5",
              ca.min .. " " .. ca.max)
T.assert_true(r.volume_loss <= 0.001, "volume loss <= 0.1%", r.volume_loss)
T.assert_true(drift < 1e-12, "ends on the planes", drift)
T.assert_true(r.max_energy_increase <= 0, "energy non-increasing", r.max_energy_increase)
T.summary()
