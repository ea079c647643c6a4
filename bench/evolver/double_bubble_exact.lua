-- The area of the standard double bubble of volumes (V1, V2), V1 <= V2: the reference of the
-- statics benchmark (statics.sh) for problems 1 and 2. Plain Lua (no froth API), so any Lua
-- 5.x runs it:
--   froth bench/evolver/double_bubble_exact.lua [V1=1] [V2=2]
-- prints the area to 13 digits and checks the (1, 1) case against 3 (9 pi)^(1/3).
--
-- Derivation. The bubble is a surface of revolution about the line of the sphere centres (the
-- x axis); in a half plane (x, y), y >= 0, its three films are circle arcs with centres on the
-- axis meeting at the triple point P = (0, a) (the triple circle lies in the plane x = 0,
-- radius a). Equal tensions balance only if the three arcs leave P at 120 degrees to each
-- other. Let the middle film (between the bodies) leave P towards the axis in the direction
-- t3 at angle theta3 = -90 + beta degrees (beta >= 0: it bulges into body 2, the larger one,
-- whose pressure is lower); the outer film of body 2 leaves at theta2 = theta3 + 120 =
-- 30 + beta, that of body 1 at theta1 = theta3 - 120 = 150 + beta (mod 360). An arc through
-- P tangent to the unit vector at angle theta has its centre on the normal, P + rho (-sin
-- theta, cos theta); on the axis (y = 0) that is rho = -a / cos theta, so
--   centre c = a tan theta,  radius r = a / |cos theta|:
--   r1 = a / cos(30 - beta), c1 = -a tan(30 - beta);  r2 = a / cos(30 + beta),
--   c2 = a tan(30 + beta);  r3 = a / sin beta, c3 = -a cot beta.
-- (1/r1 - 1/r2 = (cos(30 - beta) - cos(30 + beta)) / a = sin(beta) / a = 1/r3: the pressure
-- jumps add up, p1 - p2 = 2/r3, as the Laplace law says; and r3 = r1 r2 / (r2 - r1).)
-- The plane x = 0 cuts each sphere into caps; a cap of height h of a sphere of radius r has
-- area 2 pi r h and volume pi h^2 (3 r - h) / 3. Body 1 is the cap of sphere 1 on x < 0,
-- height h1 = r1 - c1, plus the lens between the plane and the middle film, the cap of sphere
-- 3 on x > 0 of height h3 = c3 + r3 = a tan(beta / 2); body 2 is the cap of sphere 2 on x > 0,
-- height h2 = r2 + c2, minus that lens. The area is the three caps' areas, the middle one
-- 2 pi r3 h3 = 2 pi a^2 / (1 + cos beta) (a flat disc pi a^2 at beta = 0). With a = 1 the
-- ratio V1 / V2 falls from 1 at beta = 0 to 0 at beta = 60 degrees; bisection finds the beta of the
-- wanted ratio, and scaling by s = (V1 / V1(a = 1))^(1/3) multiplies the area by s^2.
-- Check, beta = 0: r1 = r2 = r = 2a / sqrt 3, h1 = 3r/2, V1 = 9 pi r^3 / 8, area =
-- 2 (3 pi r^2) + pi (3 r^2 / 4) = 27 pi r^2 / 4 = 3 (9 pi)^(1/3) at V1 = 1.
local opts = {V1 = 1, V2 = 2}
for _, a in ipairs(arg or {}) do
  local k, v = a:match("^(%w+)=(.*)$")
  if not (k and opts[k] and tonumber(v)) then error("usage: double_bubble_exact.lua V1=.. V2=..") end
  opts[k] = tonumber(v)
end
local V1, V2 = math.min(opts.V1, opts.V2), math.max(opts.V1, opts.V2)
local pi, d = math.pi, math.pi / 180

-- volumes and area at a = 1 for the angle beta (radians)
local function bubble(beta)
  local r1, c1 = 1 / math.cos(30 * d - beta), -math.tan(30 * d - beta)
  local r2, c2 = 1 / math.cos(30 * d + beta), math.tan(30 * d + beta)
  local h1, h2, h3 = r1 - c1, r2 + c2, math.tan(beta / 2)
  local lens = beta > 0 and pi * h3 ^ 2 * (3 / math.sin(beta) - h3) / 3 or 0
  local v1 = pi * h1 ^ 2 * (3 * r1 - h1) / 3 + lens
  local v2 = pi * h2 ^ 2 * (3 * r2 - h2) / 3 - lens
  local area = 2 * pi * (r1 * h1 + r2 * h2) + 2 * pi / (1 + math.cos(beta))
  return v1, v2, area, r1, r2, 1 / math.sin(beta)
end

local function area_of(W1, W2)
  local lo, hi = 0, 60 * d -- V1 / V2 -> 0 as beta -> 60 degrees (r2 -> infinity, r1 -> a)
  for _ = 1, 200 do
    local mid = (lo + hi) / 2
    local v1, v2 = bubble(mid)
    if v1 / v2 > W1 / W2 then lo = mid else hi = mid end
  end
  local beta = (lo + hi) / 2
  local v1, v2, area, r1, r2, r3 = bubble(beta)
  local s = (W1 / v1) ^ (1 / 3)
  return area * s ^ 2, beta, s * r1, s * r2, s * r3, v2 * s ^ 3
end

local equal = area_of(1, 1)
local closed = 3 * (9 * pi) ^ (1 / 3)
assert(math.abs(equal - closed) < 1e-12 * closed, "the (1, 1) check failed")
local area, beta, r1, r2, r3, v2 = area_of(V1, V2)
print(("standard double bubble V = (%g, %g): area %.13f  (beta %.10f deg, r1 %.10f, r2 %.10f, " ..
       "r3 %.10f = r1 r2 / (r2 - r1) = %.10f, V2 check %.3e)"):format(V1, V2, area, beta / d, r1,
       r2, r3, r1 * r2 / (r2 - r1), v2 - V2))
print(("check V = (1, 1): %.13f against 3 (9 pi)^(1/3) = %.13f"):format(equal, closed))
