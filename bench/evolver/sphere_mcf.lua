-- froth: mean curvature flow of a sphere of radius R0 (Evolver's, see sphere_mcf.cmd) with
-- about 3100 vertices to t = 0.05 for several tau; prints the mean distance from the centroid
-- against the exact R(t) = sqrt(R0^2 - 4t).
--   froth bench/evolver/sphere_mcf.lua [h=0.0435] [taus=1e-4,1e-3,5e-3]
local opts = require("froth.script").options({h = 0.0435, taus = "1e-4,1e-3,5e-3",
                                              R0 = 0.62096646}, arg)
local T = 0.05
local function mean_radius(c)
  local n, m = c:info().vertices, {0, 0, 0}
  for v = 1, n do
    local x = c:vertex(v)
    for k = 1, 3 do m[k] = m[k] + x[k] / n end
  end
  local sum = 0
  for v = 1, n do
    local x = c:vertex(v)
    sum = sum + math.sqrt((x[1] - m[1]) ^ 2 + (x[2] - m[2]) ^ 2 + (x[3] - m[3]) ^ 2)
  end
  return sum / n
end
print("froth  tau     vertices  steps  seconds  R         exact     error")
for tau in tostring(opts.taus):gmatch("[^,]+") do
  tau = tonumber(tau)
  local c = froth.sphere{R = opts.R0, h = opts.h}
  local exact = math.sqrt(mean_radius(c) ^ 2 - 4 * T)
  local r = c:evolve{flow = "mcf", tau = tau, T = T, progress = false}
  local R = mean_radius(c)
  print(("froth  %-6g  %8d  %5d  %7.2f  %.6f  %.6f  %.2e"):format(tau, c:info().vertices, r.steps,
        r.wall_s, R, exact, (R - exact) / exact))
end
