-- c:vertices{where}, c:facets{where}, c:edges{where}, c:set_vertex: attributes checked against
-- invariants of the two-cell box cluster (exact combinatorics, no gmsh).
local T = require("froth.test")
local c = froth.box_cells{x = {0, 1, 2}, y = {0, 1}, z = {0, 1}, cell = function(i) return i end}
local info = c:info()

local V = c:vertices()
T.assert_equal(#V, info.vertices, "every vertex listed")
for i, v in ipairs(V) do
  T.assert_equal(v.id, i, "vertex ids in order")
  local x = c:vertex(i)
  T.assert_true(v.x[1] == x[1] and v.x[2] == x[2] and v.x[3] == x[3], "vertex position")
end
local line = c:vertices{where = function(v) return v.triple_line end}
T.assert_equal(#line, #c:triple_lines()[1].vertices, "triple-line vertices are the line's")
for _, v in ipairs(line) do
  T.assert_equal(#v.surfaces, 3, "a line vertex is on three surfaces")
  T.assert_equal(#v.bodies, 2, "and on both bodies")
  T.assert_equal(v.x[1], 1, "the line lies in the shared wall x = 1")
end
T.assert_equal(#c:vertices{where = function(v) return v.quadruple_point end}, 0, "no quadruple points")

local F = c:facets()
T.assert_equal(#F, info.facets, "every facet listed")
local area, shared = 0, 0
for _, f in ipairs(F) do
  area = area + f.area
  T.assert_near(math.sqrt(f.normal[1] ^ 2 + f.normal[2] ^ 2 + f.normal[3] ^ 2), 1, 1e-15, "unit normal")
  if #f.bodies == 2 then shared = shared + f.area end
end
T.assert_near(area, c:area(), 1e-14, "facet areas sum to the area")
T.assert_near(shared, 1, 1e-15, "the shared wall (in both bodies) has area 1")

local E = c:edges()
local triple = c:edges{where = function(e) return e.triple_line end}
T.assert_equal(#triple, 4, "the triple line has 4 edges")
T.assert_equal(#E, (3 * info.facets - #triple) // 2, "3F = 2E + (triple edges): every edge listed once")
T.assert_equal(#c:edges{where = function(e) return e.boundary end}, 0, "closed cells: no free boundary edges")
local long = 0
for _, e in ipairs(E) do long = math.max(long, e.length) end
T.assert_near(long, 1, 1e-15, "the longest edges are the unit lattice edges")

-- errors
T.check_error("vertices: option 'where' must be a function", c.vertices, c, {where = 3})
T.check_error("facets: unknown option 'wher'", c.facets, c, {wher = print})
T.check_error("boom", c.edges, c, {where = function() error("boom") end})

-- set_vertex
local E0 = c:energy()
c:set_vertex(1, {-0.1, 0, 0})
T.assert_equal(c:vertex(1)[1], -0.1, "set_vertex moves the vertex")
T.assert_true(c:energy() ~= E0, "and the energy follows")
local before = c:vertex(1)
T.check_error("set_vertex: vertex 1: the point must be finite", c.set_vertex, c, 1, {0 / 0, 0, 0})
T.check_error("vertex 99 does not exist", c.set_vertex, c, 99, {0, 0, 0})
local far = c:vertex(7) -- move vertex 6 onto a neighbour: some facet collapses
T.check_error("zero area; nothing changed", c.set_vertex, c, 6, far)
T.assert_equal(c:vertex(1)[1], before[1], "a refused set_vertex changes nothing")
T.check_error("set_vertex: the cluster is busy", c.evolve, c,
              {flow = "mcf", tau = 1e-3, steps = 1, on_step = function() c:set_vertex(1, {0, 0, 0}) end})
-- c:body_report(): Evolver's `v`
local b = froth.box_cells{x = {0, 1, 2}, y = {0, 1}, z = {0, 1}, cell = function(i) return i end}
b:set_volume(2, 1.5)
b:minimize{}
local rep, p = b:body_report(), b:pressures()
T.assert_equal(#rep, 2, "one row per body")
for i, row in ipairs(rep) do
  T.assert_equal(row.body, i, "body id")
  T.assert_equal(row.pressure, p[i], "the pressure is c:pressures()'s")
  T.assert_equal(row.target, b:target_volumes()[i], "target volume")
  T.assert_near(row.volume, row.target, 1e-12 * row.target, "at its target after minimize")
  T.assert_equal(table.concat(row.surfaces, " "), table.concat(b:bodies()[i], " "), "signed surfaces")
end
T.assert_true(rep[1].pressure > rep[2].pressure, "the smaller cell has the larger pressure")
local tet = froth.cluster{vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                          surfaces = {{{1, 3, 2}, {1, 2, 4}, {2, 3, 4}, {1, 4, 3}}}}
T.assert_equal(#tet:body_report(), 0, "no bodies, no rows")

-- c:film_angles(): the report's film angles vertex by vertex. Two unit cubes side by side:
-- where their flat outer films meet the wall between them the angles are 90, 180 (facing the
-- wall) and 90, exactly where each film's fitted two-ring stays on one flat face (the line's
-- vertices at 1/4 .. 3/4 of its length, after three refinements).
local boxes = froth.box_cells{x = {0, 1, 2}, y = {0, 1}, z = {0, 1}, cell = function(i) return i end}
for _ = 1, 3 do boxes:refine() end
local wall = nil
for s = 1, boxes:info().surfaces do
  local flat = true
  for _, f in ipairs(boxes:facets{where = function(f) return f.surface == s end}) do
    for _, v in ipairs(f.vertices) do flat = flat and boxes:vertex(v)[1] == 1 end
  end
  if flat then wall = s end
end
T.assert_true(wall ~= nil, "the wall between the cubes is one surface")
local film_angles, inner, exact = boxes:film_angles(), 0, 0
local report = boxes:report().angles
T.assert_equal(#film_angles * 3, report.count, "three angles per line vertex, as the report counts")
local least, most = 360, 0
for _, a in ipairs(film_angles) do
  T.assert_equal(#a.surfaces, 3, "a line vertex has three films")
  for i = 1, 3 do least, most = math.min(least, a.angles[i]), math.max(most, a.angles[i]) end
  local x = boxes:vertex(a.vertex)
  local along = (x[2] == 0 or x[2] == 1) and x[3] or x[2] -- the coordinate along its line
  if along >= 0.25 and along <= 0.75 then
    inner = inner + 1
    local ok = true
    for i = 1, 3 do
      local expected = a.surfaces[i] == wall and 180 or 90
      ok = ok and math.abs(a.angles[i] - expected) < 1e-9
    end
    if ok then exact = exact + 1 end
    T.assert_near(a.young_error, 60, 1e-9, "Young's 120 against 90/180/90")
  end
end
T.assert_equal(inner, 20, "five vertices in the middle half of each of the four lines")
T.assert_equal(exact, inner, "90, 180 facing the wall, 90 where the fits see flat faces")
T.assert_equal(least, report.min, "the smallest angle is the report's")
T.assert_equal(most, report.max, "the largest angle is the report's")
T.assert_equal(#froth.sphere{levels = 1}:film_angles(), 0, "no triple lines, no angles")
T.summary()
