-- Fixed vertices (Evolver's `fixed`): c:fix, c:unfix, c:fixed, froth.cluster{fixed}, the
-- `fixed` field of c:vertices records. Every scheme and minimize must leave a fixed vertex
-- exactly where it is (bit for bit: its displacement space is {0}), move the others, and keep
-- what it keeps without fixed vertices (exact volumes, non-increasing energy). The clusters are
-- built without gmsh (froth.box_cells, froth.cluster, froth.half_ellipsoid_on_plane).
local T = require("froth.test")

local function boxes()
  local c = froth.box_cells{x = {0, 1, 2}, y = {0, 1}, z = {0, 1}, cell = function(i) return i end}
  c:refine()
  return c
end

local function ids_of(records)
  local ids = {}
  for k, r in ipairs(records) do ids[k] = r.id end
  return ids
end

--- True if every vertex in `fixed` has the position of X, and some other vertex moved.
local function held(c, X, fixed)
  local is_fixed, moved = {}, false
  for _, v in ipairs(fixed) do is_fixed[v] = true end
  for v = 1, c:info().vertices do
    local x = c:vertex(v)
    local same = x[1] == X[v][1] and x[2] == X[v][2] and x[3] == X[v][3]
    if is_fixed[v] and not same then return false, "fixed vertex " .. v .. " moved" end
    if not is_fixed[v] and not same then moved = true end
  end
  return moved, "no free vertex moved"
end

-- Fix the top of the two boxes (z = 1): records from c:vertices{where} are accepted.
local c = boxes()
local top = c:vertices{where = function(v) return v.x[3] == 1 end}
T.assert_equal(c:fix(top), #top, "fix returns the number of fixed vertices")
local fixed = c:fixed()
T.assert_equal(#fixed, #top, "c:fixed() lists them")
for k, v in ipairs(ids_of(top)) do T.assert_equal(fixed[k], v, "in increasing order") end
T.assert_equal(#c:vertices{where = function(v) return v.fixed end}, #top, "records say fixed")

-- Each scheme holds them: MCF, the seed's SD, volume-exact SD, and minimize.
for _, case in ipairs{{flow = "mcf", tau = 1e-2}, {flow = "sd", tau = 1e-3, exact_volumes = false},
                      {flow = "sd", tau = 1e-3}} do
  local d = c:clone()
  T.assert_equal(#d:fixed(), #top, "clone keeps the fixed vertices")
  local X, E, V = T.positions(d), d:energy(), d:volumes()
  for _ = 1, 3 do d:step(case) end
  local ok, why = held(d, X, fixed)
  T.assert_true(ok, case.flow .. (case.exact_volumes == false and " (linear)" or "") ..
                ": fixed vertices held, the others move", why)
  T.assert_true(d:energy() < E, case.flow .. ": the energy falls", d:energy() .. " vs " .. E)
  if case.flow == "sd" and case.exact_volumes ~= false then
    for b = 1, 2 do
      T.assert_true(T.rel(d:volumes()[b], V[b]) <= 1e-12, "volume-exact SD with fixed vertices: body " .. b,
                    tostring(T.rel(d:volumes()[b], V[b])))
    end
  end
end
local m = c:clone()
local X = T.positions(m)
local r = m:minimize{tol = 1e-3}
T.assert_true(r.converged, "minimize converges with fixed vertices", r.stop_reason)
T.assert_true((held(m, X, fixed)), "minimize holds the fixed vertices")
for b = 1, 2 do
  T.assert_true(T.rel(m:volumes()[b], 1) <= 1e-12, "minimize with fixed vertices: volume " .. b .. " exact")
end
-- Without the top fixed the equilibrium is the standard double bubble, 9.1394 at exact
-- volumes; with the flat top held it must cost more.
local free = c:clone()
free:unfix(fixed)
T.assert_equal(#free:fixed(), 0, "unfix frees them")
free:minimize{tol = 1e-3}
T.assert_true(m:energy() > free:energy() + 0.1, "the held top costs energy",
              m:energy() .. " vs " .. free:energy())

-- refine: old fixed vertices stay fixed; the midpoint of an edge between two fixed vertices
-- is fixed when the edge lies in the held region (every facet at it has fixed corners only; or
-- it is a wire), no other: the top's rim edges, between the held top and the free sides, get
-- free midpoints (Evolver's edges are fixed only when fixed themselves).
local is_fixed, both = {}, 0
for _, v in ipairs(fixed) do is_fixed[v] = true end
local on_free = {}
for _, f in ipairs(c:facets()) do
  local a, b, d = table.unpack(f.vertices)
  local free = not (is_fixed[a] and is_fixed[b] and is_fixed[d])
  for _, e in ipairs{{a, b}, {b, d}, {d, a}} do
    local key = math.min(e[1], e[2]) .. "-" .. math.max(e[1], e[2])
    on_free[key] = on_free[key] or free
  end
end
local rim = 0
for _, e in ipairs(c:edges()) do
  local a, b = e.vertices[1], e.vertices[2]
  if is_fixed[a] and is_fixed[b] then
    if on_free[math.min(a, b) .. "-" .. math.max(a, b)] then rim = rim + 1 else both = both + 1 end
  end
end
T.assert_true(rim > 0 and both > 0, "the top has held edges inside and rim edges", rim .. " / " .. both)
local rc = c:clone()
rc:refine()
T.assert_equal(#rc:fixed(), #fixed + both, "refine: fixed vertices and the midpoints between two of them")
for _, v in ipairs(rc:vertices{where = function(v) return v.fixed end}) do
  T.assert_true(v.x[3] == 1, "refine: every fixed vertex is on the fixed top")
end

-- A wall cluster: fixing a rim vertex of a drop on a plane holds it on the wall.
local drop = froth.half_ellipsoid_on_plane{levels = 2}
local rim = drop:vertices{where = function(v) return #v.walls > 0 end}
drop:fix(rim[1].id)
X = T.positions(drop)
drop:step{flow = "sd", tau = 1e-3}
T.assert_true((held(drop, X, {rim[1].id})), "a fixed vertex on a wall stays put")

-- froth.cluster{fixed}: a tetrahedron with one vertex held.
local tet = {vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
             surfaces = {{facets = {{1, 3, 2}, {1, 2, 4}, {1, 4, 3}, {2, 3, 4}}}}, bodies = {{1}}}
tet.fixed = {4}
local t4 = froth.cluster(tet)
T.assert_equal(#t4:fixed(), 1, "froth.cluster{fixed}")
T.assert_equal(t4:fixed()[1], 4, "froth.cluster{fixed}: the vertex given")
tet.fixed = {9}
T.check_error("cluster: fixed vertex 9 does not exist (there are 4 vertices)", froth.cluster, tet)
tet.fixed = {"top"}
T.check_error("cluster: fixed: entry 1 is not a vertex id", froth.cluster, tet)

-- Bad input: a clear error, nothing changed.
local before = #c:fixed()
T.check_error("fix: expected a vertex id, an array of ids or of vertex records (c:vertices{...}), got string",
              c.fix, c, "top")
T.check_error("fix: entry 2 is not a vertex id", c.fix, c, {1, 0})
T.check_error("fix: entry 1 is not a vertex id", c.fix, c, {1.5})
T.check_error("fix: vertex 100000 does not exist (the cluster has vertices 1..", c.fix, c, {1, 100000})
T.check_error("unfix: vertex 100000 does not exist", c.unfix, c, 100000)
T.assert_equal(#c:fixed(), before, "a failed fix changes nothing")

-- Every vertex fixed: each flow and minimize leave the cluster as it is (an empty system; SD's
-- kappa block alone would be singular) and the time still advances.
local all = boxes()
all:fix(all:vertices())
local X0 = T.positions(all)
for _, flow in ipairs({"mcf", "sd"}) do
  local r = all:evolve{flow = flow, tau = 1e-3, steps = 2}
  T.assert_equal(r.stop_reason, "steps done", flow .. " with every vertex fixed runs")
  T.assert_true(T.same_positions(all, X0), flow .. " moves nothing")
end
T.assert_near(all:time(), 4e-3, 1e-15, "the time advances")
T.assert_equal(all:minimize{}.stop_reason, "converged", "minimize with nothing free converges")
T.assert_true(T.same_positions(all, X0), "minimize moves nothing")
T.summary()
