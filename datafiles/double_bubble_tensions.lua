-- datafiles/double_bubble_tensions.lua — seed §5.1.1, Fig. 5: double bubbles with unequal
-- tensions sigma = (1, 1, 1.5) and (1, 1, 1.75). The wall (surface 3) is the heavier film and
-- shrinks relative to the caps; at equilibrium the films meet at the angles of Young's law,
-- cos(theta_jk) = (sigma_i^2 - sigma_j^2 - sigma_k^2) / (2 sigma_j sigma_k).
-- The seed reports: "Gamma_3 shrinks relative to the others" (K = 3267, tau = 1e-3, T = 1).
--
-- Sample runs:  froth datafiles/double_bubble_tensions.lua
--               froth datafiles/double_bubble_tensions.lua h=0.1 T=0.5
--               FROTH_SMOKE=1 froth datafiles/double_bubble_tensions.lua    (ctest: 3 steps)
local script = require("froth.script")
local opts = script.options({h = 0.08, tau = 1e-3, T = 1}, arg)

local function young(si, sj, sk)
  return math.deg(math.acos((si * si - sj * sj - sk * sk) / (2 * sj * sk)))
end

for _, s3 in ipairs{1.5, 1.75} do
  -- 1. Build the two half balls with the wall's tension s3.
  local c = froth.double_bubble{h = opts.h, sigma = {1, 1, s3}}
  local wall0 = c:area(3)
  -- 2. Surface diffusion (3.6) with the tensions in the stiffness (seed (3.8), gamma = sigma |.|).
  local r = c:evolve(script.evolve_options(opts, {flow = "sd", exact_volumes = false, tau = opts.tau}))
  -- 3. Compare with Young's law.
  print(("sigma = (1, 1, %g): t = %g, %d steps, %.1f s"):format(s3, r.t, r.steps, r.wall_s))
  print(("  wall area %.4f of its initial area (seed: Gamma_3 shrinks)"):format(c:area(3) / wall0))
  print(("  angles min %.2f max %.2f; Young's law: %.2f between the caps, %.2f cap-wall;"
         .. " largest deviation %.2f degrees"):format(r.angles.min, r.angles.max,
         young(s3, 1, 1), young(1, 1, s3), r.angles.young_error))
  print(("  volume loss %.3f%%, energy %.6f"):format(100 * r.volume_loss, r.energy))
end
