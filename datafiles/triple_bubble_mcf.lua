-- datafiles/triple_bubble_mcf.lua — seed §5.1.2: the triple bubble under mean curvature flow
-- shrinks to a point; the seed reports the vanishing at t ~ 0.178 (K = 6534, tau = 1e-4,
-- T = 0.15 shown). The parametric method cannot pass it: froth's topology watch sees the
-- bodies vanish just before; the three vanish together, two pop (events) and the last one
-- ends the run, the message saying which body and when.
--
-- Sample runs:  froth datafiles/triple_bubble_mcf.lua
--               froth datafiles/triple_bubble_mcf.lua vertices=2000
--               FROTH_SMOKE=1 froth datafiles/triple_bubble_mcf.lua  (ctest: 3 steps)
local script = require("froth.script")
local opts = script.options({vertices = 6500, tau = 1e-4, T = 0.25}, arg)

local c = froth.triple_bubble{vertices = opts.vertices}
print(("triple bubble: %d vertices"):format(c:info().vertices))
local r = c:evolve(script.evolve_options(opts, {flow = "mcf", tau = opts.tau}))
print(("stopped at t = %g after %d steps (seed: vanishes at t ~ 0.178)"):format(r.t, r.steps))
for _, e in ipairs(r.events) do print(("t = %g: %s: %s"):format(e.t, e.kind, e.where)) end
print("stop reason: " .. r.stop_reason)
