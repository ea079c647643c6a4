-- datafiles/t1_band.lua — a T1 (the I -> H transition of foams) under surface diffusion:
-- three thin cells in a band around the equator of the unit ball (latitude -lat .. lat,
-- three 120-degree wedges) between two caps. The band's axis is a triple line between two
-- quadruple points; it shrinks, and at t ~ 0.011 evolve turns it into a small triangular film
-- between the caps (events: kind "T1"), splits the growing film's edges and goes on, the
-- volumes held exactly. With transitions=false the axis edge collapses and the run stops.
--
-- Sample runs:  froth datafiles/t1_band.lua
--               froth datafiles/t1_band.lua T=1 h=0.1
--               froth datafiles/t1_band.lua transitions=false
--               FROTH_SMOKE=1 froth datafiles/t1_band.lua  (ctest: 3 steps)
local script = require("froth.script")
local opts = script.options({lat = 0.2, h = 0.12, tau = 1e-3, T = 0.3, transitions = "true",
                             output = "", history = ""}, arg)

local pi = math.pi
local solids = {}
for k = 0, 2 do
  solids[k + 1] = {"ball", r = 1, angle = 2 * pi / 3, latitude = {-opts.lat, opts.lat},
                   rotate = {axis = {0, 0, 1}, angle = 2 * pi * k / 3}}
end
solids[4] = {"ball", r = 1, latitude = {opts.lat, pi / 2}}
solids[5] = {"ball", r = 1, latitude = {-pi / 2, -opts.lat}}
local c = froth.fragment{solids = solids, h = opts.h}
print(("band of three cells between two caps: %d vertices, %d triple lines, %d quadruple points")
      :format(c:info().vertices, #c:triple_lines(), #c:quadruple_points()))
local r = c:evolve(script.evolve_options(opts, {flow = "sd", tau = opts.tau,
                                                transitions = opts.transitions ~= "false"}))
for _, e in ipairs(r.events) do
  print(("t = %.4f (step %d): %s: %s; energy %.6f -> %.6f"):format(e.t, e.step, e.kind, e.where,
        e.energy_before, e.energy_after))
end
local rep = c:report()
print(("t = %g after %d steps: energy %.6f, %d quadruple points; upkeep: %d splits, %d flips, %d collapses")
      :format(r.t, r.steps, r.energy, #c:quadruple_points(), r.split_edges, r.flipped_edges,
              r.collapsed_edges))
print(("film angles %.2f..%.2f, quadruple angles %.2f..%.2f (equilibrium: 120, 109.47)")
      :format(rep.angles.min, rep.angles.max, rep.quadruple_angles.min, rep.quadruple_angles.max))
print("stop reason: " .. r.stop_reason)
