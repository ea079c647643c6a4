-- Regression: the seed's triple bubble under mean curvature flow shrinks to a point at
-- t ~ 0.178 (§5.1.2: "shrinks to a point at t = 0.178"; tau = 1e-4). The parametric method
-- cannot pass the vanishing, so the topology watch must stop the run near that time with a
-- clear message and leave a valid state (transitions = false: by default the bodies would
-- pop, api_transitions.lua). About 2000 vertices; measured when written: 0.1761.
local T = require("froth.test")

local c = froth.triple_bubble{vertices = 2000}
local r = c:evolve{flow = "mcf", tau = 1e-4, T = 0.25, progress = false,
                   transitions = false}

T.assert_true(r.event ~= nil, "the run stops on a topology event", r.stop_reason)
T.assert_equal(r.event and r.event.kind, "vanishing body", "what stopped it")
T.assert_true(math.abs(r.t - 0.178) <= 0.05 * 0.178, "stops within 5% of t = 0.178", tostring(r.t))
T.assert_true(r.stop_reason:find("^topology: body %d is vanishing") ~= nil,
              "stop_reason names the body", r.stop_reason)
T.assert_true(r.stop_reason:find("at t = ", 1, true) ~= nil, "stop_reason says when", r.stop_reason)
local V = c:volumes()
T.assert_true(V[1] > 0 and V[2] > 0 and V[3] > 0, "the kept state is a valid cluster")
T.assert_equal(c:time(), r.t, "the cluster holds the state at the stop")
T.summary()
