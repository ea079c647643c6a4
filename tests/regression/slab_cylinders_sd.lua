-- Regression: two films standing in a slab between the planes x3 = 0 and x3 = rho (§5.1.4)
-- under surface diffusion become the cylinder of their volume, radius sqrt(V / (pi rho)), at the
-- seed's tau = 1e-3 after a start ramp from 1e-6:
--   * the 1 x 1 x 8 cuboid (rho = 8), h = 0.1 (3893 vertices), to T = 0.2: every section is a
--     square becoming a circle, which takes about t = 0.1. (Not longer: a cylinder of radius
--     0.56 and length 8 is far beyond its stability limit, length pi r, and the mesh's
--     asymmetries grow from there; by T = 1 at h = 0.2 the radii spread 1.1%.)
--   * the perturbed cylinder (5.3), rho = 4, alpha = 0.5 (Fig. 14 right), h = 0.15 (1371
--     vertices; seed K = 4160), to T = 2.
-- Required: the mean distance of the vertices from the x3 axis, and every vertex, within 0.5% of
-- sqrt(V / (pi rho)); contact angles 90 +- 1.5; volume loss <= 0.2% (cuboid) and 0.1%
-- (cylinder); ends on the planes (drift < 1e-12); energy non-increasing; T reached.
-- Measured when written (12 s and 17 s): cuboid mean +0.14%, radii +0.06%..+0.23%, angles
-- 89.6..90.2, volume loss 0.100% (at h = 0.14 the mean is +0.30% and the spread 0.54%: vertices
-- on a circle enclose a polygon, so their mean distance exceeds the radius of the same area, by
-- O((h/r)^2)); cylinder mean +0.12%, radii +0.05%..+0.25%, angles 89.88..90.16, volume loss
-- 0.005% (at T = 1 its spread is still 3%; at h = 0.2 it levels off at 0.45%, the mesh's own).
local T = require("froth.test")
local measure = require("froth.measure")

local cases = {
  {name = "cuboid", rho = 8, T = 0.2, volume_loss = 0.002,
   make = function() return froth.cuboid_in_slab{size = {1, 1, 8}, h = 0.1} end},
  {name = "cylinder", rho = 4, T = 2, volume_loss = 0.001,
   make = function() return froth.cylinder_in_slab{rho = 4, alpha = 0.5, h = 0.15} end},
}
for _, case in ipairs(cases) do
  local c = case.make()
  local r = measure.evolve_tracking_drift(c, {flow = "sd", exact_volumes = false, tau = 1e-3, tau_start = 1e-6,
                                               T = case.T, progress = false})
  local fit = measure.cylinder_fit(c, case.rho)
  local ca = r.contact_angles
  print(("%s: t = %g, %d steps, %.1f s: %s, contact angles %.2f..%.2f, volume loss %.4f%%, "
         .. "drift %.1e"):format(case.name, r.t, r.steps, r.wall_s, fit.summary, ca.min, ca.max,
                                 100 * r.volume_loss, r.largest_wall_drift))
  local what = case.name .. ": "
  T.assert_equal(r.stop_reason, "T reached", what .. "T reached")
  T.assert_true(T.rel(fit.mean, fit.exact) <= 0.005, what .. "mean radius within 0.5%",
                fit.mean / fit.exact)
  T.assert_true(T.rel(fit.lo, fit.exact) <= 0.005 and T.rel(fit.hi, fit.exact) <= 0.005,
                what .. "every vertex within 0.5% of the radius",
                fit.lo / fit.exact .. " " .. fit.hi / fit.exact)
  T.assert_true(ca.min >= 88.5 and ca.max <= 91.5, what .. "contact angles 90 +- 1.5",
                ca.min .. " " .. ca.max)
  T.assert_true(r.volume_loss <= case.volume_loss,
                what .. ("volume loss <= %g%%"):format(100 * case.volume_loss), r.volume_loss)
  T.assert_true(r.largest_wall_drift < 1e-12, what .. "ends on the planes", r.largest_wall_drift)
  T.assert_true(r.max_energy_increase <= 0, what .. "energy non-increasing",
                r.max_energy_increase)
end
T.summary()
