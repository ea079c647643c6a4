-- froth.double_bubble and froth.sphere (gmsh): topology, volumes against exact formulas,
-- options, and every option error.
local T = require("froth.test")
if not froth.has("gmsh") then
  T.assert_true(froth.double_bubble == nil and froth.sphere == nil,
                "no meshed builders without gmsh")
  T.assert_equal(type(froth.read), "function", "froth.read needs no gmsh")
  return T.summary()
end
local pi = math.pi
local function rel(a, b) return math.abs(a - b) / math.abs(b) end
-- volume of a spherical cap of height h of the unit ball
local function cap(h) return pi * h * h * (3 - h) / 3 end

-- The unit ball cut at z = 0: surfaces 1 (lower cap), 2 (upper cap), 3 (flat wall);
-- bodies 1 = {1, 3} below, 2 = {2, 3} above; one closed triple line on the unit circle.
local c = froth.double_bubble{h = 0.2}
local info = c:info()
T.assert_equal(info.surfaces, 3, "surfaces")
T.assert_equal(info.triple_lines, 1, "one triple line")
T.assert_equal(info.quadruple_points, 0, "no quadruple points")
T.assert_equal(info.bodies, 2, "two bodies")
T.assert_true(info.vertices > 100 and info.vertices < 2000, "vertex count for h = 0.2", info.vertices)
local vol = c:volumes()
T.assert_true(rel(vol[1], 2 * pi / 3) < 0.03 and rel(vol[2], 2 * pi / 3) < 0.03,
              "half-ball volumes near 2 pi/3", vol[1] .. " " .. vol[2])
T.assert_true(vol[1] < 2 * pi / 3 and vol[2] < 2 * pi / 3, "inscribed meshes are smaller")
T.assert_true(rel(c:area(1), 2 * pi) < 0.03 and rel(c:area(2), 2 * pi) < 0.03, "cap areas near 2 pi")
T.assert_true(rel(c:area(3), pi) < 0.03, "wall area near pi")
local b = c:bodies()
T.assert_true(#b[1] == 2 and math.abs(b[1][1]) == 1 and math.abs(b[1][2]) == 3, "body 1 = {1, 3}")
T.assert_true(#b[2] == 2 and math.abs(b[2][1]) == 2 and math.abs(b[2][2]) == 3, "body 2 = {2, 3}")
T.assert_true(b[1][2] * b[2][2] < 0, "the wall faces out of one body and into the other")
local line = c:triple_lines()[1]
T.assert_true(line.closed and line.surfaces[1] == 1 and line.surfaces[2] == 2 and
              line.surfaces[3] == 3, "the line is a loop of surfaces 1, 2, 3")
local worst = 0
for _, v in ipairs(line.vertices) do
  local x = c:vertex(v)
  worst = math.max(worst, math.abs(x[3]), math.abs(math.sqrt(x[1] ^ 2 + x[2] ^ 2) - 1))
end
T.assert_true(worst < 1e-9, "line vertices lie on the unit circle in z = 0", worst)
for i = 1, 3 do T.assert_equal(c:sigma(i), 1, "default sigma " .. i) end
-- The lower cap lies below z = 0 and the upper above.
local low, high = math.huge, -math.huge
for v = 1, info.vertices do
  local z = c:vertex(v)[3]
  low, high = math.min(low, z), math.max(high, z)
end
T.assert_true(math.abs(low + 1) < 1e-9 and math.abs(high - 1) < 1e-9, "the ball spans z in [-1, 1]")

-- split moves the wall to z = split: body 1 (below) is the cap of height 1 + split.
local s3 = froth.double_bubble{h = 0.2, split = 0.3}
local sv = s3:volumes()
T.assert_true(rel(sv[1], cap(1.3)) < 0.03, "split 0.3: lower volume", sv[1] .. " vs " .. cap(1.3))
T.assert_true(rel(sv[2], cap(0.7)) < 0.03, "split 0.3: upper volume", sv[2] .. " vs " .. cap(0.7))
T.assert_true(sv[1] > 2 * sv[2], "split 0.3: the lower body is much larger")
T.assert_true(rel(s3:area(3), pi * (1 - 0.3 ^ 2)) < 0.03, "split 0.3: wall area pi (1 - s^2)")
local wall_z = s3:vertex(s3:triple_lines()[1].vertices[1])[3]
T.assert_near(wall_z, 0.3, 1e-9, "the triple line lies at z = split")
local sm = froth.double_bubble{h = 0.2, split = -0.3}
T.assert_true(rel(sm:volumes()[1], cap(0.7)) < 0.03, "split -0.3: the lower body is the small one")
T.assert_equal(froth.double_bubble{h = 0.3, split = 0.9}:info().bodies, 2, "split 0.9 is allowed")

-- sigma: one number for all three surfaces, or one per surface.
local g = froth.double_bubble{h = 0.3, sigma = 2}
for i = 1, 3 do T.assert_equal(g:sigma(i), 2, "sigma = 2 on surface " .. i) end
T.assert_near(g:energy(), 2 * g:area(), 1e-12, "energy = 2 * area")
local h = froth.double_bubble{h = 0.3, sigma = {1, 2, 2.5}}
for i = 1, 3 do T.assert_equal(h:sigma(i), ({1, 2, 2.5})[i], "sigma[" .. i .. "]") end
T.assert_near(h:energy(), h:area(1) + 2 * h:area(2) + 2.5 * h:area(3), 1e-12, "energy with sigma {1,2,2.5}")
T.assert_equal(h:time(), 0, "a new cluster starts at t = 0")

-- sphere: volume 4/3 pi R^3, area 4 pi R^2, every vertex exactly on the sphere.
local sp = froth.sphere{R = 2, h = 0.3}
T.assert_equal(sp:info().surfaces, 1, "sphere: one surface")
T.assert_equal(sp:info().bodies, 1, "sphere: one body")
T.assert_equal(sp:info().triple_lines, 0, "sphere: no triple lines")
T.assert_true(rel(sp:volumes()[1], 32 * pi / 3) < 0.03, "sphere volume near 32 pi/3", sp:volumes()[1])
T.assert_true(rel(sp:area(), 16 * pi) < 0.03, "sphere area near 16 pi", sp:area())
local centre = {1, -2, 3}
local moved = froth.sphere{R = 2, h = 0.3, center = centre}
local off, mean = 0, {0, 0, 0}
local n = moved:info().vertices
for v = 1, n do
  local x = moved:vertex(v)
  local d = {x[1] - centre[1], x[2] - centre[2], x[3] - centre[3]}
  off = math.max(off, math.abs(math.sqrt(d[1] ^ 2 + d[2] ^ 2 + d[3] ^ 2) - 2))
  for k = 1, 3 do mean[k] = mean[k] + d[k] / n end
end
T.assert_true(off < 1e-12, "centered sphere: every vertex at distance R from the center", off)
T.assert_true(math.abs(mean[1]) < 0.05 and math.abs(mean[2]) < 0.05 and math.abs(mean[3]) < 0.05,
              "centered sphere: vertices are centred on the center")
T.assert_near(moved:volumes()[1], sp:volumes()[1], 1e-9, "moving the center keeps the volume")
local unit = froth.sphere{h = 0.3} -- R defaults to 1
T.assert_true(rel(unit:volumes()[1], 4 * pi / 3) < 0.03, "default R = 1")

-- Errors.
local function bad_db(text, opts) T.check_error(text, froth.double_bubble, opts) end
bad_db("double_bubble: h must be positive, got 0", {h = 0})
bad_db("double_bubble: h must be positive, got -0.1", {h = -0.1})
bad_db("double_bubble: h must be positive", {h = 0 / 0})
bad_db("double_bubble: h = 0.001 is too small (about 18849556 vertices); use h >= 0.005", {h = 0.001})
bad_db("double_bubble: h must be at most 0.5, got 0.6", {h = 0.6})
bad_db("double_bubble: split must be in [-0.9, 0.9], got 0.95", {h = 0.3, split = 0.95})
bad_db("double_bubble: split must be in [-0.9, 0.9], got -1", {h = 0.3, split = -1})
bad_db("double_bubble: sigma[1] must be positive, got 0", {h = 0.3, sigma = 0})
bad_db("double_bubble: sigma[2] must be positive, got -1", {h = 0.3, sigma = {1, -1, 1}})
bad_db("double_bubble: sigma[3] must be positive", {h = 0.3, sigma = {1, 1, math.huge}})
bad_db("double_bubble: option 'sigma' must have 3 values", {h = 0.3, sigma = {1, 2}})
bad_db("double_bubble: option 'sigma' must have 3 values", {h = 0.3, sigma = {1, 2, 3, 4}})
bad_db("double_bubble: sigma[2] must be a number", {h = 0.3, sigma = {1, "2", 3}})
bad_db("double_bubble: option 'sigma' must be a number or a table of 3 numbers", {h = 0.3, sigma = "1"})
bad_db("double_bubble: option 'h' must be a number", {h = "0.3"})
bad_db("double_bubble: unknown option 'hh'", {hh = 0.3})
bad_db("double_bubble: expected an option table {...}, got number", 0.3)
local function bad_sp(text, opts) T.check_error(text, froth.sphere, opts) end
bad_sp("sphere: R must be positive, got 0", {R = 0})
bad_sp("sphere: R must be positive, got -1", {R = -1})
bad_sp("sphere: h must be positive, got 0", {h = 0})
bad_sp("sphere: h must be at most 1, got 2", {h = 2})
bad_sp("sphere: h = 0.005 is too small (about 2412743 vertices); use h >= 0.007", {R = 2, h = 0.005})
bad_sp("sphere: center must be {x, y, z}", {center = {1, 2}})
bad_sp("sphere: center must be {x, y, z}", {center = "origin"})
bad_sp("sphere: center must be finite", {center = {0, 0 / 0, 0}})
bad_sp("sphere: unknown option 'radius'", {radius = 1})
bad_sp("sphere: expected an option table {...}, got string", "unit")

T.summary()
