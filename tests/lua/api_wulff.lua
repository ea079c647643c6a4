-- Wulff shapes and Frank diagrams from Lua: froth.wulff_shape against the ellipsoid of an
-- ellipsoidal gamma (volume from above, converging), E = 3 r^2 |W| through c:set_anisotropy and
-- c:energy, the scale option, Fibonacci directions, the l1 preset between the unit cube and its
-- axis box; froth.frank_diagram on the level set gamma = 1 and its ellipsoid volume;
-- froth.cahn_hoffmann_check; every option error naming the option and value.
local T = require("froth.test")
local A = froth.anisotropies
local pi, sqrt = math.pi, math.sqrt

-- G symmetric positive definite, not diagonal; det G = 0.8 (worked out by hand below).
local G = {{2, 0.3, 0}, {0.3, 1, 0}, {0, 0, 0.5}}
local detG = (2 * 1 - 0.3 * 0.3) * 0.5
local g = A.ellipsoidal(G)
local wulff_exact = 4 / 3 * pi * sqrt(detG)     -- q . G^-1 q <= 1
local frank_exact = 4 / 3 * pi / sqrt(detG)     -- p . G p <= 1

-- Frank diagram (needs no CGAL) ----------------------------------------------------------------

local previous = math.huge
for k = 2, 4 do
  local f = froth.frank_diagram(g, {subdivisions = k})
  local info = f:info()
  T.assert_equal(info.vertices, 10 * 4 ^ k + 2, "icosphere vertex count")
  T.assert_equal(T.counts(f), "1/0/0/1", "one surface, one body")
  local worst = 0
  for v = 1, info.vertices do worst = math.max(worst, math.abs(g:gamma(f:vertex(v)) - 1)) end
  T.assert_near(worst, 0, 1e-15, "gamma = 1 at every vertex")
  local err = (frank_exact - f:volumes()[1]) / frank_exact
  T.assert_true(err > 0 and err < previous / 3, "Frank volume from below, second order",
                ("level %d: error %.3e (before %.3e)"):format(k, err, previous))
  previous = err
end
T.assert_true(previous < 4e-3, "Frank volume at level 4", previous)
T.assert_equal(froth.frank_diagram(g):info().vertices, 2562, "default subdivisions 4")

if not froth.has("cgal") then
  T.check_error("froth was built without CGAL", froth.wulff_shape, g)
  T.summary()
  return
end

-- Wulff shape of an ellipsoidal gamma ---------------------------------------------------------

previous = math.huge
local w3
for k = 2, 4 do
  local w = froth.wulff_shape(g, {subdivisions = k})
  local err = (w:volumes()[1] - wulff_exact) / wulff_exact
  T.assert_true(err > 0 and err < previous / 3, "Wulff volume from above, second order",
                ("level %d: error %.3e (before %.3e)"):format(k, err, previous))
  previous = err
  if k == 3 then w3 = w end
end
T.assert_true(previous < 3e-3, "Wulff volume at level 4", previous)

-- Every vertex lies outside W (gamma* >= 1): the polytope circumscribes the ellipsoid.
local lo = math.huge
for v = 1, w3:info().vertices do lo = math.min(lo, g:gamma_star(w3:vertex(v))) end
T.assert_true(lo >= 1 - 1e-12, "gamma*(v) >= 1 at every vertex", lo)

-- E = sum gamma(nu) |facet| = 3 |W_h|, and with scale r: |r W_h| = r^3 |W_h|, E = 3 r^2 |W_h|.
local V1 = w3:volumes()[1]
w3:set_anisotropy(1, g)
T.assert_near(w3:energy() / (3 * V1), 1, 1e-13, "E = 3 |W_h|")
local r = 2.5
local wr = froth.wulff_shape(g, {subdivisions = 3, scale = r})
wr:set_anisotropy(1, g)
T.assert_near(wr:volumes()[1] / (r ^ 3 * V1), 1, 1e-13, "scale: volume r^3 |W_h|")
T.assert_near(wr:energy() / (3 * r ^ 2 * V1), 1, 1e-13, "scale: energy 3 r^2 |W_h|")

-- Cahn–Hoffmann: gamma'(p) inside W_h, on its boundary as the directions fill the sphere.
previous = math.huge
for k = 2, 4 do
  local c = froth.cahn_hoffmann_check(g, froth.wulff_shape(g, {subdivisions = k}))
  T.assert_equal(c.samples, 1000, "default samples")
  T.assert_true(c.max_outside < 1e-13, "gamma'(p) inside W_h", c.max_outside)
  T.assert_true(c.max_support_error < 1e-12, "facets at their support value", c.max_support_error)
  T.assert_true(c.energy_defect < 1e-13, "energy defect", c.energy_defect)
  T.assert_true(c.max_distance < previous / 3, "Cahn-Hoffmann distance, second order",
                ("level %d: %.3e"):format(k, c.max_distance))
  previous = c.max_distance
end
local cr = froth.cahn_hoffmann_check(g, wr, {scale = r, samples = 300})
T.assert_equal(cr.samples, 300, "samples option")
T.assert_true(cr.max_outside < 1e-13 and cr.energy_defect < 1e-13, "scaled shape against r W")
local wrong = froth.cahn_hoffmann_check(g, wr)  -- r W_h is not W_h
T.assert_true(wrong.energy_defect > 0.5, "a wrong scale shows", wrong.energy_defect)

-- Fibonacci directions.
local wf = froth.wulff_shape(g, {directions = 2000})
local ef = (wf:volumes()[1] - wulff_exact) / wulff_exact
T.assert_true(ef > 0 and ef < 3e-3, "2000 Fibonacci directions", ef)

-- The l1 preset (5.6), Fig. 2 left: the cube [-1, 1]^3 lies in W (gamma >= |p|_1), W_h in the
-- box of its axis planes |q_j| <= gamma(e_j) = 1 + 2 eps.
for _, eps in ipairs({0.1, 0.01}) do
  local V = froth.wulff_shape(A.l1{eps = eps}, {subdivisions = 4}):volumes()[1]
  T.assert_true(V > 8 and V < 8 * (1 + 2 * eps) ^ 3, "l1 Wulff shape between cube and box",
                ("eps %g: volume %.6f"):format(eps, V))
end
for _, name in ipairs({"hexagonal", "fig3_left", "fig3_right"}) do
  local gp = A[name]()
  local c = froth.wulff_shape(gp, {subdivisions = 3})
  local chk = froth.cahn_hoffmann_check(gp, c)
  T.assert_true(chk.max_outside < 1e-13 and chk.energy_defect < 1e-13, name .. " circumscribes W")
end

-- Writing works like for any cluster.
local path = T.temp_path(".vtu")
w3:write(path)
local file = io.open(path)
T.assert_true(file ~= nil, "c:write of a Wulff shape")
if file then file:close() end
os.remove(path)

-- Errors --------------------------------------------------------------------------------------

T.check_error("froth.Anisotropy", froth.wulff_shape, 1)
T.check_error("froth.Anisotropy", froth.frank_diagram, {})
T.check_error("subdivisions must be an integer in 0..7 (got 8)", froth.wulff_shape, g,
              {subdivisions = 8})
T.check_error("subdivisions must be an integer in 0..7 (got -1)", froth.wulff_shape, g,
              {subdivisions = -1})
T.check_error("option 'subdivisions' must be an integer", froth.wulff_shape, g,
              {subdivisions = 2.5})
T.check_error("directions must be an integer in 20..200000 (got 19)", froth.wulff_shape, g,
              {directions = 19})
T.check_error("directions must be an integer in 20..200000 (got 0)", froth.wulff_shape, g,
              {directions = 0})
T.check_error("exclude each other", froth.wulff_shape, g, {directions = 100, subdivisions = 2})
T.check_error("wulff_shape: scale must be a finite number > 0 (got 0)", froth.wulff_shape, g,
              {scale = 0})
T.check_error("scale must be a finite number > 0 (got -1)", froth.wulff_shape, g, {scale = -1})
T.check_error("scale must be a finite number > 0 (got inf)", froth.wulff_shape, g,
              {scale = math.huge})
T.check_error("option 'scale' must be a number", froth.wulff_shape, g, {scale = "big"})
T.check_error("option 'facet_directions' must be true or false", froth.wulff_shape, g,
              {facet_directions = 1})
T.check_error("wulff_shape: unknown option 'sclae'", froth.wulff_shape, g, {sclae = 2})
T.check_error("frank_diagram: subdivisions must be an integer in 0..7 (got 9)",
              froth.frank_diagram, g, {subdivisions = 9})
T.check_error("frank_diagram: unknown option 'scale'", froth.frank_diagram, g, {scale = 2})
T.check_error("froth.Cluster expected", froth.cahn_hoffmann_check, g, {})
T.check_error("cahn_hoffmann_check: samples must be an integer in 1..200000 (got 0)",
              froth.cahn_hoffmann_check, g, w3, {samples = 0})
T.check_error("cahn_hoffmann_check: scale must be a finite number > 0 (got -2)",
              froth.cahn_hoffmann_check, g, w3, {scale = -2})

T.summary()
