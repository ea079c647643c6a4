-- datafiles/triple_bubble_tensions.lua — seed §5.1.2, Fig. 12: the triple bubble with
-- sigma_1 = 1.25 and 1.5 (the other films 1). Surface 1 (the lune of body 1) is the heavier
-- film and shrinks relative to the others; the angles at the triple lines follow Young's law.
--
-- Sample runs:  froth datafiles/triple_bubble_tensions.lua vertices=2000 tau=2.5e-4
--               FROTH_SMOKE=1 froth datafiles/triple_bubble_tensions.lua (ctest: 3 steps)
local script = require("froth.script")
local opts = script.options({vertices = 6500, tau = 1e-4, T = 1}, arg)

for _, s1 in ipairs{1.25, 1.5} do
  local c = froth.triple_bubble{vertices = opts.vertices, sigma = {[1] = s1}}
  local share0 = c:area(1) / c:area()
  -- tau_start: a ramp from the 90-degree junctions of the start
  local r = c:evolve(script.evolve_options(opts, {flow = "sd", exact_volumes = false, tau = opts.tau, tau_start = 1e-7}))
  print(("sigma_1 = %g: t = %g, surface 1 holds %.2f%% of the area (%.2f%% at the start);"
         .. " Young's law deviation %.2f degrees, volume loss %.3f%%")
        :format(s1, r.t, 100 * c:area(1) / c:area(), 100 * share0, r.angles.young_error,
                100 * r.volume_loss))
end
