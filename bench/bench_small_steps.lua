-- Many small steps against few large ones at the same model time (docs/benchmarks.md "Small
-- steps and the mesh"):
--   froth bench/bench_small_steps.lua [cases=zero,fixed_t] [h=0.2] [zero_steps=4000]
--                                     [taus=1e-3,1e-4,1e-5] [T=0.02] [line_relaxation=1e-3]
-- zero: zero_steps MCF steps of tau = 1e-9 (a model time of 4e-6 at the default) on the
--   icosphere of level 3, the gmsh sphere of h = 0.2 and the double bubble of h (after 20 MCF
--   steps of 1e-3): a step's normal motion is O(tau), so the shape should not change; the
--   energy change, the triple line's mean radius and the smallest facet angle before and after.
-- fixed_t: the double bubble froth.double_bubble{h} evolved by surface diffusion and by MCF
--   to t = T with each tau of `taus`: the smallest facet angle and the energy at T, and where
--   the smallest angle is (a facet with how many triple-line vertices).
-- quad (not in the default cases; 3.5 minutes): froth.quadruple_bubble{vertices = 2500} by
--   surface diffusion (exact_volumes = false, tau = 1e-4 after a ramp from 1e-8, as
--   datafiles/quadruple_bubble.lua) to t = 0.1 with evolve's defaults, for line_relaxation =
--   0, 1e-5, 1e-4, 1e-3: the smallest angle at the end.
-- zero and fixed_t run without evolve's mesh upkeep and watch (transitions = false, watch = false): what
-- the steps alone do to the mesh; each with the seed's schemes (line_relaxation = 0) and with
-- the triple-line vertices relaxing along their lines in time (line_relaxation, numerics.md
-- "Line vertices along their lines").
local opts = require("froth.script").options({cases = "zero,fixed_t", h = 0.2, zero_steps = 4000,
                                              taus = "1e-3,1e-4,1e-5", T = 0.02,
                                              line_relaxation = 1e-3}, arg)
local cases = {}
for name in tostring(opts.cases):gmatch("[^,]+") do cases[name] = true end

local function ring(c)
  local lines = c:triple_lines()
  if #lines == 0 then return 0 end
  local vs, R = lines[1].vertices, 0
  for _, v in ipairs(vs) do
    local x = c:vertex(v)
    R = R + math.sqrt(x[1] ^ 2 + x[2] ^ 2) / #vs
  end
  return R
end

-- The facet with the smallest corner angle, and how many of its vertices lie on triple lines.
local function worst_facet(c)
  local V = c:vertices()
  local worst, line_vertices = 180, 0
  for _, f in ipairs(c:facets()) do
    local p = {V[f.vertices[1]].x, V[f.vertices[2]].x, V[f.vertices[3]].x}
    for k = 1, 3 do
      local o, a, b = p[k], p[k % 3 + 1], p[(k + 1) % 3 + 1]
      local u = {a[1] - o[1], a[2] - o[2], a[3] - o[3]}
      local w = {b[1] - o[1], b[2] - o[2], b[3] - o[3]}
      local cosine = (u[1] * w[1] + u[2] * w[2] + u[3] * w[3]) /
                     math.sqrt((u[1] ^ 2 + u[2] ^ 2 + u[3] ^ 2) * (w[1] ^ 2 + w[2] ^ 2 + w[3] ^ 2))
      local angle = math.deg(math.acos(math.max(-1, math.min(1, cosine))))
      if angle < worst then
        worst, line_vertices = angle, 0
        for j = 1, 3 do if V[f.vertices[j]].triple_line then line_vertices = line_vertices + 1 end end
      end
    end
  end
  return worst, line_vertices
end

if cases.zero then
  print(("== %d MCF steps of tau = 1e-9 (model time %.0e)"):format(opts.zero_steps, 1e-9 * opts.zero_steps))
  print("| cluster | vertices | line_relaxation | energy change | line radius change | smallest angle before | after |")
  print("|---|---:|---:|---:|---:|---:|---:|")
  local clusters = {
    {"icosphere, level 3", function() return froth.sphere{levels = 3} end},
    {"gmsh sphere, h = 0.2", function() return froth.sphere{h = 0.2} end},
    {("double bubble, h = %g"):format(opts.h), function()
      local c = froth.double_bubble{h = opts.h}
      c:evolve{flow = "mcf", tau = 1e-3, steps = 20, progress = false}
      return c
    end},
  }
  for _, case in ipairs(clusters) do
    local start = case[2]()
    for _, lr in ipairs{0, opts.line_relaxation} do
      local c = start:clone()
      local E, R, before = c:energy(), ring(c), worst_facet(c)
      -- without the mesh upkeep and the watch: the steps alone
      c:evolve{flow = "mcf", tau = 1e-9, steps = opts.zero_steps, progress = false, transitions = false,
               watch = false, line_relaxation = lr}
      print(("| %s | %d | %g | %.2e | %.2e | %.2f | %.2f |"):format(case[1], c:info().vertices, lr,
            c:energy() - E, ring(c) - R, before, (worst_facet(c))))
    end
  end
end

if cases.fixed_t then
  local base = froth.double_bubble{h = opts.h}
  print(("== froth.double_bubble{h = %g} (%d vertices, smallest angle %.2f) to t = %g"):format(
        opts.h, base:info().vertices, (worst_facet(base)), opts.T))
  print("| flow | line_relaxation | tau | steps | seconds | energy | smallest angle | its facet's line vertices |")
  print("|---|---:|---:|---:|---:|---:|---:|---:|")
  for _, flow in ipairs{"sd", "mcf"} do
    for _, lr in ipairs{0, opts.line_relaxation} do
      for tau in tostring(opts.taus):gmatch("[^,]+") do
        tau = tonumber(tau)
        local c = base:clone()
        local steps = math.floor(opts.T / tau + 0.5)
        local r = c:evolve{flow = flow, tau = tau, steps = steps, progress = false, transitions = false,
                           watch = false, line_relaxation = lr}
        local angle, on_line = worst_facet(c)
        print(("| %s | %g | %g | %d | %.1f | %.6f | %.2f | %d |%s"):format(flow, lr, tau, r.steps, r.wall_s,
              c:energy(), angle, on_line, r.stop_reason ~= "steps done" and (" " .. r.stop_reason) or ""))
      end
    end
  end
end

if cases.quad then
  local base = froth.quadruple_bubble{vertices = 2500}
  print(("== froth.quadruple_bubble{vertices = 2500} (%d vertices, smallest angle %.2f), SD to t = 0.1"):format(
        base:info().vertices, base:report().mesh.min_angle))
  print("| line_relaxation | steps | seconds | energy | smallest angle | film angles | collapsed edges |")
  print("|---:|---:|---:|---:|---:|---:|---:|")
  for _, lr in ipairs{0, 1e-5, 1e-4, 1e-3} do
    local c = base:clone()
    local r = c:evolve{flow = "sd", exact_volumes = false, tau = 1e-4, tau_start = 1e-8, T = 0.1,
                       progress = false, line_relaxation = lr}
    print(("| %g | %d | %.1f | %.6f | %.2f | %.2f-%.2f | %d |"):format(lr, r.steps, r.wall_s, r.energy,
          r.mesh.min_angle, r.angles.min, r.angles.max, r.collapsed_edges))
  end
end
