-- froth.cluster from plain tables and the read-only froth.Cluster methods; every error of
-- froth.cluster, set_sigma, sigma, area and vertex, with the cluster left as it was.
local T = require("froth.test")

-- Two unit tetrahedra glued on the face {1, 2, 3}: the upper one has apex 4, the lower apex 5.
local V = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}}
local S = {{{1, 2, 4}, {2, 3, 4}, {3, 1, 4}}, -- surface 1: the upper cap
           {{2, 1, 5}, {3, 2, 5}, {1, 3, 5}}, -- surface 2: the lower cap
           {{1, 3, 2}}}                       -- surface 3: the shared wall (normal -z)
local function spec(over)
  local t = {vertices = V, surfaces = S, bodies = {{1, 3}, {2, 3}}}
  for k, v in pairs(over or {}) do t[k] = v end
  return t
end
local c = froth.cluster(spec())

-- Counts, exact volumes and areas: each cap is two right triangles (1/2) and an equilateral
-- one of side sqrt 2 (sqrt 3 / 2); each body is the tetrahedron of volume 1/6.
local info = c:info()
T.assert_equal(info.vertices, 5, "vertices")
T.assert_equal(info.facets, 7, "facets")
T.assert_equal(info.surfaces, 3, "surfaces")
T.assert_equal(info.triple_lines, 1, "triple lines")
T.assert_equal(info.quadruple_points, 0, "quadruple points")
T.assert_equal(info.bodies, 2, "bodies")
local vol = c:volumes()
T.assert_equal(#vol, 2, "two volumes")
T.assert_near(vol[1], 1 / 6, 1e-15, "upper tetrahedron volume")
T.assert_near(vol[2], 1 / 6, 1e-15, "lower tetrahedron volume")
local cap = 1 + math.sqrt(3) / 2
T.assert_near(c:area(1), cap, 1e-14, "area of surface 1")
T.assert_near(c:area(2), cap, 1e-14, "area of surface 2")
T.assert_near(c:area(3), 0.5, 1e-15, "area of surface 3")
T.assert_near(c:area(), 2 * cap + 0.5, 1e-14, "total area")
T.assert_near(c:energy(), 2 * cap + 0.5, 1e-14, "energy with sigma 1")
T.assert_equal(c:time(), 0, "time starts at 0")
T.assert_equal(c:sigma(2), 1, "default sigma")

-- set_sigma changes the energy to sum sigma_i |Gamma_i|, and nothing else.
c:set_sigma(3, 1.5)
T.assert_equal(c:sigma(3), 1.5, "sigma after set_sigma")
T.assert_near(c:energy(), 2 * cap + 1.5 * 0.5, 1e-14, "energy with sigma_3 = 1.5")
T.assert_near(c:area(3), 0.5, 1e-15, "set_sigma leaves the area")

-- vertex(i) returns a fresh copy of the position.
local x = c:vertex(4)
T.assert_true(x[1] == 0 and x[2] == 0 and x[3] == 1 and #x == 3, "vertex 4 is (0, 0, 1)")
x[3] = 7
T.assert_equal(c:vertex(4)[3], 1, "vertex() returns a copy")

-- Junctions and signed bodies: the wall's normal points down, out of body 1 and into body 2.
local lines = c:triple_lines()
T.assert_equal(#lines, 1, "one triple line")
T.assert_equal(lines[1].closed, true, "the line is a closed loop")
local lv = lines[1].vertices
table.sort(lv)
T.assert_true(#lv == 3 and lv[1] == 1 and lv[2] == 2 and lv[3] == 3, "line vertices {1,2,3}")
local ls = lines[1].surfaces
T.assert_true(#ls == 3 and ls[1] == 1 and ls[2] == 2 and ls[3] == 3, "line surfaces {1,2,3}")
T.assert_equal(#c:quadruple_points(), 0, "no quadruple points")
local b = c:bodies()
T.assert_true(#b == 2 and #b[1] == 2 and b[1][1] == 1 and b[1][2] == 3, "body 1 = {1, 3}")
T.assert_true(#b[2] == 2 and b[2][1] == 2 and b[2][2] == -3, "body 2 = {2, -3}")
-- The signs reproduce volumes() through the divergence theorem, computed here from scratch.
local function det(a, p, q) -- a . (p x q) / 6: the cone of a facet over the origin
  return (a[1] * (p[2] * q[3] - p[3] * q[2]) - a[2] * (p[1] * q[3] - p[3] * q[1]) +
          a[3] * (p[1] * q[2] - p[2] * q[1])) / 6
end
for i, body in ipairs(b) do
  local sum = 0
  for _, signed in ipairs(body) do
    for _, t in ipairs(S[math.abs(signed)]) do
      sum = sum + (signed > 0 and 1 or -1) * det(V[t[1]], V[t[2]], V[t[3]])
    end
  end
  T.assert_near(sum, vol[i], 1e-15, "signed surfaces of body " .. i .. " give its volume")
end

-- report() of a fresh cluster; the facets are right isosceles and equilateral triangles.
local r = c:report()
T.assert_equal(r.t, 0, "report t")
T.assert_near(r.energy, c:energy(), 0, "report energy")
T.assert_equal(r.volume_loss, 0, "no volume loss yet")
T.assert_equal(r.angles.count, 9, "three film angles at each of the 3 line vertices")
T.assert_near(r.mesh.min_angle, 45, 1e-12, "smallest facet angle")
T.assert_near(r.mesh.max_angle, 90, 1e-12, "largest facet angle")
T.assert_near(r.mesh.max_edge_ratio, math.sqrt(2), 1e-14, "edge ratio")
T.assert_near(r.mesh.min_area, 0.5, 1e-15, "smallest facet area")

-- tostring, and clones that share nothing.
T.assert_equal(tostring(c), "froth.Cluster (5 vertices, 7 facets, 3 surfaces, 1 triple lines, " ..
               "0 quadruple points, 2 bodies, t = 0.0)", "tostring")
local d = c:clone()
d:set_sigma(1, 2)
d:step{flow = "mcf", tau = 1e-3}
T.assert_equal(c:sigma(1), 1, "the original keeps its sigma")
T.assert_equal(d:sigma(3), 1.5, "the clone copied sigma")
T.assert_equal(c:time(), 0, "the original keeps its time")
T.assert_near(d:time(), 1e-3, 0, "the clone stepped")
T.assert_equal(c:vertex(4)[3], 1, "the original keeps its positions")
T.assert_true(d:vertex(4)[3] ~= 1, "the clone moved")

-- The {facets = ..., sigma = ...} form of a surface, and a cluster without bodies.
local e = froth.cluster{vertices = V, surfaces = {S[1], {facets = S[2], sigma = 1.75}, {facets = S[3]}}}
T.assert_equal(e:sigma(2), 1.75, "sigma from the surface table")
T.assert_equal(e:sigma(3), 1, "sigma defaults to 1")
T.assert_near(e:energy(), cap + 1.75 * cap + 0.5, 1e-14, "energy with sigma_2 = 1.75")
T.assert_equal(#e:volumes(), 0, "no bodies, no volumes")
T.assert_equal(e:info().bodies, 0, "bodies are optional")

-- A quadruple-point cluster: a regular tetrahedron cut from its centre 5 into four cells.
-- 10 single-facet surfaces (4 outer faces, 6 inner walls), 10 triple lines (the 6 outer edges
-- and 4 inner spokes), 5 quadruple points (centre and corners), each cell 1/4 of 8/3.
local QV = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}, {0, 0, 0}}
local QS, cells = {}, {}
for _, f in ipairs{{2, 3, 4}, {1, 4, 3}, {1, 2, 4}, {1, 3, 2}} do QS[#QS + 1] = {f} end
local walls = {}
for i = 1, 4 do
  for j = i + 1, 4 do
    QS[#QS + 1] = {{i, j, 5}}
    walls[i .. j] = #QS
  end
end
for k = 1, 4 do -- cell k lies against outer face k (the face opposite corner k)
  local body = {k}
  for i = 1, 4 do
    for j = i + 1, 4 do
      if i ~= k and j ~= k then body[#body + 1] = walls[i .. j] end
    end
  end
  cells[k] = body
end
local q = froth.cluster{vertices = QV, surfaces = QS, bodies = cells}
T.assert_equal(q:info().surfaces, 10, "quadruple cluster: surfaces")
T.assert_equal(q:info().triple_lines, 10, "quadruple cluster: triple lines")
T.assert_equal(q:info().quadruple_points, 5, "quadruple cluster: quadruple points")
local qp = q:quadruple_points()
table.sort(qp)
T.assert_true(#qp == 5 and qp[1] == 1 and qp[5] == 5, "every vertex is a quadruple point")
local open = 0
for _, l in ipairs(q:triple_lines()) do
  if not l.closed and #l.vertices == 2 then open = open + 1 end
end
T.assert_equal(open, 10, "ten open two-vertex triple lines")
T.assert_equal(q:report().angles, nil, "no angles where every line vertex is a quadruple point")
for k, v in ipairs(q:volumes()) do T.assert_near(v, 2 / 3, 1e-14, "cell " .. k .. " volume") end

-- Nested shells: a cube of side 1 inside a cube of side 2 (a bubble in a bubble). Body 1 = the
-- inner cube, body 2 = the shell between them, bounded by both surfaces; froth orients each
-- shell on its own and the inner one into the cavity: volumes 1 and 8 - 1 = 7, exactly.
local function cube(offset, side, first)
  local verts, tris = {}, {}
  for k = 0, 7 do
    verts[k + 1] = {offset + side * (k & 1), offset + side * ((k >> 1) & 1),
                    offset + side * ((k >> 2) & 1)}
  end
  for _, q in ipairs({{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2},
                      {1, 3, 7, 5}}) do -- faces, each outward
    tris[#tris + 1] = {first + q[1], first + q[2], first + q[3]}
    tris[#tris + 1] = {first + q[1], first + q[3], first + q[4]}
  end
  return verts, tris
end
local outer_v, outer_t = cube(-1, 2, 1)
local inner_v, inner_t = cube(-0.5, 1, 9)
for _, x in ipairs(inner_v) do outer_v[#outer_v + 1] = x end
for _, flip in ipairs({false, true}) do -- either orientation of the inner surface as given
  local t = inner_t
  if flip then
    t = {}
    for i, f in ipairs(inner_t) do t[i] = {f[1], f[3], f[2]} end
  end
  local nest = froth.cluster{vertices = outer_v, surfaces = {outer_t, t}, bodies = {{2}, {1, 2}}}
  T.assert_near(nest:volumes()[1], 1, 1e-14, "nested cubes: the inner body")
  T.assert_near(nest:volumes()[2], 7, 1e-14, "nested cubes: the shell is 8 - 1")
  local b = nest:bodies()
  T.assert_true(b[1][1] == -b[2][2], "the inner surface faces out of body 1, into the shell",
                b[1][1] .. " " .. b[2][2])
end

-- Errors of the methods, with the cluster unchanged.
T.check_error("surface 4 does not exist (the cluster has surfaces 1..3)", c.sigma, c, 4)
T.check_error("surface 0 does not exist", c.area, c, 0)
T.check_error("surface 4 does not exist", c.set_sigma, c, 4, 1)
T.check_error("number has no integer representation", c.sigma, c, 1.5)
T.check_error("vertex 6 does not exist (the cluster has vertices 1..5)", c.vertex, c, 6)
T.check_error("vertex 0 does not exist", c.vertex, c, 0)
T.check_error("froth.Cluster expected", c.info, {})
for _, bad in ipairs{0, -1, 0 / 0, math.huge} do
  T.check_error("set_sigma: surface 1: sigma must be positive", c.set_sigma, c, 1, bad)
end
T.check_error("number expected, got string", c.set_sigma, c, 1, "big")
T.assert_equal(c:sigma(1), 1, "a failed set_sigma keeps the old sigma")
T.check_error("set_sigma: the tensions at triple line 1 (surfaces 1, 2, 3: sigma 1, 1, 2) break the triangle inequality", c.set_sigma, c, 3, 2)
T.assert_equal(c:sigma(3), 1.5, "a set_sigma that breaks the triangle inequality keeps the old sigma")
T.assert_near(c:energy(), 2 * cap + 1.5 * 0.5, 1e-14, "a failed set_sigma keeps the energy")

-- Errors of froth.cluster: malformed tables.
local function bad(text, over) T.check_error(text, froth.cluster, spec(over)) end
T.check_error("cluster: expected an option table {...}, got number", froth.cluster, 5)
T.check_error("cluster: expected an option table {...}, got no value", froth.cluster)
T.check_error("cluster: surfaces must be a table, got nil", froth.cluster, {vertices = V})
T.check_error("cluster: vertices must be a table, got nil", froth.cluster, {surfaces = S})
bad("cluster: surfaces must be a table, got boolean", {surfaces = false})
bad("cluster: unknown option 'facets'", {facets = {}})
bad("cluster: bodies must be a table, got number", {bodies = 1})
bad("cluster: vertices[2] must have 3 coordinates", {vertices = {V[1], {1, 0}, V[3], V[4], V[5]}})
bad("cluster: vertices[2] must be a table, got string", {vertices = {V[1], "x", V[3], V[4], V[5]}})
bad("cluster: vertices[3][2] must be a number", {vertices = {V[1], V[2], {0, "1", 0}, V[4], V[5]}})
bad("cluster: surfaces[1][3][2] must be an integer id",
    {surfaces = {{{1, 2, 4}, {2, 3, 4}, {3, 1.5, 4}}, S[2], S[3]}})
bad("cluster: surfaces[2][1] must have 3 vertex ids", {surfaces = {S[1], {{2, 1}}, S[3]}})
bad("cluster: surfaces[2].facets must be a table, got number", {surfaces = {S[1], {facets = 2}, S[3]}})
bad("cluster: surfaces[2].sigma must be a number", {surfaces = {S[1], {facets = S[2], sigma = "1"}, S[3]}})
bad("cluster: bodies[2][2] must be a positive surface id", {bodies = {{1, 3}, {2, -3}}})
-- ... and invalid clusters (messages from the engine).
bad("cluster: no vertices", {vertices = {}})
bad("cluster: no surfaces", {surfaces = {}})
bad("cluster: surface 2 has no facets", {surfaces = {S[1], {}, S[3]}})
bad("cluster: surface 2 has sigma 0; sigma must be positive", {surfaces = {S[1], {facets = S[2], sigma = 0}, S[3]}})
bad("cluster: surface 2 has sigma -1; sigma must be positive", {surfaces = {S[1], {facets = S[2], sigma = -1}, S[3]}})
bad("cluster: vertex 2 has a non-finite coordinate", {vertices = {V[1], {0 / 0, 0, 0}, V[3], V[4], V[5]}})
bad("cluster: surface 1 facet 3 names vertex 6, but there are 5 vertices",
    {surfaces = {{{1, 2, 4}, {2, 3, 4}, {3, 1, 6}}, S[2], S[3]}})
bad("cluster: surface 1 facet 3 names vertex 0", {surfaces = {{{1, 2, 4}, {2, 3, 4}, {3, 1, 0}}, S[2], S[3]}})
bad("cluster: surface 3 facet 1 repeats a corner", {surfaces = {S[1], S[2], {{1, 3, 3}}}})
bad("cluster: vertex 6 is not a corner of any facet", {vertices = {V[1], V[2], V[3], V[4], V[5], {5, 5, 5}}})
-- vertex 5 on the segment 2-3: facet {3, 2, 5} of surface 2 is flat
bad("cluster: surface 2 facet 2 (vertices 3, 2, 5) has zero area",
    {vertices = {V[1], V[2], V[3], V[4], {0.5, 0.5, 0}}})
bad("cluster: edge 1-2 of surface 1 is a free boundary edge",
    {vertices = {V[1], V[2], V[3], V[4]}, surfaces = {S[1]}, bodies = {}})
bad("cluster: surface 1 is not consistently oriented: facets 2 and 1 both traverse edge 2-4",
    {surfaces = {{{1, 2, 4}, {3, 2, 4}, {3, 1, 4}}, S[2], S[3]}})
bad("cluster: body 1 is not closed: edge 1-2 is in 1 of its facets, not 2", {bodies = {{1}}})
bad("cluster: body 1 has no surfaces", {bodies = {{}}})
bad("cluster: body 2 names surface 4, but there are 3 surfaces", {bodies = {{1, 3}, {2, 4}}})
bad("cluster: body 2 names surface 2 twice", {bodies = {{1, 3}, {2, 2}}})
-- the single tetrahedron 1234 cut into two surfaces along its bottom face
local tet = {{{1, 2, 4}, {2, 3, 4}, {3, 1, 4}}, {{1, 3, 2}}}
bad("cluster: edge 1-2 is shared by exactly two surfaces (1 and 2); a film split in two",
    {vertices = {V[1], V[2], V[3], V[4]}, surfaces = tet, bodies = {}})
bad("cluster: edge 1-2 has three facets but only two surfaces",
    {surfaces = {{{1, 2, 4}, {2, 3, 4}, {3, 1, 4}, {2, 1, 5}, {3, 2, 5}, {1, 3, 5}}, S[3]}, bodies = {}})
-- four fins on the edge 1-2
bad("cluster: edge 1-2 is shared by 4 facets; only triple junction lines",
    {surfaces = {{{1, 2, 3}}, {{1, 2, 4}}, {{2, 1, 5}}, {{1, 2, 6}}}, bodies = {},
     vertices = {V[1], V[2], V[3], V[4], V[5], {0, -1, 0}}})

T.summary()
