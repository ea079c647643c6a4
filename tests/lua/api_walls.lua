-- External boundaries from Lua: froth.plane, froth.slab, froth.sphere_wall, froth.cylinder_wall
-- and froth.wall with their methods and every constructor error; the walls option of
-- froth.cluster, froth.read and froth.fragment; c:walls(), info().walls, the report fields
-- contact_angles and wall_drift; step/evolve{project}; a failing function wall during a step
-- or an evolution leaves the cluster as it was. Meshes are built here (no gmsh needed, except
-- for froth.read and froth.fragment).
local T = require("froth.test")
local check_error, near, yes, eq = T.check_error, T.assert_near, T.assert_true, T.assert_equal

local function vec_near(a, b, tol, what)
  local d = 0
  for k = 1, 3 do d = math.max(d, math.abs(a[k] - b[k])) end
  return yes(#a == 3 and d <= tol, what, ("{%s, %s, %s} vs {%s, %s, %s}"):format(
               a[1], a[2], a[3], b[1], b[2], b[3]))
end

-- Meshes ------------------------------------------------------------------------------------

-- The box [lo, hi] as n x n grids of triangle pairs per face, outward normals, faces named in
-- `faces` ("x-", "x+", "y-", "y+", "z-", "z+") in one surface; returns vertices, facets.
local function box(lo, hi, n, faces)
  local V, F, index = {}, {}, {}
  local function vertex(x)
    local key = ("%.9f %.9f %.9f"):format(x[1], x[2], x[3])
    if not index[key] then V[#V + 1] = x; index[key] = #V end
    return index[key]
  end
  local d = {hi[1] - lo[1], hi[2] - lo[2], hi[3] - lo[3]}
  local dx, dy, dz = {d[1], 0, 0}, {0, d[2], 0}, {0, 0, d[3]}
  local function add(p, q) return {p[1] + q[1], p[2] + q[2], p[3] + q[3]} end
  local function grid(p0, u, v)
    local function at(i, j)
      return vertex({p0[1] + i / n * u[1] + j / n * v[1], p0[2] + i / n * u[2] + j / n * v[2],
                     p0[3] + i / n * u[3] + j / n * v[3]})
    end
    for i = 0, n - 1 do
      for j = 0, n - 1 do
        local a, b, c, e = at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)
        F[#F + 1] = {a, b, c}
        F[#F + 1] = {a, c, e}
      end
    end
  end
  local want = {}
  for _, f in ipairs(faces) do want[f] = true end
  if want["x-"] then grid(lo, dz, dy) end
  if want["x+"] then grid(add(lo, dx), dy, dz) end
  if want["y-"] then grid(lo, dx, dz) end
  if want["y+"] then grid(add(lo, dy), dz, dx) end
  if want["z-"] then grid(lo, dy, dx) end
  if want["z+"] then grid(add(lo, dz), dx, dy) end
  return V, F
end

local OPEN = {"x-", "x+", "y-", "y+", "z+"}             -- no bottom
local CLOSED = {"x-", "x+", "y-", "y+", "z-", "z+"}

-- The open unit box on the floor z = 0 (n = 2), one body.
local function floor_box(walls, n)
  local V, F = box({0, 0, 0}, {1, 1, 1}, n or 2, OPEN)
  return froth.cluster{vertices = V, surfaces = {F}, bodies = {{1}}, walls = walls}
end

-- A hemisphere of radius r0 whose rim lies on the sphere wall |x - (0, 0, -Rw)| = Rw.
local function drop_on_sphere(wall, Rw, r0, J, K)
  local z0 = -Rw + math.sqrt(Rw * Rw - r0 * r0)
  local V, F = {}, {}
  for j = 0, J - 1 do
    local phi = math.pi / 2 * j / J
    for k = 0, K - 1 do
      local th = 2 * math.pi * (k + 0.5 * (j % 2)) / K
      V[#V + 1] = {r0 * math.cos(phi) * math.cos(th), r0 * math.cos(phi) * math.sin(th),
                   z0 + r0 * math.sin(phi)}
    end
  end
  V[#V + 1] = {0, 0, z0 + r0}
  local function id(j, k) return j * K + k % K + 1 end
  for j = 0, J - 2 do
    for k = 0, K - 1 do
      if j % 2 == 0 then
        F[#F + 1] = {id(j, k), id(j, k + 1), id(j + 1, k)}
        F[#F + 1] = {id(j, k + 1), id(j + 1, k + 1), id(j + 1, k)}
      else
        F[#F + 1] = {id(j, k), id(j + 1, k + 1), id(j + 1, k)}
        F[#F + 1] = {id(j, k), id(j, k + 1), id(j + 1, k + 1)}
      end
    end
  end
  for k = 0, K - 1 do F[#F + 1] = {id(J - 1, k), id(J - 1, k + 1), #V} end
  return froth.cluster{vertices = V, surfaces = {F}, bodies = {{1}}, walls = {wall}}
end

local positions, same_positions = T.positions, T.same_positions

-- The walls and their methods ----------------------------------------------------------------

-- plane: the normal is normalised, the offset is the distance from the origin along it.
local p = froth.plane{normal = {0, 0, 2}, offset = 3}
eq(tostring(p), "froth.Wall (plane (0, 0, 1) . x = 3)", "plane tostring")
near(p:F{1, 2, 5}, 2, 1e-15, "plane F from a point table")
near(p:F(1, 2, 5), 2, 1e-15, "plane F from three numbers")
vec_near(p:gradient{1, 2, 5}, {0, 0, 1}, 0, "plane gradient")
near(p:distance{1, 2, 1}, 2, 1e-15, "plane distance below")
vec_near(p:project{1, 2, 5}, {1, 2, 3}, 1e-15, "plane projection")
vec_near(froth.plane():gradient(0, 0, 0), {0, 0, 1}, 0, "froth.plane() is z = 0")
near(froth.plane{}:F(4, 5, -0.5), -0.5, 0, "froth.plane{} is z = 0")
vec_near(froth.plane{normal = {1, 1, 0}, offset = math.sqrt(2)}:project{3, 3, 4}, {1, 1, 4},
         1e-14, "tilted plane projection")

-- slab: -1 <= z <= 2, F >= 0 inside.
local s = froth.slab{normal = {0, 0, 1}, from = -1, to = 2}
near(s:F(0, 0, 0), 1, 1e-15, "slab F inside, nearer the lower plane")
near(s:F(0, 0, 1.5), 0.5, 1e-15, "slab F inside, nearer the upper plane")
near(s:F(0, 0, 3), -1, 1e-15, "slab F outside")
vec_near(s:gradient(0, 0, 1.5), {0, 0, -1}, 0, "slab gradient points into the slab")
vec_near(s:project(1, 2, 0.2), {1, 2, -1}, 1e-15, "slab projects onto the nearer plane")
vec_near(s:project(1, 2, 3), {1, 2, 2}, 1e-15, "slab projects from outside")
near(froth.slab{to = 1}:F(0, 0, 0.25), 0.25, 1e-15, "slab defaults: normal z, from 0")
yes(tostring(s):find("slab", 1, true) ~= nil, "slab tostring", tostring(s))

-- sphere_wall and cylinder_wall: exact distances and projections.
local sw = froth.sphere_wall{center = {1, 0, 0}, radius = 2}
near(sw:F(1, 0, 3), 1, 1e-15, "sphere F")
near(sw:distance(1, 0.5, 0), 1.5, 1e-15, "sphere distance inside")
vec_near(sw:gradient(1, 0, 3), {0, 0, 1}, 1e-15, "sphere gradient")
vec_near(sw:project(1, 0, 3), {1, 0, 2}, 1e-15, "sphere projection")
check_error("cannot project (0, 0, 0) onto the wall", function()
  froth.sphere_wall{radius = 1}:project(0, 0, 0) -- grad F = 0 at the center
end)
local cw = froth.cylinder_wall{point = {0, 0, 1}, axis = {0, 0, 5}, radius = 1}
near(cw:F(3, 4, 7), 4, 1e-15, "cylinder F")
vec_near(cw:gradient(3, 4, 7), {0.6, 0.8, 0}, 1e-15, "cylinder gradient")
vec_near(cw:project{3, 4, 7}, {0.6, 0.8, 7}, 1e-14, "cylinder projection")
yes(tostring(cw):find("cylinder of radius 1", 1, true) ~= nil, "cylinder tostring", tostring(cw))

-- wall: F from Lua, gradient by central differences or from Lua.
local calls = 0
local ball = froth.wall{name = "ball", F = function(x, y, z)
  calls = calls + 1
  return x * x + y * y + z * z - 4
end}
eq(tostring(ball), "froth.Wall (wall 'ball')", "function wall tostring")
near(ball:F(1, 1, 1), -1, 0, "function wall F")
local g = ball:gradient(0.3, -1.7, 2.2)
vec_near(g, {0.6, -3.4, 4.4}, 1e-8, "finite-difference gradient of F")
yes(calls >= 7, "the differences call F", calls)
near(ball:distance(1, 1, 1), 1 / math.sqrt(12), 1e-9, "first-order distance |F| / |grad F|")
local q = ball:project(1, 1, 1)
near(math.sqrt(q[1] ^ 2 + q[2] ^ 2 + q[3] ^ 2), 2, 1e-12, "projection onto the ball's sphere")
local analytic = froth.wall{F = function(x, y, z) return z - 0.1 * x * x end,
                            gradient = function(x, y, z) return -0.2 * x, 0, 1 end}
vec_near(analytic:gradient(1, 0, 0), {-0.2, 0, 1}, 0, "gradient from Lua")
eq(tostring(analytic), "froth.Wall (wall 'user wall')", "default name")
near(analytic:F(analytic:project(1, 0, 1)), 0, 1e-14, "projection onto a parabolic wall")

-- Constructor errors --------------------------------------------------------------------------

check_error("plane: unknown option 'ofset'", froth.plane, {ofset = 1})
check_error("plane: normal must be a finite non-zero vector, got (0, 0, 0)", froth.plane,
            {normal = {0, 0, 0}})
check_error("plane: option 'normal' must be {x, y, z}", froth.plane, {normal = {0, 1}})
check_error("plane: option 'normal' must be {x, y, z}", froth.plane, {normal = "up"})
check_error("plane: option 'normal' must be {x, y, z}", froth.plane, {normal = {0, "a", 1}})
check_error("plane: option 'offset' must be a number", froth.plane, {offset = "a"})
check_error("plane: offset must be finite", froth.plane, {offset = math.huge})
check_error("plane: normal must be a finite non-zero vector", froth.plane, {normal = {0 / 0, 0, 1}})
check_error("plane: expected an option table", froth.plane, 5)
check_error("slab: option 'to' is required", froth.slab, {})
check_error("slab: the lower offset 1 must be below the upper 1", froth.slab, {from = 1, to = 1})
check_error("slab: the lower offset 2 must be below the upper 1", froth.slab, {from = 2, to = 1})
check_error("slab: normal must be a finite non-zero vector", froth.slab,
            {normal = {0, 0, 0}, to = 1})
check_error("slab: unknown option 'lo'", froth.slab, {lo = 0, to = 1})
check_error("slab: expected an option table", froth.slab)
check_error("sphere_wall: option 'radius' is required", froth.sphere_wall, {})
check_error("sphere_wall: radius must be positive, got 0", froth.sphere_wall, {radius = 0})
check_error("sphere_wall: radius must be positive, got -1", froth.sphere_wall, {radius = -1})
check_error("sphere_wall: radius must be positive, got nan", froth.sphere_wall, {radius = 0 / 0})
check_error("sphere_wall: center must be finite", froth.sphere_wall,
            {radius = 1, center = {math.huge, 0, 0}})
check_error("sphere_wall: option 'center' must be {x, y, z}", froth.sphere_wall,
            {radius = 1, center = {1, 2}})
check_error("sphere_wall: unknown option 'r'", froth.sphere_wall, {radius = 1, r = 1})
check_error("cylinder_wall: option 'radius' is required", froth.cylinder_wall, {})
check_error("cylinder_wall: radius must be positive, got 0", froth.cylinder_wall, {radius = 0})
check_error("cylinder_wall: radius must be positive, got -2", froth.cylinder_wall, {radius = -2})
check_error("cylinder_wall: axis must be a finite non-zero vector", froth.cylinder_wall,
            {radius = 1, axis = {0, 0, 0}})
check_error("cylinder_wall: point must be finite", froth.cylinder_wall,
            {radius = 1, point = {0, 0 / 0, 0}})
check_error("cylinder_wall: unknown option 'center'", froth.cylinder_wall,
            {radius = 1, center = {0, 0, 0}})
check_error("wall: option 'F' must be a function (x, y, z) -> F", froth.wall, {})
check_error("wall: option 'F' must be a function (x, y, z) -> F", froth.wall, {F = 3})
check_error("wall: option 'gradient' must be a function (x, y, z) -> gx, gy, gz", froth.wall,
            {F = function() return 0 end, gradient = {0, 0, 1}})
check_error("wall: the finite-difference step must be positive, got 0", froth.wall,
            {F = function() return 0 end, fd_step = 0})
check_error("wall: the finite-difference step must be positive, got -1", froth.wall,
            {F = function() return 0 end, fd_step = -1})
check_error("wall: option 'name' must be a string", froth.wall,
            {F = function() return 0 end, name = {}})
check_error("wall: unknown option 'f'", froth.wall, {F = function() return 0 end, f = 1})

-- A function wall's failures name the wall and the point.
local boom = froth.wall{name = "boom", F = function(x, y, z) error("no F here") end}
check_error("wall 'boom': F(1, 2, 3) failed: ", boom.F, boom, 1, 2, 3)
check_error("no F here", boom.F, boom, 1, 2, 3)
check_error("wall 'boom': F(", boom.gradient, boom, 1, 2, 3) -- differences call F
local nothing = froth.wall{name = "nothing", F = function() end}
check_error("wall 'nothing': F(1, 2, 3) failed: returned nil where a number was expected",
            nothing.F, nothing, 1, 2, 3)
local text = froth.wall{name = "text", F = function() return "1" end}
check_error("wall 'text': F(0.5, 0, 0) failed: returned string where a number was expected",
            text.F, text, 0.5, 0, 0)
local nan = froth.wall{name = "nan", F = function() return 0 / 0 end}
check_error("wall 'nan': F is nan at (1, 2, 3)", nan.F, nan, 1, 2, 3)
check_error("wall 'nan'", nan.distance, nan, 1, 2, 3)
local inf = froth.wall{name = "inf", F = function() return math.huge end}
check_error("wall 'inf': F is inf at (0, 0, 0)", inf.F, inf, 0, 0, 0)
local short = froth.wall{name = "short", F = function(x, y, z) return z end,
                         gradient = function() return 0, 1 end}
check_error("wall 'short': gradient(1, 2, 3) failed: returned nil where a number was expected",
            short.gradient, short, 1, 2, 3)
local gerr = froth.wall{name = "gerr", F = function(x, y, z) return z end,
                        gradient = function() error("bad gradient") end}
check_error("wall 'gerr': gradient(1, 2, 3) failed: ", gerr.gradient, gerr, 1, 2, 3)
check_error("bad gradient", gerr.gradient, gerr, 1, 2, 3)
check_error("number expected", p.F, p, 1, "a", 3)
check_error("expected a point {x, y, z}", p.F, p, {1, 2})
check_error("froth.Wall expected", p.F, 5, {1, 2, 3})

-- The walls option ---------------------------------------------------------------------------

local V, F = box({0, 0, 0}, {1, 1, 1}, 1, OPEN)
check_error("is a free boundary edge (in one facet only) and no wall is attached; close the " ..
            "surface, give walls (froth.plane, ...) or fix both its vertices (a wire)", froth.cluster,
            {vertices = V, surfaces = {F}})
check_error("cluster: walls must be a wall or an array of walls (froth.plane{...}, ...), got number",
            froth.cluster, {vertices = V, surfaces = {F}, walls = 3})
check_error("cluster: walls must be a wall or an array of walls (froth.plane{...}, ...), got string",
            froth.cluster, {vertices = V, surfaces = {F}, walls = "floor"})
check_error("cluster: walls[2] must be a wall (froth.plane{...}, ...), got number",
            froth.cluster, {vertices = V, surfaces = {F}, walls = {froth.plane(), 5}})
check_error("cluster: walls[1] must be a wall (froth.plane{...}, ...), got table",
            froth.cluster, {vertices = V, surfaces = {F}, walls = {{}}})
check_error("no wall is attached", froth.cluster, {vertices = V, surfaces = {F}, walls = {}})
-- A free edge off every wall: the vertex and the distance to the nearest wall are named.
check_error("but on no wall: the nearest, wall 1 (plane (0, 0, 1) . x = -0.5), is at distance 0.5",
            froth.cluster, {vertices = V, surfaces = {F}, walls = froth.plane{offset = -0.5}})
check_error("could not move", froth.cluster, {vertices = V, surfaces = {F}, walls = {
  froth.plane(), froth.plane{normal = {1, 0, 0}}, froth.plane{normal = {0, 1, 0}}}})
check_error("has its ends on different walls", froth.cluster, {vertices = V, surfaces = {F},
  walls = {froth.plane{normal = {1, 0, 0}}, froth.plane{normal = {1, 0, 0}, offset = 1}}})
-- A function wall that fails while the cluster is made: a clear error, no cluster.
check_error("wall 'boom': F(", froth.cluster, {vertices = V, surfaces = {F}, walls = boom})
check_error("wall 'nan': F is nan", froth.cluster, {vertices = V, surfaces = {F}, walls = nan})

if froth.has("gmsh") then
  check_error("read: walls must be a wall or an array of walls", froth.read, "/nonexistent.msh",
              {walls = 3})
  check_error("read: walls[1] must be a wall", froth.read, "/nonexistent.msh", {walls = {true}})
  check_error("read: unknown option 'wall'", froth.read, "/nonexistent.msh",
              {wall = froth.plane()})
  local cube = {"box", min = {0, 0, 0}, size = {1, 1, 1}}
  check_error("fragment: walls must be a wall or an array of walls", froth.fragment,
              {solids = {cube}, h = 0.5, walls = "floor"})
  check_error("fragment: walls[2] must be a wall", froth.fragment,
              {solids = {cube}, h = 0.5, walls = {froth.plane(), 1}})
  -- The unit cube on the floor: its bottom becomes the lid.
  local fc = froth.fragment{solids = {cube}, h = 0.5, walls = froth.plane()}
  eq(fc:info().walls, 1, "fragment with walls: one wall")
  near(fc:volumes()[1], 1, 1e-12, "fragment cube on the floor: volume 1 with its lid")
  near(fc:area(), 5, 1e-12, "fragment cube on the floor: the bottom is gone")
  yes(fc:report().contact_angles ~= nil, "fragment cube on the floor: contact angles")
  -- Sheared by x += z / 2, its side films meet the floor at 90 -+ atan(1/2) degrees; for an
  -- isotropic film the residual of (1.26b), |n . nu|, is the sine of the deviation from 90.
  local sheared = froth.fragment{solids = {cube}, h = 0.25, walls = froth.plane(),
                                 transform = function(x, y, z) return x + z / 2, y, z end}
  local sca = sheared:report().contact_angles
  near(sca.min, 90 - math.deg(math.atan(0.5)), 1e-9, "sheared cube: smallest contact angle")
  near(sca.max, 90 + math.deg(math.atan(0.5)), 1e-9, "sheared cube: largest contact angle")
  near(sca.force_imbalance, math.sin(math.atan(0.5)), 1e-12, "sheared cube: |n . nu| = 1/sqrt(5)")
  check_error("fragment: sigma names surface 2, but there are 1 films once the lids on the walls "
              .. "are dropped", froth.fragment,
              {solids = {cube}, h = 0.5, walls = froth.plane(), sigma = {[2] = 3}})
  eq(froth.fragment{solids = {cube}, h = 0.5, walls = froth.plane(), sigma = {[1] = 3}}:sigma(1),
     3, "fragment with walls: sigma of the remaining film")
  -- write and read back an open film: it needs its walls again.
  local tmp = os.tmpname()
  local path = tmp .. ".msh"
  floor_box(froth.plane()):write(path)
  check_error("no wall is attached", froth.read, path)
  local r = froth.read(path, {walls = froth.plane()})
  eq(r:info().walls, 1, "read with walls")
  near(r:volumes()[1], 1, 1e-12, "read back: the lid counts")
  os.remove(path)
  os.remove(tmp)
end

-- Clusters with walls ------------------------------------------------------------------------

local floor = froth.plane()
local c = floor_box({floor})
eq(c:info().walls, 1, "info().walls")
local ws = c:walls()
eq(#ws, 1, "c:walls()")
eq(tostring(ws[1]), tostring(floor), "c:walls() returns the wall")
near(ws[1]:F(0, 0, 2), 2, 0, "the returned wall works")
near(c:volumes()[1], 1, 1e-14, "open box on the floor: volume 1")
eq(c:clone():info().walls, 1, "a clone keeps its walls")
local rep = c:report()
yes(rep.contact_angles ~= nil, "report.contact_angles with walls")
eq(rep.contact_angles.count, 8, "one angle per rim vertex")
near(rep.contact_angles.mean, 90, 25, "contact angles of a box standing on the floor")
yes(rep.contact_angles.min <= rep.contact_angles.mean and
    rep.contact_angles.mean <= rep.contact_angles.max, "contact angle min <= mean <= max")
near(rep.contact_angles.max_deviation,
     math.max(90 - rep.contact_angles.min, rep.contact_angles.max - 90), 1e-12, "max_deviation")
eq(rep.wall_drift, 0, "no drift on a plane")
-- Without walls, or with walls but no free edges: no such fields.
local closedV, closedF = box({0, 0, 0}, {1, 1, 1}, 1, CLOSED)
local closed = froth.cluster{vertices = closedV, surfaces = {closedF}, bodies = {{1}}}
eq(closed:info().walls, 0, "no walls")
eq(#closed:walls(), 0, "c:walls() is empty")
eq(closed:report().contact_angles, nil, "no contact_angles without walls")
eq(closed:report().wall_drift, nil, "no wall_drift without walls")
local closed_walls = froth.cluster{vertices = closedV, surfaces = {closedF}, bodies = {{1}},
                                   walls = {froth.plane{offset = -3}, froth.sphere_wall{radius = 9}}}
eq(closed_walls:info().walls, 2, "a closed cluster may be given walls")
eq(#closed_walls:walls(), 2, "c:walls() of a closed cluster")
eq(closed_walls:report().contact_angles, nil, "no contact angles: nothing is attached")
eq(closed_walls:step{flow = "mcf", tau = 1e-3}.contact_angles, nil, "nor in a step report")

-- Steps: the rim stays on the floor; reports carry the wall fields.
local st = c:clone()
local r1 = st:step{flow = "mcf", tau = 1e-2}
yes(r1.contact_angles ~= nil and r1.wall_drift ~= nil, "step report has the wall fields")
yes(r1.energy < r1.energy_before, "energy decreases")
yes(r1.wall_drift < 1e-14, "the rim stays on the floor", r1.wall_drift)
local r2 = st:step{flow = "sd", tau = 1e-3}
yes(r2.energy < r2.energy_before, "sd energy decreases")
yes(r2.wall_drift < 1e-14, "sd: the rim stays on the floor", r2.wall_drift)
local ev = st:evolve{flow = "mcf", tau = 1e-3, steps = 3, progress = false}
yes(ev.contact_angles ~= nil and ev.wall_drift ~= nil, "evolve result has the wall fields")
check_error("step: option 'project' must be true or false", st.step, st,
            {flow = "mcf", tau = 1e-3, project = 1})
check_error("evolve: option 'project' must be true or false", st.evolve, st,
            {flow = "mcf", tau = 1e-3, steps = 1, project = "yes"})

-- Curved walls drift at second order; project = true puts the rim back.
local sphere = froth.sphere_wall{center = {0, 0, -2}, radius = 2}
local drop = drop_on_sphere(sphere, 2, 0.8, 5, 16)
eq(drop:report().wall_drift < 1e-14, true, "the drop's rim starts on the sphere")
local d1 = drop:clone()
local free = d1:step{flow = "mcf", tau = 1e-3}
yes(free.wall_drift > 1e-9 and free.wall_drift < 1e-4, "linearised constraint: small drift",
    free.wall_drift)
local d2 = drop:clone()
local projected = d2:step{flow = "mcf", tau = 1e-3, project = true}
yes(projected.wall_drift < 1e-13, "project = true: on the sphere", projected.wall_drift)
local worst = 0
for v = 1, d2:info().vertices do
  local x = d2:vertex(v)
  local dist = sphere:distance(x)
  if dist < 1e-6 then worst = math.max(worst, dist) end
end
yes(worst < 1e-13, "projected rim vertices on the sphere", worst)
local de = drop:clone():evolve{flow = "mcf", tau = 1e-3, steps = 3, project = true, progress = false}
yes(de.wall_drift < 1e-13, "evolve{project = true}: on the sphere", de.wall_drift)
yes(de.contact_angles.count == 16, "a contact angle per rim vertex", de.contact_angles.count)

-- A failing function wall ---------------------------------------------------------------------

-- F fails: without a gradient function the tangent bases evaluate F before the solve; the
-- step fails and the cluster is as it was.
local fail = false
local fd_floor = froth.wall{name = "fd floor", F = function(x, y, z)
  if fail then error("F broke") end
  return z
end}
local fc = floor_box(fd_floor)
fc:step{flow = "mcf", tau = 1e-3}
local X0, t0 = positions(fc), fc:time()
fail = true
check_error("wall 'fd floor': F(", fc.step, fc, {flow = "mcf", tau = 1e-3})
check_error("F broke", fc.step, fc, {flow = "mcf", tau = 1e-3})
eq(fc:time(), t0, "failed step (F in the tangent bases): time unchanged")
yes(same_positions(fc, X0), "failed step (F in the tangent bases): positions unchanged")
check_error("wall 'fd floor': F(", fc.evolve, fc, {flow = "sd", tau = 1e-3, steps = 2,
            progress = false})
eq(fc:time(), t0, "failed evolve (F in the tangent bases): time unchanged")
yes(same_positions(fc, X0), "failed evolve (F in the tangent bases): positions unchanged")
-- The report and the volumes measure the lid through F: their errors must name the wall too.
-- KNOWN ENGINE BUG (src/bindings/lua_cluster.cpp, l_report and l_volumes): they are not wrapped
-- in guarded(), so the wall's InvalidInput escapes as a foreign C++ exception; Lua's catch(...)
-- turns it into an error whose value is the cluster userdata ("froth.Cluster (25 vertices...").
for _, method in ipairs({"report", "volumes"}) do
  local ok, err = pcall(fc[method], fc)
  yes(not ok, "c:" .. method .. "() fails while F does")
  yes(type(err) == "string" and err:find("wall 'fd floor': F(", 1, true) ~= nil,
            "c:" .. method .. "() with a failing F raises the wall's message", tostring(err))
end
fail = false
near(fc:step{flow = "mcf", tau = 1e-3}.t, t0 + 1e-3, 1e-15, "the cluster steps again once F works")

-- A step calls F first for the tangent bases (central differences), then for its report (lid
-- volumes, drift, contact angles). Count both parts, then let F fail at a chosen call in the
-- second step of an evolution.
local n_calls, limit = 0, math.huge
local counted = froth.wall{name = "counted", F = function(x, y, z)
  n_calls = n_calls + 1
  if n_calls > limit then error("F gave up") end
  return z
end}
local cc = floor_box(counted)
local probe = cc:clone()
n_calls = 0
probe:step{flow = "mcf", tau = 1e-3}
local per_step = n_calls
n_calls = 0
probe:report()
local per_report = n_calls
local per_basis = per_step - per_report
yes(per_basis > 0 and per_report > 0, "a step calls F before and after its solve",
    per_basis .. " + " .. per_report)
local function evolve_failing_at(call)
  local c = cc:clone()
  local first
  n_calls, limit = 0, call
  local ok, msg = pcall(c.evolve, c, {flow = "mcf", tau = 1e-3, steps = 3, progress = false,
                                      watch = false, on_step = function(r)
                                        if not first then first = {t = r.t, X = positions(c)} end
                                      end})
  limit = math.huge
  yes(not ok and tostring(msg):find("wall 'counted'", 1, true) ~= nil and
      tostring(msg):find("F gave up", 1, true) ~= nil, "the evolution ends with the wall's error",
      tostring(msg))
  yes(first ~= nil, "one step succeeded before F failed")
  return c, first
end
-- F fails in the second step's tangent bases: the cluster keeps the first step's state.
local c1, first1 = evolve_failing_at(per_step + 1)
if first1 then
  eq(c1:time(), first1.t, "failed evolve: the time of the last good step")
  yes(same_positions(c1, first1.X), "failed evolve: the positions of the last good step")
end
-- KNOWN ENGINE BUG (src/flows/stepper.cpp, TimeStepper::step): make_report runs after
-- c.set_positions/c.set_time, so where F first fails in the step's report the cluster has
-- already taken the failing step. Expected: the state after the last successful step.
local c2, first2 = evolve_failing_at(per_step + per_basis + 1)
if first2 then
  yes(c2:time() == first2.t and same_positions(c2, first2.X),
            "failed evolve (F fails in the second step's report) keeps the last good state",
            ("t = %.17g, last good t = %.17g"):format(c2:time(), first2.t))
end

-- F with an analytic gradient is first called after the solve (report: lids, drift): a
-- failure there must still leave the cluster as it was.
fail = false
local ga_floor = froth.wall{name = "ga floor", F = function(x, y, z)
  if fail then error("F broke") end
  return z
end, gradient = function() return 0, 0, 1 end}
local gc = floor_box(ga_floor)
local GX, gt = positions(gc), gc:time()
fail = true
check_error("wall 'ga floor': F(", gc.step, gc, {flow = "mcf", tau = 1e-3})
yes(gc:time() == gt and same_positions(gc, GX),
          "failed step (F fails in the step's report) leaves the cluster unchanged",
          ("time %.17g, expected %.17g"):format(gc:time(), gt))
fail = false
gc = floor_box(ga_floor)
fail = true
check_error("wall 'ga floor': F(", gc.evolve, gc, {flow = "mcf", tau = 1e-3, steps = 2,
            progress = false})
yes(gc:time() == gt and same_positions(gc, GX),
          "failed evolve (F fails in the step's report) leaves the cluster unchanged",
          ("time %.17g, expected %.17g"):format(gc:time(), gt))
fail = false
-- With project = true the projection calls F before anything changes.
gc = floor_box(ga_floor)
fail = true
check_error("wall 'ga floor': F(", gc.step, gc, {flow = "mcf", tau = 1e-3, project = true})
eq(gc:time(), gt, "failed projected step: time unchanged")
yes(same_positions(gc, GX), "failed projected step: positions unchanged")
fail = false

-- F returning NaN during an evolution is a geometric failure: the evolution stops with an
-- event (no Lua error) and the cluster keeps the state before the failing step.
local nan_now = false
local nan_floor = froth.wall{name = "nan floor", F = function(x, y, z)
  if nan_now then return 0 / 0 end
  return z
end}
local nc = floor_box(nan_floor)
nc:step{flow = "mcf", tau = 1e-3}
local NX, nt = positions(nc), nc:time()
nan_now = true
local ok3, res = pcall(nc.evolve, nc, {flow = "mcf", tau = 1e-3, steps = 3, progress = false})
yes(not ok3 or (res.event ~= nil and res.steps == 0), "NaN F stops the evolution",
    ok3 and tostring(res.stop_reason) or tostring(res))
if ok3 and res.event then
  yes(res.event.message:find("wall 'nan floor': F is nan", 1, true) ~= nil,
      "the event names the wall", res.event.message)
end
eq(nc:time(), nt, "NaN F: time unchanged")
yes(same_positions(nc, NX), "NaN F: positions unchanged")
nan_now = false

T.summary()
