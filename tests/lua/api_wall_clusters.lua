-- The named clusters on walls of lua/froth/wall_clusters.lua (seed §5.1.4): froth.cube_on_plane,
-- froth.half_sphere_on_plane, froth.cylinder_in_slab, froth.cuboid_in_slab,
-- froth.drop_on_sphere_wall. Counts, walls, free edges on the walls, volumes against exact
-- values, default sizes and errors (coarse meshes: this file takes about a second).
local T = require("froth.test")
local names = {"cube_on_plane", "half_sphere_on_plane", "cylinder_in_slab", "cuboid_in_slab",
               "drop_on_sphere_wall"}
if not froth.has("gmsh") then
  for _, n in ipairs(names) do T.assert_true(froth[n] == nil, "no " .. n .. " without gmsh") end
  return T.summary()
end
local pi = math.pi
local rel, counts = T.rel, T.counts

-- Vertices on the cluster's single wall (to 1e-9) and the largest distance of any of them.
local function on_wall(c)
  local w = c:walls()[1]
  local n, worst = 0, 0
  for v = 1, c:info().vertices do
    local d = w:distance(c:vertex(v))
    if d < 1e-9 then n, worst = n + 1, math.max(worst, d) end
  end
  return n, worst
end

-- Every builder: 1 film, 1 body, 1 wall, its rim on the wall at 90 degrees or as built.
local function common(c, what)
  T.assert_equal(counts(c), "1/0/0/1", what .. ": one film, one body")
  T.assert_equal(c:info().walls, 1, what .. ": one wall")
  local r = c:report()
  T.assert_true(r.contact_angles ~= nil and r.contact_angles.count > 0,
                what .. ": contact angles are measured (free edges on the wall)")
  T.assert_true(r.wall_drift < 1e-12, what .. ": rim on the wall", r.wall_drift)
  T.assert_true(on_wall(c) >= r.contact_angles.count, what .. ": rim vertices on the wall")
end

-- cube_on_plane: the bottom face is the lid, volume exactly s^3.
local cube = froth.cube_on_plane{h = 0.25}
common(cube, "cube")
T.assert_near(cube:volumes()[1], 1, 1e-12, "cube volume 1 (the lid counts)")
T.assert_near(cube:area(), 5, 1e-12, "cube film area 5 (no bottom face)")
T.assert_equal(tostring(cube:walls()[1]), "froth.Wall (plane (0, 0, 1) . x = 0)", "the wall x3 = 0")
local cube2 = froth.cube_on_plane{size = 2, h = 0.5}
T.assert_near(cube2:volumes()[1], 8, 1e-11, "size = 2: volume 8")
-- default: about the seed's K = 5185 film vertices
local n = froth.cube_on_plane():info().vertices
T.assert_true(math.abs(n - 5185) < 0.1 * 5185, "cube: about 5185 vertices by default", n)
n = froth.cube_on_plane{vertices = 1000}:info().vertices
T.assert_true(math.abs(n - 1000) < 150, "cube: vertices = 1000", n)

-- half_sphere_on_plane: volume 2 pi R^3 / 3, angles 90 from the start.
local hs = froth.half_sphere_on_plane{R = 1.5, h = 0.2}
common(hs, "half sphere")
T.assert_true(rel(hs:volumes()[1], 2 * pi * 1.5 ^ 3 / 3) < 0.01, "half sphere volume",
              hs:volumes()[1])
local ca = hs:report().contact_angles
T.assert_true(math.abs(ca.min - 90) < 0.5 and math.abs(ca.max - 90) < 0.5,
              "half sphere: 90 degrees", ca.min .. " " .. ca.max)

-- cylinder_in_slab (5.3): volume pi int_0^rho r(x3)^2 = pi rho (1 + alpha^2 / 2) (the inscribed
-- polyhedron a little less); the ends r(0) = r(rho) = 1 + alpha on the slab's planes.
local cyl = froth.cylinder_in_slab{h = 0.2}
common(cyl, "cylinder")
T.assert_true(rel(cyl:volumes()[1], pi * 4 * 1.125) < 0.01, "rho = 4, alpha = 0.5: volume",
              cyl:volumes()[1])
local lo, hi, rmax = math.huge, -math.huge, 0
for v = 1, cyl:info().vertices do
  local x = cyl:vertex(v)
  lo, hi = math.min(lo, x[3]), math.max(hi, x[3])
  rmax = math.max(rmax, math.sqrt(x[1] ^ 2 + x[2] ^ 2))
end
T.assert_true(math.abs(lo) < 1e-12 and math.abs(hi - 4) < 1e-12, "ends on x3 = 0 and 4", lo .. " " .. hi)
T.assert_near(rmax, 1.5, 1e-6, "r(0) = 1 + alpha")
local pinch = froth.cylinder_in_slab{rho = 8, alpha = 0.25, h = 0.3}
T.assert_true(rel(pinch:volumes()[1], pi * 8 * (1 + 0.25 ^ 2 / 2)) < 0.02, "rho = 8, alpha = 0.25: volume",
              pinch:volumes()[1])
T.assert_equal(tostring(pinch:walls()[1]):match("^froth.Wall %(slab"), "froth.Wall (slab", "a slab wall")

-- cuboid_in_slab: flat faces, exact volume.
local cub = froth.cuboid_in_slab{size = {1, 2, 3}, h = 0.3}
common(cub, "cuboid")
T.assert_near(cub:volumes()[1], 6, 1e-11, "1 x 2 x 3 cuboid")
T.assert_near(cub:area(), 18, 1e-11, "its four sides")

-- drop_on_sphere_wall: the sheared half ball keeps the half ball's volume; froth's volume
-- closes the lid by the sphere patch under the drop, so it is the half ball's 2 pi r^3 / 3 up
-- to the mesh (0.70612 at h = 0.15: -1.7%; a flat fan lid would add a sliver of 0.034).
local drop = froth.drop_on_sphere_wall{h = 0.15}
common(drop, "drop")
local R, r = 2, 0.7
T.assert_true(rel(drop:volumes()[1], 2 * pi * r ^ 3 / 3) < 0.02, "drop volume",
              drop:volumes()[1])
ca = drop:report().contact_angles
local built = 90 - math.deg(math.asin(r / R))   -- the sheared rim meets the sphere at 69.5
T.assert_true(math.abs(ca.mean - built) < 1, "drop: built at 90 - asin(r / R) degrees", ca.mean)

-- Errors name the builder.
T.check_error("cube_on_plane: unknown option 'R'", froth.cube_on_plane, {R = 1})
T.check_error("cube_on_plane: size must be positive, got 0", froth.cube_on_plane, {size = 0})
T.check_error("cube_on_plane: option 'size' must be a number", froth.cube_on_plane, {size = "1"})
T.check_error("cube_on_plane: give h or vertices, not both", froth.cube_on_plane, {h = 0.1, vertices = 500})
T.check_error("cube_on_plane: h must be positive, got 0", froth.cube_on_plane, {h = 0})
T.check_error("cube_on_plane: vertices must be at least 100, got 10", froth.cube_on_plane, {vertices = 10})
T.check_error("cube_on_plane: option 'vertices' must be an integer", froth.cube_on_plane, {vertices = 1000.5})
T.check_error("cube_on_plane: expected an option table {...}, got number", froth.cube_on_plane, 1)
T.check_error("half_sphere_on_plane: R must be positive, got -1", froth.half_sphere_on_plane, {R = -1})
T.check_error("cylinder_in_slab: rho must be positive, got 0", froth.cylinder_in_slab, {rho = 0})
T.check_error("cylinder_in_slab: alpha must be in (-1, 1)", froth.cylinder_in_slab, {alpha = 1})
T.check_error("cuboid_in_slab: option 'size' must be {a, b, rho}", froth.cuboid_in_slab, {size = {1, 1}})
T.check_error("cuboid_in_slab: size must be positive in x, y and z, got {1, 0, 8}",
              froth.cuboid_in_slab, {size = {1, 0, 8}})
T.check_error("drop_on_sphere_wall: r must be smaller than R = 2, got 2", froth.drop_on_sphere_wall, {r = 2})
T.check_error("drop_on_sphere_wall: option keys must be names", froth.drop_on_sphere_wall, {1})

T.summary()
