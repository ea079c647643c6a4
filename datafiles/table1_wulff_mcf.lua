-- datafiles/table1_wulff_mcf.lua — seed §5.2.1, Table 1: anisotropic mean curvature flow with
-- beta = gamma of the upper half of a Wulff shape standing on the plane x3 = 0, scheme (3.10).
-- gamma(p) = sqrt(p.Gp), G = diag(1, eps^2, eps^2) (L = 1); the exact solution (5.5) is the
-- shrinking half ellipsoid x(t) = sqrt(1 - 4t) G^(1/2) S^2_{>=0}, extinct at T = 1/4.
-- Error: max over the time steps of max over the vertices of the distance to x(t_m) (the
-- seed's definition, a Newton method for the closest point), up to T/2 and up to T - tau,
-- with tau = 0.125 h^2 (h the largest facet diameter of X^0).
--
-- The meshes are froth.half_ellipsoid_on_plane: the octahedral refinement of the half sphere,
-- K = (2^k + 1)^2 vertices like the seed's, but its h is smaller than the seed's at the same K
-- (0.195 vs 0.275 at K = 289: the seed's mesh is not described), so froth's tau is smaller too.
-- Compare at equal K (the table's rows) and mind the h column.
--
-- Sample runs:  froth datafiles/table1_wulff_mcf.lua                   (k = 4..7, both eps)
--               froth datafiles/table1_wulff_mcf.lua kmax=5 eps=0.5
--               FROTH_SMOKE=1 froth datafiles/table1_wulff_mcf.lua     (ctest: k = 3, up to T/2)
local script = require("froth.script")
local opts = script.options({kmin = 4, kmax = 7, eps = 0}, arg)

-- The seed's Table 1: K -> {h, error at T/2, error at T - tau} for eps = 0.5 and 0.1.
local seed = {
  [0.5] = {[289] = {2.7470e-01, 7.8899e-03, 1.0094e-01}, [1089] = {1.3957e-01, 2.2296e-03, 7.6033e-02},
           [4225] = {7.0067e-02, 5.8183e-04, 4.9572e-02}, [16641] = {3.5069e-02, 1.5238e-04, 3.0130e-02}},
  [0.1] = {[289] = {2.7076e-01, 4.6355e-03, 1.0020e-01}, [1089] = {1.3801e-01, 1.5169e-03, 7.6160e-02},
           [4225] = {6.9339e-02, 4.0686e-04, 4.9487e-02}, [16641] = {3.4711e-02, 1.2193e-04, 3.4094e-02}},
}

--- One row: the errors up to T/2 and up to T - tau, and the run's cost.
local function run(eps, k)
  local axes = {1, eps, eps}
  local c, h = froth.half_ellipsoid_on_plane{levels = k, axes = axes}
  c:set_anisotropy(1, froth.anisotropies.ellipsoidal{1, eps ^ 2, eps ^ 2})
  c:set_mobility(1, "gamma")
  -- tau = 0.125 h^2, rounded down so that T = 1/4 is an even number N of steps: then T/2 and
  -- T - tau are step times.
  local N = 2 * math.ceil(0.25 / (0.125 * h ^ 2) / 2)
  local tau = 0.25 / N
  local steps = opts.smoke and math.min(20, N // 2) or N - 1
  local err_half, err_end, energy_up = 0, 0, 0
  local t0 = os.clock()
  for m = 1, steps do
    local r = c:step{flow = "mcf", tau = tau}
    energy_up = math.max(energy_up, (r.energy - r.energy_before) / r.energy_before)
    local s = math.sqrt(1 - 4 * r.t)
    local e = c:ellipsoid_distance{s * axes[1], s * axes[2], s * axes[3]}
    err_end = math.max(err_end, e)
    if m <= N // 2 then err_half = err_end end
  end
  return {K = c:info().vertices, h = h, tau = tau, steps = steps, half = err_half, last = err_end,
          seconds = os.clock() - t0, energy_up = energy_up}
end

local rows = {} -- returned for tests/regression/table1_wulff_mcf.lua: rows[eps][K] = run(...)
local eps_list = opts.eps > 0 and {opts.eps} or {0.5, 0.1}
local kmin, kmax = opts.kmin, opts.kmax
if opts.smoke then kmin, kmax = 3, 3 end
for _, eps in ipairs(eps_list) do
  print(("eps = %g:  froth (h, error at T/2, error at T - tau)  |  seed (h, T/2, T - tau)"):format(eps))
  print("    K       h     tau     err T/2   err T-tau |     h      err T/2   err T-tau | ratio T/2, T-tau   steps      s")
  local prev
  for k = kmin, kmax do
    local r = run(eps, k)
    rows[eps] = rows[eps] or {}
    rows[eps][r.K] = r
    local s = seed[eps] and seed[eps][r.K]
    local seed_text = s and ("%7.4f  %.4e  %.4e | %5.2f  %5.2f"):format(s[1], s[2], s[3], r.half / s[2], r.last / s[3])
                      or "      (not in the seed's table)"
    print(("%6d  %6.4f  %.1e  %.4e  %.4e | %s  %6d  %6.1f"):format(r.K, r.h, r.tau, r.half, r.last,
          seed_text, r.steps, r.seconds))
    if prev and not opts.smoke then
      print(("        order T/2: %.2f   order T-tau: %.2f"):format(math.log(prev.half / r.half) / math.log(prev.h / r.h),
            math.log(prev.last / r.last) / math.log(prev.h / r.h)))
    end
    if r.energy_up > 1e-12 then print(("  energy rose by %.2e in some step"):format(r.energy_up)) end
    prev = r
  end
end

return {rows = rows, seed = seed}
