-- bench/bench_evolve.lua — the default scene (datafiles/double_bubble.lua) timed end to end:
-- the double bubble at h = 0.08 evolved by surface diffusion with tau = 1e-3 to T = 1
-- (1000 steps), without output. Prints one markdown table row (docs/benchmarks.md).
--
--   build-bench/froth bench/bench_evolve.lua               (about two minutes on 2 cores)
--   build-bench/froth bench/bench_evolve.lua h=0.1 T=0.1   (shorter)
local script = require("froth.script")
local opts = script.options({h = 0.08, tau = 1e-3, T = 1}, arg)

local c0 = os.clock()
local c = froth.double_bubble{h = opts.h}
local build_cpu = os.clock() - c0

local assemble = 0
local result = c:evolve{flow = "sd", exact_volumes = false, tau = opts.tau, T = opts.T, progress = false,
                        on_step = function(s) assemble = assemble + s.assemble_s end}

local V = c:volumes()
local exact = 3 * (9 * math.pi) ^ (1 / 3) * ((V[1] + V[2]) / 2) ^ (2 / 3)
print(("gmsh: %.2f s CPU; evolve: wall_s from the engine (steps + report, no output)"):format(build_cpu))
print(("stop: %s"):format(result.stop_reason))
print("| h | vertices | steps | T | factorizations | wall s | solve s | assembly s | s/step | area error | max volume loss | max dE/E |")
print("|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|")
print(("| %g | %d | %d | %g | %d | %.1f | %.1f (%.0f%%) | %.1f (%.0f%%) | %.4f | %+.3f%% | %.3f%% | %.1e |"):format(
  opts.h, c:info().vertices, result.steps, result.t, result.factorizations, result.wall_s,
  result.solve_s, 100 * result.solve_s / result.wall_s,
  assemble, 100 * assemble / result.wall_s, result.wall_s / result.steps,
  100 * (result.energy - exact) / exact, 100 * result.volume_loss, result.max_energy_increase))
