-- froth.measure: measurements of clusters that datafiles and tests share.
--   local measure = require("froth.measure")
--   local mean, lo, hi = measure.axis_distances(c)
--   local dev, r = measure.wulff_deviation(c, gamma, {half = true})
--   local r = measure.evolve_tracking_drift(c, {flow = "sd", tau = 1e-3, T = 1})
--   local fit = measure.cylinder_fit(c, rho)
local M = {}
local script = require("froth.script")

--- Mean, smallest and largest distance of the cluster's vertices from the x3 axis; with
--- `keep(x)` (x = {x1, x2, x3}) only over the vertices it accepts (nil if it accepts none).
function M.axis_distances(c, keep)
  local n, sum, lo, hi = 0, 0, math.huge, -math.huge
  for v = 1, c:info().vertices do
    local x = c:vertex(v)
    if not keep or keep(x) then
      local d = math.sqrt(x[1] ^ 2 + x[2] ^ 2)
      n, sum, lo, hi = n + 1, sum + d, math.min(lo, d), math.max(hi, d)
    end
  end
  if n == 0 then return nil end
  return sum / n, lo, hi
end

--- c:evolve(options) (its on_step is taken over), with the result gaining
--- `largest_wall_drift`: the largest `wall_drift` of the steps' reports (0 without walls).
function M.evolve_tracking_drift(c, options)
  local drift = 0
  options.on_step = function(s) drift = math.max(drift, s.wall_drift or 0) end
  local r = c:evolve(options)
  r.largest_wall_drift = drift
  return r
end

--- Body 1 against the cylinder of its volume standing in the slab 0 < x3 < rho: a table with
--- `exact` = sqrt(V / (pi rho)), the `mean`, smallest (`lo`) and largest (`hi`) distance of the
--- vertices from the x3 axis, and a one-line `summary` of them.
function M.cylinder_fit(c, rho)
  local exact = math.sqrt(c:volumes()[1] / (math.pi * rho))
  local mean, lo, hi = M.axis_distances(c)
  local pct = function(x) return 100 * (x / exact - 1) end
  return {exact = exact, mean = mean, lo = lo, hi = hi,
          summary = ("radius mean %.5f vs sqrt(V/(pi rho)) = %.5f (%+.3f%%), min %+.3f%% max %+.3f%%")
                    :format(mean, exact, pct(mean), pct(lo), pct(hi))}
end

--- Body 1 against the half ball on x3 = 0 of the same volume V = 2 pi R^3 / 3, centred at the
--- origin: returns R and the smallest and largest vertex distance from the origin.
function M.half_sphere_fit(c)
  local R = (3 * c:volumes()[1] / (2 * math.pi)) ^ (1 / 3)
  local lo, hi = math.huge, -math.huge
  for v = 1, c:info().vertices do
    local x = c:vertex(v)
    local d = math.sqrt(x[1] ^ 2 + x[2] ^ 2 + x[3] ^ 2)
    lo, hi = math.min(lo, d), math.max(hi, d)
  end
  return R, lo, hi
end

--- The sphere |x - (0, 0, z0)| = a that best fits the cluster's vertices (least squares on
--- |x|^2 = 2 z0 x3 + k, center on the x3 axis): returns z0 and the mean, smallest and largest
--- vertex distance from (0, 0, z0) (the mean is the radius a).
function M.axial_sphere_fit(c)
  local n, sz, ss, szz, szs = c:info().vertices, 0, 0, 0, 0
  for v = 1, n do
    local x = c:vertex(v)
    local s = x[1] ^ 2 + x[2] ^ 2 + x[3] ^ 2
    sz, ss, szz, szs = sz + x[3], ss + s, szz + x[3] ^ 2, szs + x[3] * s
  end
  local z0 = (n * szs - sz * ss) / (n * szz - sz * sz) / 2
  local sum, lo, hi = 0, math.huge, -math.huge
  for v = 1, n do
    local x = c:vertex(v)
    local d = math.sqrt(x[1] ^ 2 + x[2] ^ 2 + (x[3] - z0) ^ 2)
    sum, lo, hi = sum + d, math.min(lo, d), math.max(hi, d)
  end
  return z0, sum / n, lo, hi
end

--- The radius a of the spherical cap of volume V outside the ball |x| <= R that meets its
--- sphere orthogonally (centre at distance sqrt(R^2 + a^2)): 4 pi a^3 / 3 less the lens the
--- two balls share, solved by bisection.
function M.orthogonal_cap_radius(R, V)
  local pi = math.pi
  local function cap_volume(b)
    local d = math.sqrt(R * R + b * b)
    local lens = pi * (R + b - d) ^ 2 * (d * d + 2 * d * b - 3 * b * b + 2 * d * R + 6 * b * R
                                         - 3 * R * R) / (12 * d)
    return 4 * pi * b ^ 3 / 3 - lens
  end
  local lo, hi = 0, 10 * R
  while cap_volume(hi) < V do hi = 2 * hi end
  for _ = 1, 100 do
    local m = (lo + hi) / 2
    if cap_volume(m) < V then lo = m else hi = m end
  end
  return (lo + hi) / 2
end

--- The slab datafiles' run (cuboid_in_slab.lua, cylinder_in_slab.lua): SD with the script
--- options opts (tau, tau_start, T, every, output, rho; 3 steps when opts.smoke), then prints
--- the stop, the radii against the cylinder of the same volume and the contact angles.
--- Returns the evolve result (with largest_wall_drift) and the cylinder_fit.
function M.run_in_slab(c, opts)
  local r = M.evolve_tracking_drift(c, script.evolve_options(opts, {
    flow = "sd", exact_volumes = false, tau = opts.tau, tau_start = opts.tau_start, every = opts.every}))
  local fit = M.cylinder_fit(c, opts.rho)
  local ca = r.contact_angles
  print(("t = %.4g after %d steps (%.1f s): %s"):format(r.t, r.steps, r.wall_s, r.stop_reason))
  print(fit.summary .. (", spread %.3f%%   (seed: a cylinder)"):format(100 * (fit.hi - fit.lo) / fit.exact))
  print(("contact angles min %.2f  max %.2f  mean %.2f degrees (exact 90)")
        :format(ca.min, ca.max, ca.mean))
  return r, fit
end

--- How far the film of body 1 is from the boundary of the scaled Wulff shape rW of gamma with
--- the same volume: max over the vertices of |gamma*(X_v)/r - 1| (0 exactly on the boundary of
--- rW centred at the origin; a relative distance in the Wulff metric), and r. With
--- `opts.half`, body 1 is the upper half (x3 >= 0) of rW resting on x3 = 0 (for a gamma even
--- in x3, so that it holds half of |rW|). |W| is that of froth.wulff_shape (level 4 plus the
--- facet directions: an outer polytope, within 0.3% of |W|, so r within 0.1%); needs CGAL.
--- For a drop on the plane z = 0: the centre of its rim (the mean of the vertices on z = 0) and
--- max_v |gamma*(x_v - centre) / S - 1|, how far the drop is from the Wulff shape S W centred on
--- its rim (the rim slides, so its centre, not the origin, is where the shape sits).
function M.rim_centred_wulff_deviation(c, gamma, S)
  local cx, cy, n = 0, 0, 0
  for v = 1, c:info().vertices do
    local x = c:vertex(v)
    if math.abs(x[3]) < 1e-9 then cx, cy, n = cx + x[1], cy + x[2], n + 1 end
  end
  cx, cy = cx / n, cy / n
  local dev = 0
  for v = 1, c:info().vertices do
    local x = c:vertex(v)
    dev = math.max(dev, math.abs(gamma:gamma_star(x[1] - cx, x[2] - cy, x[3]) / S - 1))
  end
  return dev, cx, cy
end

function M.wulff_deviation(c, gamma, opts)
  local W = froth.wulff_shape(gamma):volumes()[1]
  if opts and opts.half then W = W / 2 end
  local r = (c:volumes()[1] / W) ^ (1 / 3)
  local dev = 0
  for v = 1, c:info().vertices do
    dev = math.max(dev, math.abs(gamma:gamma_star(c:vertex(v)) / r - 1))
  end
  return dev, r
end

--- The standard double bubble of volumes V1 <= V2 with sigma = 1 (two spherical caps of radii
--- r1 <= r2 and a middle cap of radius r3 = r1 r2 / (r2 - r1), meeting at 120 degrees, so the
--- centres are d = sqrt(r1^2 + r2^2 - r1 r2) apart). Returns {area, r1, r2, r3, p1 = 2 / r1,
--- p2 = 2 / r2}. The junction plane is at a = (d^2 + r1^2 - r2^2) / (2 d) from centre 1, its
--- circle of radius rho = sqrt(r1^2 - a^2); bubble 1 is sphere 1's cap of height r1 + a plus the
--- lens of height h3 = r3 - sqrt(r3^2 - rho^2), bubble 2 sphere 2's cap of height r2 + d - a
--- minus the lens. The ratio r2 / r1 is found by bisection on V2 / V1, then the scale.
--- Equal volumes give 3 (9 pi)^(1/3) V^(2/3).
function M.standard_double_bubble(V1, V2)
  if V1 > V2 then V1, V2 = V2, V1 end
  local pi = math.pi
  local function cap(R, h) return pi * h * h * (3 * R - h) / 3 end
  local function shape(k) -- r1 = 1, r2 = k
    local d = math.sqrt(1 + k * k - k)
    local a = (d * d + 1 - k * k) / (2 * d)
    local rho = math.sqrt(1 - a * a)
    local h1, h2 = 1 + a, k + d - a
    local r3, h3 = math.huge, 0
    if k > 1 then
      r3 = k / (k - 1)
      h3 = r3 - math.sqrt(r3 * r3 - rho * rho)
    end
    local lens = k > 1 and cap(r3, h3) or 0
    local area = 2 * pi * (h1 + k * h2) + (k > 1 and 2 * pi * r3 * h3 or pi * rho * rho)
    return cap(1, h1) + lens, cap(k, h2) - lens, area, r3
  end
  local lo, hi = 1, 1e3
  for _ = 1, 200 do
    local mid = 0.5 * (lo + hi)
    local a, b = shape(mid)
    if b / a < V2 / V1 then lo = mid else hi = mid end
  end
  local k = 0.5 * (lo + hi)
  local v1, _, area, r3 = shape(k)
  local s = (V1 / v1) ^ (1 / 3)
  return {area = area * s * s, r1 = s, r2 = k * s, r3 = r3 * s, p1 = 2 / s, p2 = 2 / (k * s)}
end

--- The MacPherson-Srolovitz residuals of one MCF step of tau from `before` to `after`, two
--- c:grain_measures() of the same bodies: per grain |dV/dt - law| / (2 pi L), with dV/dt the
--- volume change over tau and law = -2 pi (L - e / 6) at the mean of the two states' mean
--- widths L and triple-line lengths e (normal velocity kappa, the sum of the principal
--- curvatures). `sixth` replaces 1/6 (to show that the law discriminates).
function M.macpherson_srolovitz(before, after, tau, sixth)
  assert(#before == #after, "macpherson_srolovitz: the same bodies before and after")
  sixth = sixth or 1 / 6
  local out = {}
  for b, g in ipairs(after) do
    local L = 0.5 * (before[b].mean_width + g.mean_width)
    local lines = 0.5 * (before[b].line_length + g.line_length)
    local rate = (g.volume - before[b].volume) / tau
    out[b] = math.abs(rate + 2 * math.pi * (L - sixth * lines)) / (2 * math.pi * L)
  end
  return out
end

return M
