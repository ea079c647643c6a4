-- Kelvin against Weaire-Phelan (docs/benchmarks.md "Foams"): the cost of a cell (its area,
-- films counted for both cells, over V^(2/3)) after c:minimize{} at each h, against the
-- literature (Kelvin 5.306, Weaire-Phelan 5.288: Weaire and Phelan, Phil. Mag. Lett. 69, 1994,
-- both from Surface Evolver).
--   froth bench/bench_foams.lua [foam=kelvin,weaire_phelan] [h=0.3,0.15,0.08,0.04] [max_iterations=1000]
--                               [hessian=0|1]  (1: Newton's steps below residual 1e-3, c:minimize's hessian)
-- Prints per foam and h: cells, vertices, facets, build and minimize seconds, iterations,
-- whether minimize converged (else why it stopped), the cost and its deviation from the
-- literature. Peak memory: run under /usr/bin/time -v (one foam and h per run).
local opts = require("froth.script").options({foam = "kelvin,weaire_phelan", h = "0.3,0.15,0.08",
                                              max_iterations = 1000, hessian = 0}, arg)
local known = {kelvin = 5.306, weaire_phelan = 5.288}
print("foam            h  cells  vertices   facets  build_s  minimize_s  iterations  newton  stop        cost      vs_known")
for foam in tostring(opts.foam):gmatch("[^,]+") do
  for h in tostring(opts.h):gmatch("[^,]+") do
    local t0 = os.clock()
    local c = froth[foam .. "_foam"]{h = tonumber(h)}
    local build = os.clock() - t0
    local r = c:minimize{max_iterations = opts.max_iterations, hessian = opts.hessian ~= 0}
    local info = c:info()
    local cost = 2 * c:energy() / info.bodies
    print(("%-14s %5s  %5d  %8d  %7d  %7.2f  %10.2f  %10d  %6d  %-10s  %.6f  %+.3f%%"):format(foam, h,
          info.bodies, info.vertices, info.facets, build, r.wall_s, r.iterations, r.hessian_steps,
          r.converged and "converged" or r.stop_reason:match("^[%a_]+"), cost,
          100 * (cost / known[foam] - 1)))
    io.stdout:flush()
  end
end
