-- datafiles/catenoid.lua — a soap film spanning two coaxial rings (Evolver's cat.fe problem):
-- the rings are wires (free boundary edges between fixed vertices), the film encloses no body,
-- and c:minimize{} finds the catenoid r(z) = a cosh(z / a) with a cosh(z0 / a) = R (the
-- larger root: the stable catenoid; none exists for z0 / R above 0.6627). The rings are regular
-- K-gons, so the discrete area converges as K^-2 to the exact 2 pi a z0 + pi a^2 sinh(2 z0 / a).
--
-- Sample runs:  froth datafiles/catenoid.lua
--               froth datafiles/catenoid.lua K=96 z0=0.6
--               FROTH_SMOKE=1 froth datafiles/catenoid.lua       (ctest: a few iterations)
local script = require("froth.script")
local opts = script.options({K = 48, z0 = 0.5, R = 1}, arg)
local K, z0, R = math.floor(opts.K), opts.z0, opts.R
local M = math.max(2, 2 * math.floor(K * z0 / (math.pi * R) + 0.5)) -- rings: near-equilateral

-- 1. A tube of K vertices a ring and M + 1 rings (alternate rings turned by half a step), its
--    end rings fixed: froth.cluster needs no gmsh.
local V, F, rings = {}, {}, {}
local function id(i, j) return j * K + (i % K) + 1 end
for j = 0, M do
  for i = 0, K - 1 do
    local t = 2 * math.pi * (i + 0.5 * (j % 2)) / K
    V[#V + 1] = {R * math.cos(t), R * math.sin(t), -z0 + 2 * z0 * j / M}
    if j == 0 or j == M then rings[#rings + 1] = #V end
  end
end
for j = 0, M - 1 do
  for i = 0, K - 1 do
    local a, b, c, d = id(i, j), id(i + 1, j), id(i, j + 1), id(i + 1, j + 1)
    if j % 2 == 0 then
      F[#F + 1], F[#F + 2] = {a, b, c}, {b, d, c}
    else
      F[#F + 1], F[#F + 2] = {a, d, c}, {a, b, d}
    end
  end
end
local c = froth.cluster{vertices = V, surfaces = {F}, fixed = rings}
print(("tube: %d vertices, %d facets, %d wire edges"):format(c:info().vertices, c:info().facets,
      #c:edges{where = function(e) return e.wire end}))

-- 2. The equilibrium: no volume constraint, the rings held.
local r = c:minimize{max_iterations = opts.smoke and 3 or 1000}
print(("minimize: %s after %d iterations (%.2f s)"):format(r.stop_reason, r.iterations, r.wall_s))

-- 3. Against the exact catenoid (Newton's method for a, from the cylinder's a = R side).
local a = R
for _ = 1, 100 do
  local f = a * math.cosh(z0 / a) - R
  a = a - f / (math.cosh(z0 / a) - z0 / a * math.sinh(z0 / a))
end
local exact = 2 * math.pi * a * z0 + math.pi * a * a * math.sinh(2 * z0 / a)
local waist = math.huge
for _, v in ipairs(c:vertices{where = function(v) return math.abs(v.x[3]) < 1e-12 end}) do
  waist = math.min(waist, math.sqrt(v.x[1] ^ 2 + v.x[2] ^ 2))
end
print(("area %.8f   exact catenoid %.8f   error %+.2e"):format(c:area(), exact, (c:area() - exact) / exact))
if waist < math.huge then print(("waist radius %.6f   exact a = %.6f"):format(waist, a)) end
return {area = c:area(), exact = exact, result = r}
