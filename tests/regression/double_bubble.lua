-- Regression: the default scene end to end (seed §5.1.1). Two half balls under surface
-- diffusion, tau = 1e-3, T = 1, about 3000 vertices, must reach the standard double bubble:
--   * total area within 0.3% of 3 (9 pi)^(1/3) (2 pi/3)^(2/3) = 14.960902449492 (exact;
--     reference-values.md), for the volumes the cluster has;
--   * film angles at the triple line 120 +- 1.5 degrees;
--   * maximum relative volume loss <= 0.2% (the seed reports 0.11%);
--   * energy non-increasing at every step (Theorem 3.2), no remeshing (counts unchanged).
local T = require("froth.test")
arg = {} -- run the datafile with its defaults
local out = dofile(os.getenv("FROTH_DATAFILES") .. "/double_bubble.lua")
local r, c = out.result, out.cluster

T.assert_near(r.t, 1.0, 1e-12, "final time")
T.assert_equal(r.steps, 1000, "steps")
T.assert_true(math.abs(r.energy - 14.960902449492) <= 0.003 * 14.960902449492,
              "area within 0.3% of the standard double bubble", tostring(r.energy))
T.assert_true(math.abs(r.energy - out.exact) <= 0.003 * out.exact,
              "area within 0.3% of the standard double bubble of the discrete volumes",
              ("%.6f vs %.6f"):format(r.energy, out.exact))
T.assert_true(r.angles.min >= 118.5 and r.angles.max <= 121.5, "angles 120 +- 1.5",
              ("min %.3f max %.3f"):format(r.angles.min, r.angles.max))
T.assert_true(r.volume_loss <= 0.002, "volume loss <= 0.2%", tostring(r.volume_loss))
T.assert_true(out.worst_increase <= 1e-13, "energy non-increasing at every step",
              tostring(out.worst_increase))
T.assert_equal(r.max_energy_increase, out.worst_increase, "evolve reports the same increase")
T.assert_equal(c:info().vertices, 2994, "vertex count unchanged (no remeshing; gmsh h=0.08)")
T.summary()
