-- datafiles/torus_bubble_stretched.lua — seed §5.1.1, Fig. 9: a torus bubble with R = 2,
-- r = 0.5, stretched by the seed's maps G1 and G2 so that it is not rotationally symmetric.
-- Under surface diffusion the toroidal ring thins at one point and would tear (seed: t ~ 0.91,
-- torus/dumbbell volume 0.25); froth's topology watch stops the run there and says where.
--
-- The seed's text fits two constructions, and this file runs both (layout=ball or
-- layout=halves runs one; see froth.torus_bubble in docs/lua_api.md):
--   "ball"   the ball |x| <= 2 fragmented with the torus (froth's default; it matches the
--            seed's 1.28 for r = 1): torus/ball 0.211 (exact 0.2112); the ring (the torus
--            outside the ball, a crescent) thins at azimuth ~125 degrees and the run stops at
--            t = 0.268 (5300 vertices; 0.267 with 12000).
--   "halves" two half spheres standing on the torus's top and bottom circles, the torus
--            body the whole tube: torus/dumbbell 0.281 (exact 0.2836); the ring thins at
--            azimuth ~115 degrees and the run stops at t = 0.634 (5300 vertices; 0.637 with
--            10000), its z-thickness there 0.13 of initially 1.
-- Neither reaches the seed's 0.91: both rings tear where G1 and G2 stretch them lengthwise,
-- the thinner crescent first. The stretching sets the time: unstretched (h = 0.17) the rings
-- tear only at t = 1.44 ("ball") and 2.58 ("halves"); with "halves" and r = 0.45 (torus/
-- dumbbell 0.228) at t = 0.47. Surface diffusion's time scale itself is checked exactly
-- (tests/regression/sphere_sd_mode_decay.lua), so the difference is the seed's initial
-- cluster, which its text does not pin down. A third construction matches both of the seed's
-- volume relations: the whole tube as the torus and a ball of radius 2.34 minus the tube as
-- the dumbbell (froth.fragment{solids = {torus, ball r = 2.34}}: 1.272 for r = 1, 0.253
-- stretched; the radius is fitted, not in the seed); its ring tears at t = 0.718. The tear
-- times are not a resolution or start-up effect: 1500 vertices give 0.713 / 0.622 ("halves"),
-- a fixed tau = 1e-3 from t = 0 (no ramp, as in the seed) 0.71 / 0.62, and in every run the
-- ring's height falls from 0.5 to 0 within the last 0.03 of time.
--
-- Sample runs:  froth datafiles/torus_bubble_stretched.lua                 (about 80 s)
--               froth datafiles/torus_bubble_stretched.lua layout=halves vertices=10000
--               FROTH_SMOKE=1 froth datafiles/torus_bubble_stretched.lua (ctest: 3 steps each)
local script = require("froth.script")
local opts = script.options({vertices = 5300, tau = 1e-3, T = 2, layout = "both"}, arg)

local layouts = opts.layout == "both" and {"ball", "halves"} or {opts.layout}
local rows = {}
for _, layout in ipairs(layouts) do
  local c = froth.torus_bubble{r = 0.5, stretch = true, layout = layout,
                               vertices = opts.vertices}
  local V = c:volumes()
  print(("layout %-6s: %d vertices, torus/dumbbell volume %.4f (seed: 0.25)")
        :format(layout, c:info().vertices, V[2] / V[1]))
  -- tau_start: a ramp from the 90-degree junctions of the start
  local r = c:evolve(script.evolve_options(opts, {flow = "sd", exact_volumes = false, tau = opts.tau, tau_start = 1e-7}))
  print(("  t = %g after %d steps (%.0f s), volume loss %.3f%%"):format(r.t, r.steps, r.wall_s,
        100 * r.volume_loss))
  print("  stop reason: " .. r.stop_reason)
  rows[#rows + 1] = ("%-8s %8.4f %10.3f"):format(layout, V[2] / V[1], r.t)
end
print("\nlayout   torus/dumbbell   stops at t      (seed: 0.25, the ring tears at t ~ 0.91)")
for _, row in ipairs(rows) do print(row) end
