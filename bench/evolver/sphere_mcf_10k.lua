-- froth: mean curvature flow of the unit icosphere refined 5 times (froth.sphere{levels = 5}:
-- 10242 vertices, 20480 facets, as Evolver's ico.fe after `r` 5 times, sphere_mcf_10k.cmd) to
-- t = 0.1; error |(R0^2 - R(T)^2) / (4 T) - 1| with R from the volume (the exact flow has
-- R^2 = R0^2 - 4t).
--   froth bench/evolver/sphere_mcf_10k.lua [levels=5] [runs=1:1e-4,2:2e-3,2:1e-3,2:5e-4]
local opts = require("froth.script").options({levels = 5, runs = "1:1e-4,2:2e-3,2:1e-3,2:5e-4"}, arg)
local T = 0.1
local function radius(c) return (3 * c:volumes()[1] / (4 * math.pi)) ^ (1 / 3) end
print("froth  order  tau      vertices  steps  seconds  R0          R(T)        error")
for order, tau in tostring(opts.runs):gmatch("(%d):([^,]+)") do
  local c = froth.sphere{levels = opts.levels}
  local R0 = radius(c)
  local r = c:evolve{flow = "mcf", tau = tonumber(tau), T = T, order = tonumber(order),
                     progress = false}
  local R = radius(c)
  print(("froth  %5s  %-7g  %8d  %5d  %7.2f  %.8f  %.8f  %.3e"):format(order, tonumber(tau),
        c:info().vertices, r.steps, r.wall_s, R0, R, math.abs((R0 ^ 2 - R ^ 2) / (4 * T) - 1)))
end
