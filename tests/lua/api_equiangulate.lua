-- c:equiangulate (Evolver's `u`): edge flips until every interior edge of a film is locally
-- Delaunay. Invariants: vertices never move, a flat film keeps its area, the result passes the
-- Delaunay test everywhere and a second call flips nothing; triple lines, walls, wires and held
-- faces are never flipped. (Evolver's own numbers for `u` are checked in api_fe.lua.)
local T = require("froth.test")

local function angle(p, a, b)
  local u = {a[1] - p[1], a[2] - p[2], a[3] - p[3]}
  local w = {b[1] - p[1], b[2] - p[2], b[3] - p[3]}
  local cx = {u[2] * w[3] - u[3] * w[2], u[3] * w[1] - u[1] * w[3], u[1] * w[2] - u[2] * w[1]}
  return math.atan(math.sqrt(cx[1] ^ 2 + cx[2] ^ 2 + cx[3] ^ 2), u[1] * w[1] + u[2] * w[2] + u[3] * w[3])
end

-- The largest sum of the two angles opposite an interior edge of one surface.
local function worst_angle_sum(c)
  local X, opposite = T.positions(c), {}
  for _, f in ipairs(c:facets()) do
    local v = f.vertices
    for k = 1, 3 do
      local a, b, p = v[k], v[k % 3 + 1], v[(k + 1) % 3 + 1]
      local key = math.min(a, b) .. "-" .. math.max(a, b) .. "-" .. f.surface
      opposite[key] = opposite[key] or {}
      table.insert(opposite[key], angle(X[p], X[a], X[b]))
    end
  end
  local worst = 0
  for _, list in pairs(opposite) do
    if #list == 2 then worst = math.max(worst, list[1] + list[2]) end
  end
  return worst
end

-- A flat rhombus split along its long diagonal: both opposite angles are obtuse.
local rhombus = {vertices = {{-2, 0, 0}, {0, -1, 0}, {2, 0, 0}, {0, 1, 0}},
                 surfaces = {{{1, 2, 3}, {1, 3, 4}}}, fixed = {1, 2, 3, 4}}
local held = froth.cluster(rhombus)
T.assert_true(worst_angle_sum(held) > math.pi, "the rhombus is not Delaunay")
T.assert_equal(held:equiangulate().flips, 0, "four fixed corners (a held face) do not flip")
-- A flat film on a stretched grid inside a fixed frame, its inner vertices jittered.
local function plate(n, jitter)
  local V, F, fixed = {}, {}, {}
  local function id(i, j) return j * (n + 1) + i + 1 end
  local seed = 7
  local function rnd() seed = (seed * 1103515245 + 12345) % 2147483648; return seed / 2147483648 - 0.5 end
  for j = 0, n do
    for i = 0, n do
      local edge = i == 0 or j == 0 or i == n or j == n
      local x, y = i / n, j / n
      if not edge then x, y = x + jitter * rnd() / n, y + jitter * rnd() / n end
      V[#V + 1] = {3 * x, y, 0} -- stretched: the regular split is far from Delaunay
      if edge then fixed[#fixed + 1] = #V end
    end
  end
  for j = 0, n - 1 do
    for i = 0, n - 1 do
      F[#F + 1] = {id(i, j), id(i + 1, j), id(i + 1, j + 1)}
      F[#F + 1] = {id(i, j), id(i + 1, j + 1), id(i, j + 1)}
    end
  end
  return {vertices = V, surfaces = {F}, fixed = fixed}
end
local c = froth.cluster(plate(8, 0.6))
local X, area = T.positions(c), c:area()
T.assert_true(worst_angle_sum(c) > math.pi + 0.1, "the plate starts far from Delaunay", worst_angle_sum(c))
local r = c:equiangulate()
T.assert_true(r.flips > 10, "the plate: edges flipped", r.flips)
T.assert_true(r.sweeps >= 1, "the plate: sweeps counted", r.sweeps)
T.assert_true(T.same_positions(c, X), "the vertices do not move")
T.assert_near(c:area(), area, 1e-13, "a flat film keeps its area")
T.assert_equal(c:info().facets, 128, "as many facets as before")
T.assert_true(worst_angle_sum(c) <= math.pi + 1e-9, "every interior edge is locally Delaunay", worst_angle_sum(c))
T.assert_equal(c:equiangulate().flips, 0, "a second pass flips nothing")

-- A double bubble: its triple line and bodies are kept, volumes change a little.
if froth.has("gmsh") then
  local db = froth.double_bubble{h = 0.25}
  local line = #db:edges{where = function(e) return e.triple_line end}
  local before, v0 = db:info(), db:volumes()
  local u = db:equiangulate()
  local after, v1 = db:info(), db:volumes()
  local change = math.max(math.abs(v1[1] - v0[1]) / v0[1], math.abs(v1[2] - v0[2]) / v0[2])
  T.assert_true(u.flips > 0, "double bubble: edges flipped", u.flips)
  T.assert_near(u.volume_change, change, 1e-15, "double bubble: volume_change is the largest relative change")
  T.assert_equal(#db:edges{where = function(e) return e.triple_line end}, line, "double bubble: the triple line keeps its edges")
  T.assert_equal(after.triple_lines, before.triple_lines, "double bubble: triple lines kept")
  T.assert_equal(after.bodies, 2, "double bubble: two bodies")
  T.assert_true(u.volume_change < 1e-2, "double bubble: a small volume change", u.volume_change)
  T.assert_true(worst_angle_sum(db) <= math.pi + 1e-9, "double bubble: Delaunay after", worst_angle_sum(db))
end

-- Errors.
T.check_error("equiangulate: max_sweeps must be in 1..1000000, got 0", c.equiangulate, c, {max_sweeps = 0})
T.check_error("equiangulate: unknown option 'sweeps'", c.equiangulate, c, {sweeps = 3})
local busy = froth.cluster(plate(4, 0.3))
T.check_error("equiangulate: the cluster is busy", busy.evolve, busy,
              {flow = "mcf", tau = 1e-3, steps = 1, on_step = function() busy:equiangulate() end})
T.summary()
