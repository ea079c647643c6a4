-- Scaling of a step with the vertex count (docs/benchmarks.md "Scale"): the icosphere
-- froth.sphere{levels = L} (10 * 4^L + 2 vertices), first steps and steady steps.
--   froth bench/bench_scale.lua [flow=mcf] [levels=5,6,7] [steps=4] [order=1] [tau=1e-3]
--   froth bench/bench_scale.lua h=0.0039 steps=3 order=2   (gmsh's sphere instead: 974k vertices)
--   froth bench/bench_scale.lua flow=sd sd_solver=blocks   (or lu; auto: blocks from 10^5 unknowns)
-- Prints per level: vertices, build seconds, first step (pattern, analysis, factorisation),
-- the mean of the later steps, their solve part, and factorisations. Peak memory: run under
-- /usr/bin/time -v (one level per run, since the peak is the process's).
local opts = require("froth.script").options({flow = "mcf", levels = "5,6,7", steps = 4,
                                              order = 1, tau = 1e-3, h = 0,
                                              sd_solver = "auto"}, arg)
print("flow  order  vertices  build_s  first_s  step_s  solve_s  unknowns  factorisations")
local sizes = {}
for level in tostring(opts.levels):gmatch("[^,]+") do sizes[#sizes + 1] = {levels = tonumber(level)} end
if opts.h > 0 then sizes = {{h = opts.h}} end
for _, size in ipairs(sizes) do
  local t0 = os.time()
  local c = froth.sphere(size)
  local build = os.time() - t0 -- wall seconds: gmsh meshes in a child process
  local first = c:step{flow = opts.flow, tau = opts.tau, order = opts.order,
                       sd_solver = opts.sd_solver}
  local first_s = first.assemble_s + first.solve_s
  local r = c:evolve{flow = opts.flow, tau = opts.tau, steps = opts.steps, order = opts.order,
                     sd_solver = opts.sd_solver, progress = false, watch = false}
  print(("%-4s  %5d  %8d  %7.2f  %7.2f  %6.3f  %7.3f  %8d  %d"):format(opts.flow, opts.order,
        c:info().vertices, build, first_s, r.wall_s / r.steps, r.solve_s / r.steps,
        first.unknowns, r.factorizations))
end
