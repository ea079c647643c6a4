-- c:write to .vtu/.off/.ply/.msh, froth.read of .msh files, froth.has; and their errors.
local T = require("froth.test")

local dir = os.tmpname()
os.remove(dir) -- a fresh name: write creates the missing folder
local written = {}
local function path(name)
  written[#written + 1] = dir .. "/" .. name
  return written[#written]
end
local function slurp(p)
  local f = io.open(p, "rb")
  if not f then return "" end
  local s = f:read("a")
  f:close()
  return s
end

-- The two glued tetrahedra after one step (so that coordinates are not round numbers).
local V = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}}
local S = {{{1, 2, 4}, {2, 3, 4}, {3, 1, 4}}, {{2, 1, 5}, {3, 2, 5}, {1, 3, 5}}, {{1, 3, 2}}}
local c = froth.cluster{vertices = V, surfaces = S, bodies = {{1, 3}, {2, 3}}}
c:step{flow = "sd", tau = 1e-3}
local E, vol = c:energy(), c:volumes()

-- write returns nothing and changes nothing.
T.assert_equal(select("#", c:write(path("tets.off"))), 0, "write returns no values")
c:write(path("tets.ply"))
c:write(path("tets.vtu"))
c:write(path("tets.MSH")) -- extensions are case-insensitive
T.assert_true(c:energy() == E and c:time() == 1e-3, "write leaves the cluster")

-- OFF: the vertices and the 0-based facets, read back here and measured independently.
local off = slurp(dir .. "/tets.off")
local nums = {}
for w in off:gmatch("%S+") do nums[#nums + 1] = w end
T.assert_true(nums[1] == "OFF" and nums[2] == "5" and nums[3] == "7" and nums[4] == "0", "OFF header")
local X, k = {}, 5
for v = 1, 5 do
  X[v] = {tonumber(nums[k]), tonumber(nums[k + 1]), tonumber(nums[k + 2])}
  k = k + 3
  local x = c:vertex(v)
  T.assert_true(X[v][1] == x[1] and X[v][2] == x[2] and X[v][3] == x[3],
                "OFF vertex " .. v .. " round-trips exactly")
end
local F = {}
for f = 1, 7 do
  T.assert_equal(nums[k], "3", "OFF facet " .. f .. " is a triangle")
  F[f] = {tonumber(nums[k + 1]) + 1, tonumber(nums[k + 2]) + 1, tonumber(nums[k + 3]) + 1}
  k = k + 4
end
-- facets are written surface by surface, in order: compare with the input triangles
local flat = {}
for _, s in ipairs(S) do for _, t in ipairs(s) do flat[#flat + 1] = t end end
local same = true
for f = 1, 7 do
  for j = 1, 3 do same = same and F[f][j] == flat[f][j] end
end
T.assert_true(same, "OFF facets are the input facets, 0-based")
local function cone(t) -- signed volume of the cone over the origin
  local a, b, q = X[t[1]], X[t[2]], X[t[3]]
  return (a[1] * (b[2] * q[3] - b[3] * q[2]) - a[2] * (b[1] * q[3] - b[3] * q[1]) +
          a[3] * (b[1] * q[2] - b[2] * q[1])) / 6
end
for i, body in ipairs(c:bodies()) do
  local sum = 0
  for _, signed in ipairs(body) do
    for _, t in ipairs(S[math.abs(signed)]) do sum = sum + (signed > 0 and 1 or -1) * cone(t) end
  end
  T.assert_near(sum, vol[i], 1e-15, "volume " .. i .. " from the OFF file")
end

-- PLY: per-face surface ids; VTU: counts, time and the fields.
local ply = slurp(dir .. "/tets.ply")
T.assert_true(ply:find("element vertex 5\n", 1, true) and ply:find("element face 7\n", 1, true) and
              ply:find("comment froth cluster, time 0.001\n", 1, true), "PLY header")
local ids = {}
for id in ply:gmatch("\n3 %d+ %d+ %d+ (%d+)") do ids[#ids + 1] = id end
T.assert_equal(table.concat(ids, " "), "1 1 1 2 2 2 3", "PLY surface ids")
local vtu = slurp(dir .. "/tets.vtu")
T.assert_true(vtu:find('NumberOfPoints="5" NumberOfCells="7"', 1, true) ~= nil, "VTU counts")
T.assert_true(vtu:find('Name="TimeValue" NumberOfTuples="1" format="ascii">0.001<', 1, true) ~= nil,
              "VTU time")
T.assert_true(vtu:find('Name="mean_curvature"', 1, true) and vtu:find('Name="surface"', 1, true),
              "VTU point field mean_curvature and cell field surface")
local msh = slurp(dir .. "/tets.MSH")
T.assert_equal(msh:sub(1, 30), "$MeshFormat\n4.1 0 8\n$EndMeshFo", "MSH 4.1 ASCII")

-- Write errors.
T.check_error("write: unknown file type '.xyz' (use .vtu, .off, .ply or .msh)", c.write, c, dir .. "/a.xyz")
T.check_error("has no file extension (use .vtu, .off, .ply or .msh)", c.write, c, dir .. "/noext")
T.check_error("write: cannot create directory", c.write, c, dir .. "/tets.off/sub/a.vtu")
T.check_error("string expected, got no value", c.write, c)

-- froth.has
T.check_error("has: unknown feature 'no such feature' (known: \"gmsh\", \"cgal\")", froth.has,
              "no such feature")
T.assert_equal(type(froth.has("cgal")), "boolean", "froth.has('cgal') is a boolean")
T.check_error("string expected", froth.has)
T.assert_equal(froth.has("gmsh"), type(froth.double_bubble) == "function",
               "froth.double_bubble exists iff gmsh")
T.assert_equal(type(froth.read), "function", "froth.read needs no gmsh")
do
  -- froth.read of .msh files we wrote: the same cluster, with time 0 and sigma 1.
  local r = froth.read(dir .. "/tets.MSH")
  local ri, ci = r:info(), c:info()
  for _, key in ipairs{"vertices", "facets", "surfaces", "triple_lines", "quadruple_points", "bodies"} do
    T.assert_equal(ri[key], ci[key], "read: " .. key)
  end
  T.assert_true(r:volumes()[1] == vol[1] and r:volumes()[2] == vol[2], "read: same volumes")
  T.assert_equal(r:time(), 0, "read: time starts at 0")
  local b = froth.has("gmsh") and froth.double_bubble{h = 0.3} or froth.box_cells{x = {0, 1, 2}, y = {0, 1}, z = {0, 1}, cell = function(i) return i end}
  b:set_sigma(3, 1.5)
  b:write(path("db.msh"))
  local rb = froth.read(dir .. "/db.msh")
  local bi, rbi = b:info(), rb:info()
  for _, key in ipairs{"vertices", "facets", "surfaces", "triple_lines", "quadruple_points", "bodies"} do
    T.assert_equal(rbi[key], bi[key], "double bubble read: " .. key)
  end
  for i = 1, 2 do
    T.assert_near(rb:volumes()[i], b:volumes()[i], 1e-12 * b:volumes()[i], "double bubble volume " .. i)
  end
  for i = 1, 3 do T.assert_near(rb:area(i), b:area(i), 1e-12 * b:area(i), "double bubble area " .. i) end
  T.assert_equal(rb:sigma(3), 1, "read: sigma is 1 (the file carries none)")
  local moved = 0
  for v = 1, bi.vertices do
    local x, y = b:vertex(v), rb:vertex(v)
    moved = math.max(moved, math.abs(x[1] - y[1]), math.abs(x[2] - y[2]), math.abs(x[3] - y[3]))
  end
  T.assert_equal(moved, 0, "read: same vertex numbering and positions")

  -- Read errors: clear messages, no crash.
  T.check_error("read: cannot open '" .. dir .. "/missing.msh': No such file or directory",
                froth.read, dir .. "/missing.msh")
  T.check_error("read: cannot open '" .. dir .. "': Is a directory", froth.read, dir)
  local f = assert(io.open(path("garbage.msh"), "w"))
  f:write("this is not a mesh\n")
  f:close()
  T.check_error("read: '" .. dir .. "/garbage.msh' is not a readable mesh", froth.read, dir .. "/garbage.msh")
  f = assert(io.open(path("empty.msh"), "w"))
  f:close()
  T.check_error("read: '" .. dir .. "/empty.msh' has no triangles", froth.read, dir .. "/empty.msh")
  T.check_error("is not a readable mesh", froth.read, dir .. "/tets.vtu")
  T.check_error("string expected, got no value", froth.read)
  -- and the cluster still reads after all that (gmsh state is clean)
  T.assert_equal(froth.read(dir .. "/tets.MSH"):info().facets, 7, "read works after failed reads")
end

for i = #written, 1, -1 do os.remove(written[i]) end
os.remove(dir)
T.summary()
