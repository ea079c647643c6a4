-- froth.measure: measurements of clusters that datafiles and tests share.
--   local measure = require("froth.measure")
--   local mean, lo, hi = measure.axis_distances(c)
--   local dev, r = measure.wulff_deviation(c, gamma, {half = true})
--   local r = measure.evolve_tracking_drift(c, {flow = "sd", tau = 1e-3, T = 1})
--   local fit = measure.cylinder_fit(c, rho)
local M = {}

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

--- The slab datafiles' run (cuboid_in_slab.lua, cylinder_in_slab.lua): SD with the script
--- options opts (tau, tau_start, T, every, output, rho; 3 steps when opts.smoke), then prints
--- the stop, the radii against the cylinder of the same volume and the contact angles.
--- Returns the evolve result (with largest_wall_drift) and the cylinder_fit.
function M.run_in_slab(c, opts)
  local r = M.evolve_tracking_drift(c, {
    flow = "sd", tau = opts.tau, tau_start = opts.tau_start,
    T = (not opts.smoke) and opts.T or nil, steps = opts.smoke and 3 or nil, every = opts.every,
    output = (opts.output ~= "" and not opts.smoke) and opts.output or nil})
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

return M
