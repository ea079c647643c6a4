-- Regression: minimize with transitions goes on past a sliver its upkeep leaves. A 27-cell
-- Voronoi foam (seed 3, 5 Lloyd steps): after its transitions a facet below 0.1 degree is left
-- that no collapse or flip removes, five times in 100 iterations. Until 2026-12-06 the rounds
-- stopped at the first; now such a sliver (above 0.01 degree) is deferred: the next round
-- starts with it, and the rounds and their transitions go on to max_iterations. The
-- relaxation stays a relaxation: exact volumes, a lower energy, every Plateau point with its
-- four lines, no crossing. (The case was seed 6 until its rounds started at the last round's
-- tau, 2026-12-07: the runs are chaotic, and seed 6 then met a sliver below 0.01 degree after
-- 97 iterations, the hard limit; seed 3 defers five slivers and reaches 100.)
local T = require("froth.test")

local start = froth.foam{n = 27, seed = 3, h = 0.4, lloyd = 5}
local c = start:clone()
local r = c:minimize{max_iterations = 100, transitions = true}
print(("%s after %d iterations in %d rounds, %d transitions, %d deferred, energy %.9g -> %.9g")
      :format(r.stop_reason:sub(1, 80), r.iterations, r.rounds, #r.events, r.deferred or 0,
              start:energy(), c:energy()))
T.assert_true((r.deferred or 0) >= 1, "a round started with a sliver the upkeep left", tostring(r.deferred))
T.assert_true(r.iterations == 100, "the rounds go on to max_iterations",
              r.iterations .. " iterations: " .. r.stop_reason)
T.assert_true(#r.events >= 10, "through transitions", tostring(#r.events))
T.assert_true(c:energy() < start:energy(), "to a lower energy",
              ("%.9g against %.9g"):format(c:energy(), start:energy()))
T.assert_true(r.volume_error <= 1e-10, "at the target volumes", tostring(r.volume_error))
T.assert_plateau_points(c)
-- the watch's crossing test (CGAL) on the state left, by a step too short to move it
local w = c:clone():evolve{flow = "mcf", tau = 1e-12, steps = 1, progress = false,
                           transitions = false, watch = {self_intersection_every = 1,
                           min_facet_angle = 1e-9, min_edge_fraction = 1e-9}}
T.assert_true(not (w.event and w.event.kind == "self-intersection"), "no film crosses another",
              w.stop_reason)
T.summary()
