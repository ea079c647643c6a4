-- froth.fragment (gmsh): counts, volumes against exact values, the surface and body order,
-- solid options and transformations, sigma, transform, and the error messages.
local T = require("froth.test")
if not froth.has("gmsh") then
  T.assert_true(froth.fragment == nil, "no froth.fragment without gmsh")
  return T.summary()
end
local pi = math.pi
local rel, counts = T.rel, T.counts
-- the extent of the vertices along coordinate d
local function range(c, d)
  local lo, hi = math.huge, -math.huge
  for v = 1, c:info().vertices do
    local x = c:vertex(v)[d]
    lo, hi = math.min(lo, x), math.max(hi, x)
  end
  return lo, hi
end

-- One ball: one surface, one body; every vertex on the sphere.
local one = froth.fragment{solids = {{"ball", center = {1, 2, 3}, r = 0.5}}, h = 0.1}
T.assert_equal(counts(one), "1/0/0/1", "one ball: surfaces/lines/points/bodies")
T.assert_true(rel(one:volumes()[1], 4 / 3 * pi * 0.125) < 0.02, "one ball: volume", one:volumes()[1])

-- Two overlapping unit balls at distance 1: body 2 = B \ A = ball minus the lens
-- pi (4 r + d) (2 r - d)^2 / 12 = 5 pi / 12.
local two = froth.fragment{solids = {{"ball", r = 1}, {"ball", center = {1, 0, 0}, r = 1}}, h = 0.1}
T.assert_equal(counts(two), "3/1/0/2", "two balls")
local v = two:volumes()
T.assert_true(rel(v[1], 4 * pi / 3) < 0.015, "two balls: body 1 is the whole first ball", v[1])
T.assert_true(rel(v[2], 4 * pi / 3 - 5 * pi / 12) < 0.015, "two balls: body 2 = B minus the lens", v[2])
-- Surfaces by region pair: 1 = (outside, 1), 2 = (outside, 2), 3 = (1, 2): the wall is part
-- of sphere A, inside B.
local b = two:bodies()
T.assert_true(#b[1] == 2 and math.abs(b[1][1]) == 1 and math.abs(b[1][2]) == 3, "body 1 = {1, 3}")
T.assert_true(#b[2] == 2 and math.abs(b[2][1]) == 2 and math.abs(b[2][2]) == 3, "body 2 = {2, 3}")
local wall_off = 0
for _, l in ipairs(two:triple_lines()) do
  for _, w in ipairs(l.vertices) do
    local x = two:vertex(w)
    wall_off = math.max(wall_off, math.abs(x[1] - 0.5))
  end
end
T.assert_true(wall_off < 1e-9, "the triple line is the circle x = 1/2", wall_off)

-- Overlapping balls in the order given: the later minus the earlier (dependencies.md
-- "three_spheres"): 3 bodies, 6 films, 4 triple lines, 2 quadruple points.
local three = froth.fragment{solids = {{"ball", r = 1}, {"ball", center = {1, 0, 0}, r = 1},
                                       {"ball", center = {0.5, 0.8, 0}, r = 1}}, h = 0.15}
T.assert_equal(counts(three), "6/4/2/3", "three balls")
T.assert_true(rel(three:volumes()[1], 4 * pi / 3) < 0.015, "three balls: body 1 is ball 1")

-- A box with a ball on its top face: the ball's body is the half ball outside the box.
local bb = froth.fragment{solids = {{"box", min = {-1, -1, -1}, max = {1, 1, 1}},
                                    {"ball", center = {0, 0, 1}, r = 0.6}}, h = 0.1}
T.assert_equal(counts(bb), "3/1/0/2", "box + ball")
T.assert_near(bb:volumes()[1], 8, 1e-9, "box + ball: the box keeps its volume")
T.assert_true(rel(bb:volumes()[2], 2 / 3 * pi * 0.216) < 0.015, "box + ball: half ball", bb:volumes()[2])
T.assert_near(bb:area(3), pi * 0.36, 0.02 * pi * 0.36, "box + ball: the wall is the disk r = 0.6")

-- size = ... is the same box as max = ...; rotate about the solid's center, then translate.
local rb = froth.fragment{solids = {{"box", min = {0, 0, 0}, size = {1, 1, 1}, translate = {10, 0, 0},
                                     rotate = {axis = {0, 0, 1}, angle = pi / 4}}}, h = 0.2}
local lo, hi = range(rb, 1)
T.assert_near(lo, 10.5 - math.sqrt(0.5), 1e-9, "rotated box: x min")
T.assert_near(hi, 10.5 + math.sqrt(0.5), 1e-9, "rotated box: x max")
T.assert_near(rb:volumes()[1], 1, 1e-9, "rotated box: volume 1")

-- scale: a number, or factors {sx, sy, sz} (an ellipsoid).
local el = froth.fragment{solids = {{"ball", r = 1, scale = {1, 1, 2}}}, h = 0.12}
T.assert_true(rel(el:volumes()[1], 8 * pi / 3) < 0.015, "ellipsoid volume", el:volumes()[1])
local z0, z1 = range(el, 3)
T.assert_near(z1 - z0, 4, 1e-6, "ellipsoid height")
local big = froth.fragment{solids = {{"ball", r = 1, scale = 2}}, h = 0.25}
T.assert_true(rel(big:volumes()[1], 32 * pi / 3) < 0.02, "scale = 2", big:volumes()[1])

-- cylinder: base, axis vector (length = height), r. torus: center, R, r, axis.
local cy = froth.fragment{solids = {{"cylinder", base = {0, 0, 0}, axis = {2, 0, 0}, r = 0.5}}, h = 0.1}
T.assert_true(rel(cy:volumes()[1], pi * 0.25 * 2) < 0.015, "cylinder volume", cy:volumes()[1])
lo, hi = range(cy, 1)
T.assert_true(math.abs(lo) < 1e-9 and math.abs(hi - 2) < 1e-9, "cylinder along x from 0 to 2")
local to = froth.fragment{solids = {{"torus", R = 2, r = 0.5, axis = {1, 0, 0}}}, h = 0.12}
T.assert_true(rel(to:volumes()[1], 2 * pi ^ 2 * 2 * 0.25) < 0.015, "torus volume", to:volumes()[1])
lo, hi = range(to, 1)
T.assert_true(math.abs(lo + 0.5) < 1e-4 and math.abs(hi - 0.5) < 1e-4, "torus about the x axis",
              lo .. " " .. hi)

-- angle: a wedge of a ball; three of them make the triple bubble.
local wedge = froth.fragment{solids = {{"ball", r = 1, angle = pi / 2}}, h = 0.1}
T.assert_equal(counts(wedge), "1/0/0/1", "a wedge is one surface")
T.assert_true(rel(wedge:volumes()[1], pi / 3) < 0.01, "quarter ball volume", wedge:volumes()[1])

-- latitude: the band of a ball between two latitudes; {0, pi/2} is the upper half ball.
local half = froth.fragment{solids = {{"ball", r = 1, latitude = {0, pi / 2}}}, h = 0.1}
T.assert_equal(counts(half), "1/0/0/1", "a half ball is one surface (dome and disk)")
T.assert_true(rel(half:volumes()[1], 2 * pi / 3) < 0.01, "half ball volume", half:volumes()[1])
local whole = froth.fragment{solids = {{"ball", r = 1, latitude = {-pi / 2, pi / 2}}}, h = 0.2}
T.assert_true(rel(whole:volumes()[1], 4 * pi / 3) < 0.02, "latitude {-pi/2, pi/2}: the ball")

-- Boxes sharing faces: the seed's quadruple bubble.
local quad = froth.fragment{solids = {{"box", min = {0, 0, 0}, size = {2, 1, 1}},
                                      {"box", min = {0, 0, 1}, size = {1, 1, 1}},
                                      {"box", min = {1, 0, 1}, size = {1, 1, 1}},
                                      {"box", min = {0, 0, 2}, size = {2, 1, 1}}}, h = 0.2}
T.assert_equal(counts(quad), "9/8/4/4", "quadruple bubble of boxes")

-- body ids: solids with one id form one body (a union), the order of the solids still decides
-- who owns an overlap. A capsule (two half balls on a cylinder: one body, one film, its
-- internal disks dropped), then the same capsule after a ball inside it, listed first: the
-- ball keeps its volume (as body 2), body 1 = the capsule minus the ball.
local function capsule_parts(body)
  return {{"ball", center = {0, 0, 0.5}, r = 1, latitude = {0, pi / 2}, body = body},
          {"ball", center = {0, 0, -0.5}, r = 1, latitude = {-pi / 2, 0}, body = body},
          {"cylinder", base = {0, 0, -0.5}, axis = {0, 0, 1}, r = 1, body = body}}
end
local capsule = froth.fragment{solids = capsule_parts(1), h = 0.1}
T.assert_equal(counts(capsule), "1/0/0/1", "a capsule from three solids: one film, one body")
local capsule_volume = 4 * pi / 3 + pi
T.assert_true(rel(capsule:volumes()[1], capsule_volume) < 0.01, "capsule: 4 pi/3 + pi",
              capsule:volumes()[1])
local parts = capsule_parts(1)
table.insert(parts, 1, {"ball", r = 0.5, body = 2})
local hollow = froth.fragment{solids = parts, h = 0.1}
T.assert_equal(counts(hollow), "2/0/0/2", "a ball inside the capsule, listed first")
T.assert_true(rel(hollow:volumes()[2], pi / 6) < 0.02, "the ball listed first keeps its volume",
              hollow:volumes()[2])
T.assert_true(rel(hollow:volumes()[1], capsule_volume - pi / 6) < 0.01,
              "body 1 = the capsule minus the ball", hollow:volumes()[1])

-- h on one solid refines the films of its body only.
local coarse = froth.fragment{solids = {{"ball", r = 1}, {"ball", center = {1.5, 0, 0}, r = 1}}, h = 0.2}
local fine = froth.fragment{solids = {{"ball", r = 1}, {"ball", center = {1.5, 0, 0}, r = 1, h = 0.08}},
                            h = 0.2}
T.assert_true(fine:info().vertices > 3 * coarse:info().vertices, "local h refines",
              fine:info().vertices .. " vs " .. coarse:info().vertices)

-- Without h: about `vertices` vertices (default 5000).
local auto = froth.fragment{solids = {{"ball", r = 1}}, vertices = 2000}
T.assert_true(math.abs(auto:info().vertices - 2000) < 200, "vertices = 2000", auto:info().vertices)

-- sigma: a number, or {[surface] = sigma} (others 1).
local s1 = froth.fragment{solids = {{"ball", r = 1}, {"ball", center = {1, 0, 0}, r = 1}}, h = 0.3,
                          sigma = 2}
for i = 1, 3 do T.assert_equal(s1:sigma(i), 2, "sigma = 2 on surface " .. i) end
local s2 = froth.fragment{solids = {{"ball", r = 1}, {"ball", center = {1, 0, 0}, r = 1}}, h = 0.3,
                          sigma = {[3] = 1.5}}
T.assert_equal(s2:sigma(3), 1.5, "sigma[3]")
T.assert_equal(s2:sigma(1), 1, "unlisted sigma is 1")
local s3 = froth.fragment{solids = {{"ball", r = 1}, {"ball", center = {1, 0, 0}, r = 1}}, h = 0.3,
                          sigma = {1, 2, 2.5}}
for i = 1, 3 do T.assert_equal(s3:sigma(i), ({1, 2, 2.5})[i], "sigma array " .. i) end

-- transform maps every mesh vertex after meshing (gmsh's mesh is deterministic).
local plain = froth.fragment{solids = {{"ball", r = 1}}, h = 0.3}
local tr = froth.fragment{solids = {{"ball", r = 1}}, h = 0.3,
                          transform = function(x, y, z) return 2 * x, y, z + 1 end}
T.assert_equal(tr:info().vertices, plain:info().vertices, "transform keeps the vertices")
local worst = 0
for w = 1, plain:info().vertices do
  local p, q = plain:vertex(w), tr:vertex(w)
  worst = math.max(worst, math.abs(q[1] - 2 * p[1]), math.abs(q[2] - p[2]), math.abs(q[3] - p[3] - 1))
end
T.assert_true(worst < 1e-12, "transform maps x -> 2x, z -> z + 1", worst)
T.assert_true(rel(tr:volumes()[1], 2 * plain:volumes()[1]) < 1e-9, "transform doubles the volume")

-- Errors.
local function bad(text, args) T.check_error(text, froth.fragment, args) end
local B = {"ball", r = 1}
bad("fragment: solids[2] (ball): radius r must be positive, got 0", {solids = {B, {"ball", r = 0}}})
bad("fragment: solids[1] (ball): radius r must be positive, got -1", {solids = {{"ball", r = -1}}})
bad("fragment: solids[1] (box): size must be positive in x, y and z, got {1, 1, 0}",
    {solids = {{"box", min = {0, 0, 0}, max = {1, 1, 0}}}})
bad("fragment: solids[1] (box): give exactly one of max and size", {solids = {{"box", min = {0, 0, 0}}}})
bad("fragment: solids[1] (box): option 'min' is required", {solids = {{"box", size = {1, 1, 1}}}})
bad("fragment: solids[1] (torus): tube radius r = 1 must be smaller than the major radius R = 1",
    {solids = {{"torus", R = 1, r = 1}}})
bad("fragment: solids[1] (cylinder): axis must be a nonzero vector (its length is the height)",
    {solids = {{"cylinder", r = 1, axis = {0, 0, 0}}}})
bad("fragment: solids[1]: unknown solid kind 'cone' (known: ball, box, cylinder, torus)",
    {solids = {{"cone", r = 1}}})
bad('fragment: solids[1] must start with its kind: "ball", "box", "cylinder" or "torus"',
    {solids = {{r = 1}}})
bad('fragment: solids[2] must be a table such as {"ball", r = 1}, got number', {solids = {B, 3}})
bad("fragment: solids[1] (ball): unknown option 'radius'", {solids = {{"ball", r = 1, radius = 1}}})
bad("fragment: solids[1] (ball): center must be {x, y, z}", {solids = {{"ball", r = 1, center = {1, 2}}}})
bad("fragment: solids[1] (ball): scale must be positive, got {0, 0, 0}", {solids = {{"ball", r = 1, scale = 0}}})
bad("fragment: solids[1] (ball): scale must be a number or {sx, sy, sz}", {solids = {{"ball", r = 1, scale = {1, 2}}}})
bad("fragment: solids[1] (ball): rotate: option 'angle' is required",
    {solids = {{"ball", r = 1, rotate = {axis = {1, 0, 0}}}}})
bad("fragment: solids[1] (ball): rotate axis must be a nonzero vector",
    {solids = {{"ball", r = 1, rotate = {axis = {0, 0, 0}, angle = 1}}}})
bad("fragment: solids[1] (ball): angle must be in (0, 2 pi], got 7", {solids = {{"ball", r = 1, angle = 7}}})
bad("fragment: solids[1] (ball): latitude {lo, hi} must satisfy -pi/2 <= lo < hi <= pi/2 (radians), got {1, 1}",
    {solids = {{"ball", r = 1, latitude = {1, 1}}}})
bad("fragment: solids[1] (ball): latitude {lo, hi} must satisfy -pi/2 <= lo < hi <= pi/2 (radians), got {-2, 0}",
    {solids = {{"ball", r = 1, latitude = {-2, 0}}}})
bad("fragment: solids[1] (ball): latitude must be {lo, hi} (radians)", {solids = {{"ball", r = 1, latitude = 0}}})
bad("fragment: solids[1] (ball): latitude must be {lo, hi} (radians)", {solids = {{"ball", r = 1, latitude = {0, "1"}}}})
bad("fragment: solids[1] (box): unknown option 'latitude'",
    {solids = {{"box", min = {0, 0, 0}, size = {1, 1, 1}, latitude = {0, 1}}}})
bad("fragment: solids[2] (ball) lies inside the solids before it: its body would be empty",
    {solids = {B, {"ball", r = 0.5}}, h = 0.3})
bad("fragment: solids[2] (ball) has no body id, solids[1] has one: give body to every solid or to none",
    {solids = {{"ball", r = 1, body = 1}, {"ball", center = {1, 0, 0}, r = 1}}, h = 0.3})
bad("fragment: solids[2] (ball) has body id, solids[1] has none: give body to every solid or to none",
    {solids = {B, {"ball", center = {1, 0, 0}, r = 1, body = 1}}, h = 0.3})
bad("fragment: solids[2] (ball): body = 3 must be in 1..2 (one body per id)",
    {solids = {{"ball", r = 1, body = 1}, {"ball", center = {1, 0, 0}, r = 1, body = 3}}, h = 0.3})
bad("fragment: solids[1] (ball): body = 0 must be in 1..2 (one body per id)",
    {solids = {{"ball", r = 1, body = 0}, {"ball", center = {1, 0, 0}, r = 1, body = 1}}, h = 0.3})
bad("fragment: body ids must number the bodies 1..n: no solid has body 1",
    {solids = {{"ball", r = 1, body = 2}, {"ball", center = {1, 0, 0}, r = 1, body = 2}}, h = 0.3})
bad("fragment: solids[1] (ball): option 'body' must be an integer", {solids = {{"ball", r = 1, body = 1.5}}})
bad("fragment: solids[2] (ball) lies inside the solids before it: it adds nothing to its body",
    {solids = {{"ball", r = 1, body = 1}, {"ball", r = 0.5, body = 1}}, h = 0.3})
bad("fragment: solids[3] (ball) touches no other solid: a cluster must be connected",
    {solids = {B, {"ball", center = {1, 0, 0}, r = 1}, {"ball", center = {5, 0, 0}, r = 1}}, h = 0.3})
bad("fragment: solids[3] (ball) is not connected to solids[1]: a cluster must be connected",
    {solids = {B, {"ball", center = {1, 0, 0}, r = 1}, {"ball", center = {5, 0, 0}, r = 1},
               {"ball", center = {6, 0, 0}, r = 1}}, h = 0.3})
bad("fragment: h must be positive, got 0", {solids = {B}, h = 0})
bad("fragment: h = 5 is larger than the cluster (extent 2); use h <= 2", {solids = {B}, h = 5})
bad("fragment: h = 0.001 gives about 15079645 vertices, more than 400000; use a larger h (h >= 0.00620136)",
    {solids = {B}, h = 0.001})
bad("fragment: h = 0.1 (with the solids' own h) gives about 15079645 vertices, more than 400000",
    {solids = {{"ball", r = 1, h = 0.001}}, h = 0.1})
bad("fragment: solids[1] (ball): h must be positive, got -1", {solids = {{"ball", r = 1, h = -1}}})
bad("fragment: give h or vertices, not both", {solids = {B}, h = 0.3, vertices = 1000})
bad("fragment: vertices must be in [100, 400000], got 10", {solids = {B}, vertices = 10})
bad("fragment: sigma[3] names surface 3, but the cluster has only 1 surface", {solids = {B}, h = 0.3, sigma = {[3] = 2}})
bad("fragment: sigma[1] must be positive, got 0", {solids = {B}, h = 0.3, sigma = {0}})
bad("fragment: sigma must be positive, got -1", {solids = {B}, h = 0.3, sigma = -1})
bad("fragment: sigma keys must be surface ids 1, 2, ...", {solids = {B}, h = 0.3, sigma = {a = 1}})
bad("fragment: sigma[1] must be a number", {solids = {B}, h = 0.3, sigma = {"1"}})
bad("fragment: option 'sigma' must be a number or a table {[surface] = sigma}", {solids = {B}, sigma = "1"})
bad("fragment: option 'transform' must be a function (x, y, z) -> x, y, z", {solids = {B}, transform = 1})
bad("fragment: transform must return 3 numbers x, y, z",
    {solids = {B}, h = 0.3, transform = function(x) return x end})
bad("fragment: no solids", {solids = {}})
bad("fragment: option 'solids' must be a table of solids, got nil", {h = 0.1})
bad("fragment: unknown option 'hh'", {solids = {B}, hh = 0.1})
bad("fragment: expected an option table {...}, got number", 3)

T.summary()
