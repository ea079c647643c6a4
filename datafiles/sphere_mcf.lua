-- datafiles/sphere_mcf.lua — a sphere shrinking under mean curvature flow.
-- The exact solution is a sphere of radius R(t) = sqrt(R0^2 - 4t) (kappa = sum of principal
-- curvatures), vanishing at t = R0^2/4. We evolve to T = R0^2/8 and print the radius error.
--
-- Sample runs:  froth datafiles/sphere_mcf.lua
--               froth datafiles/sphere_mcf.lua h=0.05 tau=1e-4
--               FROTH_SMOKE=1 froth datafiles/sphere_mcf.lua         (ctest: 3 steps)
local script = require("froth.script")
local opts = script.options({R = 1, h = 0.1, tau = 1e-3, T = 0.125}, arg)

-- 1. Build the sphere (gmsh).
local c = froth.sphere{R = opts.R, h = opts.h}
print(("sphere: %d vertices, %d facets"):format(c:info().vertices, c:info().facets))

-- 2. Evolve by mean curvature flow (3.5), solved as the SPD system (4.6b).
local function mean_radius()
  local n, sum = c:info().vertices, 0
  for v = 1, n do
    local x = c:vertex(v)
    sum = sum + math.sqrt(x[1] ^ 2 + x[2] ^ 2 + x[3] ^ 2)
  end
  return sum / n
end
local result = c:evolve(script.evolve_options(opts, {flow = "mcf", tau = opts.tau}))

-- 3. Compare with R(t)^2 = R0^2 - 4t.
local R = mean_radius()
local exact = math.sqrt(opts.R ^ 2 - 4 * result.t)
print(("t = %.4g after %d steps: mean radius %.6f, exact %.6f, error %.2e")
      :format(result.t, result.steps, R, exact, R - exact))
print(("energy %.6f (exact sphere area %.6f)"):format(result.energy, 4 * math.pi * exact ^ 2))
return {radius = R, exact = exact, result = result}
