-- datafiles/pop_cells.lua — topological transitions under mean curvature flow: a small cell
-- (a ball of radius 0.2) sits at a quadruple point, on a triple line or on a film of the
-- seed's triple bubble. It shrinks fastest, the topology watch sees it vanish, and evolve pops
-- it (Evolver's `pop`): the cell collapses to a point, which becomes a quadruple point, a
-- point of the triple line or of the film, and the run goes on with the triple bubble until
-- that vanishes too (at t ~ 0.178, seed §5.1.2). Each pop is an entry of the result's events.
--
-- Sample runs:  froth datafiles/pop_cells.lua
--               froth datafiles/pop_cells.lua where=film h=0.1
--               FROTH_SMOKE=1 froth datafiles/pop_cells.lua  (ctest: 3 steps)
local script = require("froth.script")
local opts = script.options({where = "quadruple", h = 0.12, tau = 2e-4, T = 0.25}, arg)

local centres = {quadruple = {0, 0, 1}, triple = {0, 0, 0}, film = {0.5, 0, 0}}
local names = {quadruple = "at a quadruple point", triple = "on a triple line", film = "on a film"}
local centre = centres[opts.where]
if not centre then error("pop_cells: where must be quadruple, triple or film, got " .. opts.where) end
local solids = {{"ball", r = 0.2, translate = centre}}
for k = 0, 2 do
  solids[k + 2] = {"ball", r = 1, angle = 2 * math.pi / 3,
                   rotate = {axis = {0, 0, 1}, angle = 2 * math.pi * k / 3}}
end
local c = froth.fragment{solids = solids, h = opts.h}
local info = c:info()
print(("triple bubble with a small cell %s: %d vertices, %d bodies, %d quadruple points")
      :format(names[opts.where], info.vertices, info.bodies, #c:quadruple_points()))
local r = c:evolve(script.evolve_options(opts, {flow = "mcf", tau = opts.tau}))
for _, e in ipairs(r.events) do
  print(("t = %.4f (step %d): %s: %s; energy %.6f -> %.6f"):format(e.t, e.step, e.kind, e.where,
        e.energy_before, e.energy_after))
end
info = c:info()
print(("after %d steps, t = %g: %d bodies, %d triple lines, %d quadruple points")
      :format(r.steps, r.t, info.bodies, #c:triple_lines(), #c:quadruple_points()))
print("stop reason: " .. r.stop_reason)
