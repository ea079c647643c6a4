-- bench/bench_anisotropy.lua — the cost of anisotropy (issue 5): steps of the default double
-- bubble (SD) and of the structured half sphere on a plane (SD, K = 1089) with gamma = |.| (the
-- isotropic fast path), r = 1 anisotropies (one linear solve, a 9x9 element matrix per facet),
-- and the regularised l1 norm (5.6) with r = 3, 10, 30 and Fig. 3 right (r = 30): Newton's
-- method on the nonlinear system of (3.9), solves per step. Prints markdown rows for
-- docs/benchmarks.md.
--
--   build/froth bench/bench_anisotropy.lua              (a few minutes on 2 cores)
--   build/froth bench/bench_anisotropy.lua steps=5
local script = require("froth.script")
local opts = script.options({steps = 10, tau = 1e-3, h = 0.08}, arg)
local A = froth.anisotropies

local gammas = {
  {"none (isotropic fast path)", nil},
  {"isotropic(1) object", A.isotropic(1)},
  {"l1 eps 0.1, r = 1", A.l1{eps = 0.1}},
  {"hexagonal, r = 1", A.hexagonal{}},
  {"l1 eps 0.01, r = 3", A.l1{eps = 0.01, r = 3}},
  {"l1 eps 0.01, r = 10", A.l1{eps = 0.01, r = 10}},
  {"fig3_left (r = 30)", A.fig3_left{}},
  {"fig3_right (r = 30)", A.fig3_right{}},
}

local scenes = {
  {"double bubble", function() return froth.double_bubble{h = opts.h} end},
  {"half sphere on plane", function() return froth.half_ellipsoid_on_plane{levels = 5} end},
}

print(("SD, tau = %g, %d steps from the initial shape; s/step includes the report")
      :format(opts.tau, opts.steps))
print("| scene | vertices | gamma | s/step | solves/step | substeps | energy drop | outcome |")
print("|---|--:|---|--:|--:|--:|--:|---|")
for _, scene in ipairs(scenes) do
  for _, g in ipairs(gammas) do
    local c = scene[2]()
    if g[2] then c:set_anisotropy("all", g[2]) end
    local e0 = c:energy()
    local solves, substeps, done, outcome = 0, 0, 0, "ok"
    local t0 = os.clock()
    for _ = 1, opts.steps do
      local ok, r = pcall(c.step, c, {flow = "sd", exact_volumes = false, tau = opts.tau})
      if not ok then
        outcome = tostring(r):match("did not converge in %d+ solves") or tostring(r)
        break
      end
      done = done + 1
      solves = solves + math.max(1, r.fixed_point_iterations)
      substeps = substeps + r.substeps
    end
    local s = os.clock() - t0
    print(("| %s | %d | %s | %.4f | %.1f | %d | %.2f%% | %s |"):format(scene[1], c:info().vertices,
          g[1], done > 0 and s / done or s, solves / math.max(done, 1), substeps,
          100 * (1 - c:energy() / e0), outcome))
  end
end
