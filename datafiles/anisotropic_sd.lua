-- datafiles/anisotropic_sd.lua — seed §5.2.2: anisotropic surface diffusion (3.8)/(3.11), beta = 1.
--   case=fig17     the double bubble of Fig. 4 with the regularised l1 norm (5.6), eps = 0.1
--   case=fig17b    the same with eps = 0.01
--   case=fig18     gamma_1 = (5.6) with eps = 0.01 on the outer film of body 1, gamma_2 = gamma_3 = |.|
--   case=fig19     the triple bubble of Fig. 11 with the hexagonal anisotropy of Fig. 2 right
--   case=fig20     the unit half sphere on x3 = 0 with gamma = |.| (or gamma=l1, fig3_left,
--                  fig3_right: the r = 30 anisotropies of Fig. 3, see below), evolving to the upper
--                  half of its Wulff shape
-- Each run checks what the seed's experiments claim: the energy |Gamma|_gamma never rises
-- (Theorem 3.2; also at 10x the seed's tau: tau=1e-2), the volumes are kept (loss <= 1%), and
-- the mesh stays free of degenerate facets (smallest angle printed). For fig20 the final film is
-- compared with the scaled Wulff shape rW of the same volume: the deviation is
-- max_v |gamma*(X_v) / r - 1| (0 exactly on the boundary of rW; relative, in the Wulff metric).
-- The seed: K = 3267, J = 6240, tau = 1e-3, T = 1 (Figs. 17/18); fig20: K = 4225, tau = 1e-3, T = 1.
--
-- Thin facets: with the nearly crystalline eps = 0.01 the scheme's tangential motion spreads
-- the vertices evenly in the anisotropy's metrics, not in the Euclidean one, and facets along
-- the sharp edges of the Wulff-like shapes become thin (smallest angle 0.2-0.9 degrees, edge
-- ratio 24-67) without collapsing: in fig19 the smallest angle falls to 0.41 degrees at
-- t = 0.08 and rises back to 0.50 at t = 0.3 while the energy settles. The topology watch
-- therefore flags a collapsing facet on nearly crystalline surfaces only below a tenth of its
-- usual 0.5 degrees (docs/lua_api.md, evolve's watch).
--
-- r = 30 (fig3_left, fig3_right): the nonlinear system of (3.9) is solved by Newton's method;
-- the first steps from the half sphere take tens of solves each, later ones 5-10
-- (docs/benchmarks.md). The Wulff distance uses froth.wulff_shape (needs CGAL).
--
-- Sample runs:  froth datafiles/anisotropic_sd.lua case=fig17
--               froth datafiles/anisotropic_sd.lua case=fig20 gamma=fig3_right
--               FROTH_SMOKE=1 froth datafiles/anisotropic_sd.lua   (ctest: 3 steps of each case)
local script = require("froth.script")
local measure = require("froth.measure")
local opts = script.options({case = "fig17", h = 0.08, vertices = 4000, tau = 1e-3, T = 1,
                             gamma = "isotropic", r = 1, eps = 0.01, output = ""}, arg)

local A = froth.anisotropies

--- The cluster and the anisotropy of each case.
local function setup(case)
  if case == "fig17" or case == "fig17b" or case == "fig18" then
    local c = froth.double_bubble{h = opts.h}
    local eps = case == "fig17" and 0.1 or 0.01
    if case == "fig18" then
      c:set_anisotropy(1, A.l1{eps = eps})
    else
      c:set_anisotropy("all", A.l1{eps = eps})
    end
    return c, ("double bubble, (5.6) eps = %g%s"):format(eps, case == "fig18" and " on surface 1 only" or "")
  elseif case == "fig19" then
    local c = froth.triple_bubble{vertices = opts.vertices}
    c:set_anisotropy("all", A.hexagonal{eps = 1e-2})
    return c, "triple bubble, hexagonal anisotropy (Fig. 2 right, eps = 0.01)"
  elseif case == "fig20" then
    local c = froth.half_ellipsoid_on_plane{levels = 6} -- K = 4225 like the seed's
    local g = opts.gamma == "isotropic" and A.isotropic(1)
              or opts.gamma == "l1" and A.l1{eps = opts.eps, r = opts.r}
              or opts.gamma == "fig3_left" and A.fig3_left{eps = opts.eps}
              or opts.gamma == "fig3_right" and A.fig3_right{eps = opts.eps}
              or error("gamma must be isotropic, l1, fig3_left or fig3_right")
    c:set_anisotropy(1, g)
    return c, ("half sphere on x3 = 0, %s"):format(tostring(g))
  end
  error("case must be fig17, fig17b, fig18, fig19 or fig20")
end

local cases = opts.smoke and {"fig17", "fig18", "fig19", "fig20"} or {opts.case}
for _, case in ipairs(cases) do
  local c, what = setup(case)
  local info = c:info()
  print(("%s: %s, %d vertices, %d facets"):format(case, what, info.vertices, info.facets))
  local worst, iterations = 0, 0
  local r = c:evolve(script.evolve_options(opts, {
    flow = "sd", exact_volumes = false, tau = opts.tau, tau_start = 1e-7,
    on_step = function(s)
      worst = math.max(worst, (s.energy - s.energy_before) / s.energy_before)
      iterations = math.max(iterations, s.fixed_point_iterations)
    end}))
  print(("  t = %.4g after %d steps (%.1f s): %s"):format(r.t, r.steps, r.wall_s, r.stop_reason))
  print(("  energy %.6f, largest relative energy increase of a step %.2e (Theorem 3.2: <= 0)")
        :format(r.energy, worst))
  print(("  volume loss %.3f%% (seed: < 1%%), smallest facet angle %.2f degrees, largest edge ratio"
         .. " in a facet %.1f, most fixed-point solves %d")
        :format(100 * r.volume_loss, r.mesh.min_angle, r.mesh.max_edge_ratio, iterations))
  local angles = c:report().angles
  if angles then
    -- Meaningful for smooth gamma (fig17: 0.022 at T = 1); with eps = 0.01 gamma' jumps with the
    -- normal and the measure is dominated by the fitted normals (0.13-0.57).
    print(("  triple lines: force imbalance of (2.3) %.3f (0 at the anisotropic equilibrium; the"
           .. " isotropic Young angles are off by %.1f degrees)"):format(angles.force_imbalance,
                                                                   angles.young_error))
  end
  if case == "fig20" then
    local dev, scale = measure.wulff_deviation(c, c:anisotropy(1) or A.isotropic(1), {half = true})
    print(("  distance to the scaled half Wulff shape (r = %.4f): max |gamma*(X)/r - 1| = %.2e")
          :format(scale, dev))
    local contact = c:report().contact_angles
    print(("  wall: residual of the contact condition (1.26b) %.3f, contact angles %.1f..%.1f")
          :format(contact.force_imbalance, contact.min, contact.max))
  end
end
