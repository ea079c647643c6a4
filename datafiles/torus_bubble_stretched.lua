-- datafiles/torus_bubble_stretched.lua — seed §5.1.1, Figs. 9-10: a torus bubble with
-- R = 2, r = 0.5, stretched by the seed's maps G1 and G2 so that it is not rotationally
-- symmetric. Under surface diffusion the ring thins at one point and tears (seed: t ~ 0.91);
-- froth's topology watch stops the run there and says where.
-- Known difference: froth stops much earlier, at t ~ 0.27 (a crossing of the band, surface 4,
-- with the outer torus, surface 3, at 5300 vertices; a collapsing facet of surface 3 at
-- t = 0.267 with 12000 vertices, so not a resolution effect), and our torus/ball volume ratio
-- is 0.21 where the seed reports 0.25. With r = 0.54, which gives the seed's 0.25, the stop
-- moves only to t = 0.33. So the seed's construction of this cluster differs from ours in a
-- way the text does not pin down (see the issue 3 notes).
--
-- Sample runs:  froth datafiles/torus_bubble_stretched.lua
--               FROTH_SMOKE=1 froth datafiles/torus_bubble_stretched.lua (ctest: 3 steps)
local script = require("froth.script")
local opts = script.options({vertices = 5300, tau = 1e-3, T = 2}, arg)

local c = froth.torus_bubble{r = 0.5, stretch = true, vertices = opts.vertices}
local V = c:volumes()
print(("stretched torus bubble: %d vertices; torus/ball volume %.4f (seed: 0.25; the exact"
       .. " volume of the stretched solids is 0.2112, see docs/lua_api.md)")
      :format(c:info().vertices, V[2] / V[1]))
local r = c:evolve{flow = "sd", tau = opts.tau, tau_start = 1e-7, -- ramp: 90-degree start
                   T = (not opts.smoke) and opts.T or nil, steps = opts.smoke and 3 or nil}
print(("t = %g after %d steps, volume loss %.3f%%"):format(r.t, r.steps, 100 * r.volume_loss))
print("stop reason: " .. r.stop_reason .. " (seed: the ring tears at t ~ 0.91)")
