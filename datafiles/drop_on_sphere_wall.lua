-- datafiles/drop_on_sphere_wall.lua — a drop on a curved wall (the seed's (3.11) with
-- D = {|x| > R}; not one of its experiments): the half ball of radius r = 0.7 sheared onto the
-- sphere |x| = R = 2, first meeting it at 90 - asin(r / R) = 69.5 degrees. Under surface
-- diffusion it becomes the spherical cap of its volume meeting the wall at 90 degrees: the
-- sphere of radius a centred at (0, 0, sqrt(R^2 + a^2)), which cuts the wall orthogonally.
-- The rim moves in the wall's tangent planes (the linearised constraint), so it drifts off the
-- sphere by O(tau^2); project=1 moves it back after every step (not part of the scheme).
-- froth's volume closes the lid by a fan of chords, which lies below the wall by a sliver that
-- changes as the rim moves; the "true volume" below subtracts that sliver.
-- froth with these defaults (3156 vertices, 37 s on 2 cores): contact angles 89.74..90.08,
-- fitted sphere radius +0.02% of the orthogonal cap of the same volume (distances within
-- 0.03%), center height 2.09848 vs sqrt(R^2 + a^2) = 2.09841, true volume -0.033%, wall drift
-- 4.0e-5 (froth's own volume_loss 2.04%: the sliver).
--
-- Sample runs:  froth datafiles/drop_on_sphere_wall.lua
--               froth datafiles/drop_on_sphere_wall.lua h=0.1 project=1 output=
--               FROTH_SMOKE=1 froth datafiles/drop_on_sphere_wall.lua      (ctest: 3 steps)
local script = require("froth.script")
local opts = script.options({R = 2, r = 0.7, vertices = 3000, h = 0, tau = 1e-3,
                             tau_start = 1e-6, T = 1, project = 0, every = 100,
                             output = "out/drop_on_sphere_wall.pvd"}, arg)
local pi, R = math.pi, opts.R

local size = opts.h > 0 and {h = opts.h} or {vertices = opts.vertices}
local c = froth.drop_on_sphere_wall{R = R, r = opts.r, h = size.h, vertices = size.vertices}
local wall = c:walls()[1]
local info = c:info()
print(("drop of radius %g on the sphere wall |x| = %g: %d vertices, %d facets")
      :format(opts.r, R, info.vertices, info.facets))

-- The sliver between the fan (apex at the pole) and the sphere cap above the rim circle.
local function sliver(rho)
  local hc = R - math.sqrt(R * R - rho * rho)
  return pi * hc ^ 2 * (3 * R - hc) / 3 - pi * rho * rho * hc / 3
end
local function rim_radius()
  local sum, k = 0, 0
  for v = 1, c:info().vertices do
    local x = c:vertex(v)
    if wall:distance(x) < 1e-3 then sum, k = sum + math.sqrt(x[1] ^ 2 + x[2] ^ 2), k + 1 end
  end
  return sum / k
end
local function true_volume() return c:volumes()[1] - sliver(rim_radius()) end
local V0 = true_volume()

local drift = 0
local r = c:evolve{flow = "sd", tau = opts.tau, tau_start = opts.tau_start,
                   T = (not opts.smoke) and opts.T or nil, steps = opts.smoke and 3 or nil,
                   project = opts.project == 1, every = opts.every,
                   output = (opts.output ~= "" and not opts.smoke) and opts.output or nil,
                   on_step = function(s) drift = math.max(drift, s.wall_drift) end}

-- The sphere |x - (0, 0, z0)| = a through the film by least squares: |x|^2 = 2 z0 x3 + k.
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
local a = sum / n
-- The orthogonal cap of the drop's volume: 4 pi a^3 / 3 less the lens shared with |x| <= R.
local function cap_volume(b)
  local d = math.sqrt(R * R + b * b)
  return 4 * pi * b ^ 3 / 3 - pi * (R + b - d) ^ 2 * (d * d + 2 * d * b - 3 * b * b + 2 * d * R
                                                      + 6 * b * R - 3 * R * R) / (12 * d)
end
local blo, bhi = 1e-3, 10 * R
for _ = 1, 80 do
  local m = (blo + bhi) / 2
  if cap_volume(m) < V0 then blo = m else bhi = m end
end
local predicted = (blo + bhi) / 2
local V1 = true_volume()
local ca = r.contact_angles

print(("t = %.4g after %d steps (%.1f s): %s%s"):format(r.t, r.steps, r.wall_s, r.stop_reason,
      opts.project == 1 and " (projected onto the wall after every step)" or ""))
print(("contact angles min %.2f  max %.2f  mean %.2f degrees (exact 90)")
      :format(ca.min, ca.max, ca.mean))
print(("fitted sphere: radius %.5f (distances %+.2f%%..%+.2f%%), center height %.5f; orthogonal "
       .. "to the wall: sqrt(R^2 + a^2) = %.5f"):format(a, 100 * (lo / a - 1), 100 * (hi / a - 1),
      z0, math.sqrt(R * R + a * a)))
print(("radius of the orthogonal cap of the same volume %.5f (fitted %+.2f%%)")
      :format(predicted, 100 * (a / predicted - 1)))
print(("true volume %.6f -> %.6f (%+.3f%%); froth's volume_loss %.3f%% (the fan lid's sliver)")
      :format(V0, V1, 100 * (V1 / V0 - 1), 100 * r.volume_loss))
print(("wall drift: largest over the steps %.2e, now %.2e"):format(drift, r.wall_drift))
print(("largest relative energy increase of a step: %.2e (stability: <= 0%s)")
      :format(r.max_energy_increase, opts.project == 1 and "; not guaranteed with projection" or ""))
if not opts.smoke and opts.output ~= "" then print("ParaView series: " .. opts.output) end

return {result = r, cluster = c}
