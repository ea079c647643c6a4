-- Convergence: a sphere of radius 1 under mean curvature flow, exact R(t)^2 = 1 - 4t.
-- Three meshes, h halved each time and tau = 0.1 h^2; the error
--   e(h) = max over vertices | |x_v(t)|^2 - (1 - 4t) |   at t = 0.1
-- must fall at about second order (the seed reports O(h^2) away from singularities, Table 1;
-- measured: rates 1.69 and 1.92 on the gmsh meshes of 192, 694 and 2719 vertices).
local T = require("froth.test")

local function error_at(h)
  local c = froth.sphere{R = 1, h = h}
  local r = c:evolve{flow = "mcf", tau = 0.1 * h * h, T = 0.1, progress = false}
  local exact, worst = 1 - 4 * r.t, 0
  for v = 1, c:info().vertices do
    local x = c:vertex(v)
    worst = math.max(worst, math.abs(x[1] ^ 2 + x[2] ^ 2 + x[3] ^ 2 - exact))
  end
  return worst, c:info().vertices, r.steps, r.t
end

local hs, errors = {0.3, 0.15, 0.075}, {}
for i, h in ipairs(hs) do
  local e, n, steps, t = error_at(h)
  errors[i] = e
  T.assert_near(t, 0.1, 1e-12, "evolve lands on t = 0.1")
  print(("h = %-6g vertices = %-5d steps = %-4d error = %.3e%s"):format(h, n, steps, e,
        i > 1 and ("   rate = %.2f"):format(math.log(errors[i - 1] / e, 2)) or ""))
end
for i = 2, #hs do
  local rate = math.log(errors[i - 1] / errors[i], 2)
  T.assert_true(rate > 1.5 and rate < 2.6, ("rate %d about 2"):format(i - 1), tostring(rate))
end
T.summary()
