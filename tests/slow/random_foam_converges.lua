-- Slow regression: a random 64-cell foam minimised with transitions and Newton's steps
-- converges. froth.foam{n = 64, seed = 1, h = 0.4, lloyd = 50} (datafiles/random_foam.lua's
-- foam): the rounds make its T1s, inverse T1s, two-sided film collapses and film pinches, and
-- Newton's steps (hessian = true, below residual 1e-3) take it to residual 1e-6, where the plain
-- steps alone end at 2.5e-4 after 2000 iterations (docs/benchmarks.md "Foams", 2026-12-07).
-- Measured when written (8c66345): 601 iterations (110 Newton's) in 37 rounds, 460
-- transitions, residual 3.7e-7, cost 5.34930, 130 s CPU. Required: converged, volumes exact,
-- every Plateau point with its four lines, and the cost within 1e-4 of the plain steps' 5.34925
-- (`froth datafiles/random_foam.lua transitions=1 max_iterations=2000`, same doc): Newton's
-- equilibrium keeps the mesh's tangential layout, a difference of 9e-6 when written.
local T = require("froth.test")

local c = froth.foam{n = 64, seed = 1, h = 0.4, lloyd = 50}
local r = c:minimize{transitions = true, hessian = true, max_iterations = 3000}
local cost = 2 * r.energy / 64
print(("%d iterations (%d Newton's) in %d rounds, %d transitions, residual %.3g, cost %.6f, %s, %.0f s")
      :format(r.iterations, r.hessian_steps, r.rounds, #r.events, r.residual, cost, r.stop_reason, r.wall_s))
T.assert_true(r.converged, "the 64-cell foam converges", r.stop_reason)
T.assert_true(r.residual <= 1e-6 and r.volume_error <= 1e-12, "residual 1e-6, exact volumes",
              r.residual .. " " .. r.volume_error)
T.assert_true(r.hessian_steps > 0 and #r.events > 100, "through Newton's steps and transitions",
              r.hessian_steps .. " " .. #r.events)
T.assert_true(math.abs(cost - 5.34925) <= 1e-4 * 5.34925, "the plain steps' cost within 1e-4", tostring(cost))
T.assert_plateau_points(c)
T.summary()
