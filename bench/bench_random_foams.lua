-- Random Voronoi foams (docs/benchmarks.md "Foams"): how the films' mesher and Lloyd's
-- relaxation of the sites decide how far c:minimize{} gets before a topology change stops it,
-- and with transitions=1 how far c:minimize{transitions = true} gets through its T1s.
--   froth bench/bench_random_foams.lua [n=16,64] [lloyd=0,5,20,50] [mesher=fan,gmsh] [h=0.4]
--                                      [transitions=0] [max_iterations=1000]
-- Prints per foam: cells, mesher, Lloyd steps, vertices, the smallest facet corner angle of
-- the fresh mesh (degrees, c:report().mesh.min_angle), minimize's
-- iterations and stop, and the cost (film area, each film counted for both its cells, over
-- V^(2/3), V = 1) at the start and at the stop. CPU seconds (os.clock) leave out gmsh's child
-- process: time one foam under /usr/bin/time -v for the build's wall time and memory.
local opts = require("froth.script").options({n = "16,64", lloyd = "0,5,20,50", mesher = "fan,gmsh",
                                              h = 0.4, transitions = 0, max_iterations = 1000}, arg)

print("cells  mesher  lloyd  vertices  min_angle  build_cpu_s  iterations  minimize_s  stop            cost_0   cost"
      .. (opts.transitions ~= 0 and "    rounds  transitions  residual" or ""))
for n in tostring(opts.n):gmatch("[^,]+") do
  for mesher in tostring(opts.mesher):gmatch("[^,]+") do
    for lloyd in tostring(opts.lloyd):gmatch("[^,]+") do
      local t0 = os.clock()
      local c = froth.foam{n = tonumber(n), seed = 1, h = tonumber(opts.h), lloyd = tonumber(lloyd), mesher = mesher}
      local build = os.clock() - t0
      local cost0 = 2 * c:energy() / tonumber(n)
      local angle = c:report().mesh.min_angle
      local r = c:minimize{max_iterations = opts.max_iterations, transitions = opts.transitions ~= 0}
      local stop = r.converged and "converged" or r.stop_reason:match("^[%a_]+")
      local line = ("%5s  %-6s  %5s  %8d  %9.2f  %11.2f  %10d  %10.2f  %-14s  %.4f  %.4f"):format(n, mesher,
            lloyd, c:info().vertices, angle, build, r.iterations, r.wall_s, stop, cost0, 2 * r.energy / tonumber(n))
      if r.rounds then line = line .. ("  %8d  %11d  %8.2g"):format(r.rounds, #r.events, r.residual) end
      print(line)
      io.stdout:flush()
    end
  end
end
