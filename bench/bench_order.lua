-- The temporal order of c:step{order = 1 | 2} (docs/benchmarks.md "Order in time"):
--   froth bench/bench_order.lua [cases=sphere,sd,bubble,auto] [levels=4] [relax=0] [sd_level=2]
--                               [bubble_h=0.2] [bubble_settle=0]
-- sphere: MCF of the icosphere (froth.sphere{levels}) to t = 0.05; errors of the energy and of
--   R from the volume against the same scheme at tau = T/1024 (the time error), and of R
--   against the exact sqrt(1 - 4t) (time and space).
-- sd: surface diffusion of r = 1 + 0.05 P2(cos theta) on the icosphere of level sd_level to t = 0.02,
--   relaxed first to BGN's tangential condition (1000 steps of 1e-9); energy error against
--   order 2 at T/1024, and error of the fitted P2 amplitude (a shape measure).
-- bubble: MCF of froth.double_bubble{h = bubble_h} to t = 0.02 after 20 order-1 steps of 1e-3;
--   energy, volume and the triple line's mean radius and height against order 2 at T/512;
--   bubble_settle > 0 settles the start by that many steps of 1e-9 first.
-- auto: tau = "auto" against fixed order-2 steps, MCF of the icosphere of level 2 to t = 0.24
--   (extinction at 0.25); error of R from the volume against order 2 at T/4096.
-- Slopes are log2 of the ratio of successive errors. Seconds are the run's wall time.
local opts = require("froth.script").options({cases = "sphere,sd,bubble,auto", levels = 4, relax = 0,
                                              sd_level = 2, bubble_h = 0.2, bubble_settle = 0},
                                             arg)
local cases = {}
for name in tostring(opts.cases):gmatch("[^,]+") do cases[name] = true end

local function radius(c) return (3 * c:volumes()[1] / (4 * math.pi)) ^ (1 / 3) end

-- relax > 0: after each run, that many steps of 1e-9 of the same flow settle BGN's tangential
-- condition without changing the shape (by 1e-9 per step), so what is left is the shape's error.
local function settle(c, flow)
  if opts.relax > 0 then c:evolve{flow = flow, tau = 1e-9, steps = opts.relax, progress = false} end
end

local function table_of(title, make, flow, T, ns, ref_n, measures)
  print(("== %s%s"):format(title, opts.relax > 0 and (", settled by %d steps of 1e-9"):format(
        opts.relax) or ""))
  local ref = make()
  ref:evolve{flow = flow, tau = T / ref_n, steps = ref_n, order = 2, progress = false}
  settle(ref, flow)
  local head = "order  tau        steps  seconds"
  for _, m in ipairs(measures) do head = head .. ("  %-10s slope"):format(m.name) end
  print(head)
  for order = 1, 2 do
    local last = {}
    for _, n in ipairs(ns) do
      local c = make()
      local r = c:evolve{flow = flow, tau = T / n, steps = n, order = order, progress = false}
      local line = ("%5d  %-9.3e  %5d  %7.3f"):format(order, T / n, n, r.wall_s)
      settle(c, flow)
      for k, m in ipairs(measures) do
        local e = math.abs(m.value(c, ref))
        local slope = last[k] and ("%5.2f"):format(math.log(last[k] / e, 2)) or "    -"
        line = line .. ("  %-10.3e %s"):format(e, slope)
        last[k] = e
      end
      print(line)
    end
  end
  print()
end

if cases.sphere then
  local T = 0.05
  local make = function() return froth.sphere{levels = opts.levels} end
  table_of(("MCF of the icosphere, level %d (%d vertices), to t = %g"):format(opts.levels,
           make():info().vertices, T), make, "mcf", T, {8, 16, 32, 64, 128}, 1024, {
    {name = "energy", value = function(c, ref) return c:energy() - ref:energy() end},
    {name = "R(vol)", value = function(c, ref) return radius(c) - radius(ref) end},
    {name = "R-exact", value = function(c) return radius(c) - math.sqrt(1 - 4 * T) end},
  })
end

-- Shape measures that do not depend on where the vertices sit on the surface (BGN's
-- tangential motion): the amplitude a of r = r0 + a P2(cos theta) fitted to the vertices by
-- least squares about the centroid, and the triple line's mean radius and height about the z
-- axis (the double bubble's axis of symmetry).
local function p2_amplitude(c)
  local n, g = c:info().vertices, {0, 0, 0}
  for v = 1, n do local x = c:vertex(v); for k = 1, 3 do g[k] = g[k] + x[k] / n end end
  local s11, s12, s22, b1, b2 = 0, 0, 0, 0, 0
  for v = 1, n do
    local x = c:vertex(v)
    local d = {x[1] - g[1], x[2] - g[2], x[3] - g[3]}
    local r = math.sqrt(d[1] ^ 2 + d[2] ^ 2 + d[3] ^ 2)
    local p = 1.5 * (d[3] / r) ^ 2 - 0.5
    s11, s12, s22, b1, b2 = s11 + 1, s12 + p, s22 + p * p, b1 + r, b2 + r * p
  end
  return (s11 * b2 - s12 * b1) / (s11 * s22 - s12 * s12)
end

local function ring(c)
  local vs = c:triple_lines()[1].vertices
  local R, z = 0, 0
  for _, v in ipairs(vs) do
    local x = c:vertex(v)
    R, z = R + math.sqrt(x[1] ^ 2 + x[2] ^ 2) / #vs, z + x[3] / #vs
  end
  return {R, z}
end

if cases.sd then
  local base = froth.sphere{levels = opts.sd_level}
  for v = 1, base:info().vertices do
    local x = base:vertex(v)
    local r = 1 + 0.05 * (1.5 * x[3] * x[3] - 0.5)
    base:set_vertex(v, r * x[1], r * x[2], r * x[3])
  end
  base:evolve{flow = "sd", tau = 1e-9, steps = 1000, progress = false}
  table_of(("SD of a P2 mode on the icosphere, level %d (%d vertices), to t = 0.02"):format(
           opts.sd_level, base:info().vertices),
           function() return base:clone() end, "sd", 0.02, {8, 16, 32, 64, 128}, 1024, {
    {name = "energy", value = function(c, ref) return c:energy() - ref:energy() end},
    {name = "P2 amp", value = function(c, ref) return p2_amplitude(c) - p2_amplitude(ref) end},
  })
end

if cases.bubble and froth.has("gmsh") then
  local base = froth.double_bubble{h = opts.bubble_h}
  base:evolve{flow = "mcf", tau = 1e-3, steps = 20, progress = false}
  if opts.bubble_settle > 0 then
    base:evolve{flow = "mcf", tau = 1e-9, steps = opts.bubble_settle, progress = false}
  end
  table_of(("MCF of the double bubble, h = %g (%d vertices), to t = 0.02 after t = 0.02"):format(
           opts.bubble_h, base:info().vertices), function() return base:clone() end, "mcf", 0.02,
           {4, 8, 16, 32, 64}, 512, {
    {name = "energy", value = function(c, ref) return c:energy() - ref:energy() end},
    {name = "volume 1", value = function(c, ref) return c:volumes()[1] - ref:volumes()[1] end},
    {name = "ring R", value = function(c, ref) return ring(c)[1] - ring(ref)[1] end},
    {name = "ring z", value = function(c, ref) return ring(c)[2] - ring(ref)[2] end},
  })
end

if cases.auto then
  local T = 0.24
  print(("== tau = \"auto\" against fixed steps: MCF of the icosphere, level 2, to t = %g"):format(T))
  local ref = froth.sphere{levels = 2}
  ref:evolve{flow = "mcf", tau = T / 4096, T = T, order = 2, progress = false}
  local function err(c) return math.abs(radius(c) - radius(ref)) / radius(ref) end
  print("run                 steps  rejected  seconds  error")
  for _, tol in ipairs{1e-3, 1e-4, 3e-5, 1e-5} do
    local c = froth.sphere{levels = 2}
    local r = c:evolve{flow = "mcf", tau = "auto", tol = tol, T = T, progress = false}
    print(("auto tol = %-7.0e  %5d  %8d  %7.3f  %.3e"):format(tol, r.steps, r.rejected_steps,
          r.wall_s, err(c)))
  end
  for _, n in ipairs{128, 256, 512, 1024} do
    local c = froth.sphere{levels = 2}
    local r = c:evolve{flow = "mcf", tau = T / n, T = T, order = 2, progress = false}
    print(("fixed, order 2      %5d  %8s  %7.3f  %.3e"):format(n, "", r.wall_s, err(c)))
  end
end
