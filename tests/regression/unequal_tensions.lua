-- Regression: the seed's double bubble with sigma = (1, 1, 1.5) (Fig. 5) under surface
-- diffusion, tau = 1e-3, T = 1, about 3000 vertices. The heavier wall must shrink, and the
-- film angles must approach Young's law: force balance sum_j sigma_j mu_j = 0 gives
-- cos(theta_caps) = (1.5^2 - 2) / 2, theta_caps = 82.82 degrees, and 138.59 between cap and wall.
-- Measured when written: Young error 0.94 degrees, wall area 0.285 of its initial area,
-- volume loss 0.198%.
local T = require("froth.test")

local c = froth.double_bubble{h = 0.08, sigma = {1, 1, 1.5}}
local wall0 = c:area(3)
local r = c:evolve{flow = "sd", exact_volumes = false, tau = 1e-3, T = 1, progress = false}

local caps = math.acos((1.5 ^ 2 - 2) / 2) * 180 / math.pi
T.assert_near(caps, 82.819244, 1e-5, "Young's angle between the caps")
T.assert_true(r.angles.young_error <= 1.5, "film angles obey Young's law within 1.5 degrees",
              tostring(r.angles.young_error))
T.assert_near(r.angles.min, caps, 1.5, "smallest film angle is the one between the caps")
T.assert_true(c:area(3) / wall0 < 0.5, "the heavier wall shrinks", tostring(c:area(3) / wall0))
T.assert_true(r.max_energy_increase <= 1e-13, "energy non-increasing at every step",
              tostring(r.max_energy_increase))
T.assert_true(r.volume_loss <= 0.003, "volume loss <= 0.3%", tostring(r.volume_loss))
T.summary()
