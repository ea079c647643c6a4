-- Time scale of surface diffusion: a sphere of radius 1 perturbed by a small zonal harmonic,
-- r = 1 + eps P_l(cos theta). Linearised, V = -Delta_s kappa damps the mode as
-- exp(-lambda_l t) with lambda_l = (l - 1) l (l + 1) (l + 2) / R^4 (24 for l = 2, 120 for
-- l = 3; Mullins 1957). The scheme is backward Euler in time, so over steps tau the discrete
-- rate is ln(1 + lambda tau) / tau (23.86 and 119.3 here). Checked within 2.5%: this pins the
-- flow's time scale (a wrong factor in (3.8) would show as 2x), which the energy and volume
-- tests do not. Measured at h = 0.07 (3114 vertices): 23.67 (l = 2), 118.76 (l = 3).
local T = require("froth.test")

local function legendre(l, c)
  if l == 2 then return 1.5 * c * c - 0.5 end
  return 2.5 * c ^ 3 - 1.5 * c
end

-- Least-squares amplitude of P_l in the radial deviation over the vertices (quasi-uniform).
local function amplitude(c, l)
  local n, rs, ps = c:info().vertices, {}, {}
  local mean = 0
  for v = 1, n do
    local x = c:vertex(v)
    local r = math.sqrt(x[1] ^ 2 + x[2] ^ 2 + x[3] ^ 2)
    rs[v], ps[v] = r, legendre(l, x[3] / r)
    mean = mean + r / n
  end
  local num, den = 0, 0
  for v = 1, n do
    num, den = num + (rs[v] - mean) * ps[v], den + ps[v] ^ 2
  end
  return num / den
end

local function decay_rate(l, eps, tau, duration)
  local c = froth.fragment{solids = {{"ball", r = 1}}, h = 0.07, transform = function(x, y, z)
    local r = math.sqrt(x * x + y * y + z * z)
    local f = (1 + eps * legendre(l, z / r)) / r
    return x * f, y * f, z * f
  end}
  local a0 = amplitude(c, l)
  T.assert_near(a0, eps, 0.02 * eps, ("l = %d: the mesh carries the mode"):format(l))
  local r = c:evolve{flow = "sd", exact_volumes = false, tau = tau, T = duration, progress = false}
  local rate = -math.log(amplitude(c, l) / a0) / r.t
  local expected = math.log(1 + (l - 1) * l * (l + 1) * (l + 2) * tau) / tau
  print(("l = %d  vertices = %d  steps = %d  rate = %.2f  backward Euler %.2f  (exact %d)")
        :format(l, c:info().vertices, r.steps, rate, expected, (l - 1) * l * (l + 1) * (l + 2)))
  T.assert_near(rate, expected, 0.025 * expected, ("l = %d decay rate"):format(l))
end

decay_rate(2, 0.01, 5e-4, 0.05)
decay_rate(3, 0.01, 1e-4, 0.01)
T.summary()
