-- Slow regression: the seed's triple bubble with sigma_1 = 1.5 (§5.1.2, Fig. 12, bottom) under
-- surface diffusion at the seed's resolution (about 6500 vertices; the seed's K = 6534), tau =
-- 1e-3 after a start ramp, T = 1: the heavier lune (surface 1) shrinks relative to the others,
-- and the film angles obey Young's law for the tensions (1.5, 1, 1, ...). At 2000 vertices
-- the Young deviation is 1.60 degrees (the regression triple_bubble_sd runs that size with
-- equal tensions); the issue's bound of 1.5 degrees holds from this resolution on.
-- Measured when written: 6514 vertices, Young deviation 1.14 degrees, film angles
-- 82.42..139.03, surface 1 share of the area 24.24% -> 20.21%, volume loss 0.093%, 89 s.
-- Required: Young's law within 1.5 degrees, surface 1's share of the area down by at least 2
-- points from the start, energy non-increasing, volume loss <= 0.1%.
local T = require("froth.test")

local c = froth.triple_bubble{vertices = 6500, sigma = {[1] = 1.5}}
local share0 = c:area(1) / c:area()
local r = c:evolve{flow = "sd", exact_volumes = false, tau = 1e-3, tau_start = 1e-7, T = 1, progress = false}
local share = c:area(1) / c:area()
print(("%d vertices: Young deviation %.2f degrees, angles %.2f..%.2f, surface 1 share %.2f%% ->"
       .. " %.2f%%, loss %.3f%%, %.0f s"):format(c:info().vertices, r.angles.young_error,
       r.angles.min, r.angles.max, 100 * share0, 100 * share, 100 * r.volume_loss, r.wall_s))
T.assert_equal(r.stop_reason, "T reached", "T = 1 reached")
T.assert_true(r.angles.young_error <= 1.5, "Young's law within 1.5 degrees", r.angles.young_error)
T.assert_true(share <= share0 - 0.02, "the heavier film shrinks", ("%g -> %g"):format(share0, share))
T.assert_true(r.max_energy_increase <= 0, "energy non-increasing", r.max_energy_increase)
T.assert_true(r.volume_loss <= 0.001, "volume loss <= 0.1%", r.volume_loss)
T.summary()
