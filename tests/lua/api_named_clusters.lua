-- The named clusters of lua/froth/clusters.lua (seed §5.1): froth.torus_bubble,
-- froth.triple_bubble, froth.quadruple_bubble. Counts, default sizes, volumes against exact
-- values, the seed's stretching, sigma, surface numbering and errors.
local T = require("froth.test")
if not froth.has("gmsh") then
  T.assert_true(froth.torus_bubble == nil and froth.triple_bubble == nil and
                froth.quadruple_bubble == nil, "no named clusters without gmsh")
  return T.summary()
end
local pi = math.pi
local rel, counts = T.rel, T.counts
-- signed surface ids of body k as a string, e.g. "1 -4 5"
local function body(c, k)
  local ids = {}
  for _, s in ipairs(c:bodies()[k]) do ids[#ids + 1] = math.abs(s) end
  return table.concat(ids, " ")
end

-- Torus bubble, R = 2, r = 1: 4 films, 2 triple lines, no quadruple point; about 4800
-- vertices (seed K = 4802). Exact volumes: ball 32 pi / 3, torus outside it 25.956317 (by
-- quadrature of the tube section), ratio 1.291028 (the seed reports 1.28).
local tb = froth.torus_bubble()
T.assert_equal(counts(tb), "4/2/0/2", "torus bubble: surfaces/lines/points/bodies")
T.assert_true(math.abs(tb:info().vertices - 4800) < 480, "torus bubble: about 4800 vertices",
              tb:info().vertices)
local v = tb:volumes()
T.assert_true(rel(v[1] / v[2], 1.291028) < 0.01, "ball/torus = 1.291", v[1] / v[2])
T.assert_true(rel(v[1], 32 * pi / 3) < 0.01, "torus bubble: body 1 is the ball", v[1])
T.assert_equal(body(tb, 1), "1 2 4", "body 1 = caps 1, 2 and band 4")
T.assert_equal(body(tb, 2), "3 4", "body 2 = outer torus 3 and band 4")
-- sphere and torus meet where rho = 7/4, z = +-sqrt(15)/4
for k, l in ipairs(tb:triple_lines()) do
  local z = tb:vertex(l.vertices[1])[3]
  T.assert_near(math.abs(z), math.sqrt(15) / 4, 1e-6, "triple line " .. k .. " at |z| = sqrt(15)/4")
end
for k, l in ipairs(tb:triple_lines()) do
  T.assert_true(l.closed, "torus bubble: triple line " .. k .. " is a loop")
end
local high = -math.huge
for k = 1, tb:info().vertices do high = math.max(high, tb:vertex(k)[3]) end
T.assert_near(high, 2, 1e-9, "the upper cap reaches the pole")

-- r = 0.5: torus/ball = 0.170638.
local small = froth.torus_bubble{r = 0.5}
local w = small:volumes()
T.assert_true(rel(w[2] / w[1], 0.170638) < 0.01, "r = 0.5: torus/ball = 0.1706", w[2] / w[1])
T.assert_equal(counts(small), "4/2/0/2", "r = 0.5: counts")

-- layout = "halves": the two half spheres of radius 2 stand on the torus's top and bottom
-- circles (z = +-1, rho = 2), the torus body is the whole tube. Exact volumes: torus
-- 2 pi^2 R r^2 = 4 pi^2, dumbbell 4/3 pi R^3 + pi (2 r R^2 - pi R r^2 + 4/3 r^3) = 43.092756.
local halves = froth.torus_bubble{layout = "halves", h = 0.25}
T.assert_equal(counts(halves), "4/2/0/2", "halves: surfaces/lines/points/bodies")
local hv = halves:volumes()
T.assert_true(rel(hv[1], 32 * pi / 3 + pi * (8 - 2 * pi + 4 / 3)) < 0.01, "halves: the dumbbell",
              hv[1])
T.assert_true(rel(hv[2], 4 * pi ^ 2) < 0.01, "halves: body 2 is the whole tube", hv[2])
T.assert_equal(body(halves, 1), "1 2 4", "halves: dumbbell = caps 1, 2 and the inner wall 4")
T.assert_equal(body(halves, 2), "3 4", "halves: torus = its outer half 3 and inner half 4")
local off_circle = 0
for _, l in ipairs(halves:triple_lines()) do
  for _, v in ipairs(l.vertices) do
    local x = halves:vertex(v)
    off_circle = math.max(off_circle, math.abs(math.sqrt(x[1] ^ 2 + x[2] ^ 2) - 2),
                          math.abs(math.abs(x[3]) - 1))
  end
end
T.assert_true(off_circle < 1e-9, "halves: the triple lines are the circles rho = 2, z = +-1",
              off_circle)
-- stretched with r = 0.5: torus/dumbbell 0.283648 (quadrature of the stretched volumes)
local hs = froth.torus_bubble{layout = "halves", r = 0.5, stretch = true, h = 0.1}
T.assert_true(rel(hs:volumes()[2] / hs:volumes()[1], 0.283648) < 0.01,
              "halves, stretched: torus/dumbbell = 0.2836", hs:volumes()[2] / hs:volumes()[1])

-- stretch = true: the seed's G_1 (x < 0: x e^{-0.2 x}) and G_2 (y < 0: y e^{-0.1 y}) on the
-- mesh vertices; about 5300 vertices (seed K = 5314). Exact ratio 0.211214 (quadrature; the
-- seed reports 0.25).
local st = froth.torus_bubble{r = 0.5, stretch = true}
T.assert_true(math.abs(st:info().vertices - 5300) < 530, "stretched: about 5300 vertices",
              st:info().vertices)
local sv = st:volumes()
T.assert_true(rel(sv[2] / sv[1], 0.211214) < 0.01, "stretched: torus/ball = 0.2112", sv[2] / sv[1])
-- vertex by vertex against the same mesh unstretched
local a = froth.torus_bubble{r = 0.5, h = 0.3}
local b = froth.torus_bubble{r = 0.5, h = 0.3, stretch = true}
T.assert_equal(b:info().vertices, a:info().vertices, "stretching keeps the vertices")
local worst, moved = 0, 0
for k = 1, a:info().vertices do
  local p, q = a:vertex(k), b:vertex(k)
  local x = p[1] < 0 and p[1] * math.exp(-0.2 * p[1]) or p[1]
  local y = p[2] < 0 and p[2] * math.exp(-0.1 * p[2]) or p[2]
  worst = math.max(worst, math.abs(q[1] - x), math.abs(q[2] - y), math.abs(q[3] - p[3]))
  if q[1] ~= p[1] then moved = moved + 1 end
end
T.assert_true(worst < 1e-12, "stretched vertices are G_2(G_1(x))", worst)
T.assert_true(moved > a:info().vertices / 3, "about half of the vertices move", moved)

-- Triple bubble: 6 films, 4 triple lines, 2 quadruple points (the poles); about 6500
-- vertices (seed K = 6534); three equal volumes 4 pi / 9; body 1 = {1, 4, 5} as in the seed.
local tr = froth.triple_bubble()
T.assert_equal(counts(tr), "6/4/2/3", "triple bubble")
T.assert_true(math.abs(tr:info().vertices - 6500) < 650, "triple: about 6500 vertices", tr:info().vertices)
for k = 1, 3 do
  T.assert_true(rel(tr:volumes()[k], 4 * pi / 9) < 0.01, "triple: volume " .. k, tr:volumes()[k])
end
T.assert_equal(body(tr, 1), "1 4 5", "triple: body 1 = {1, 4, 5}")
T.assert_equal(body(tr, 2), "2 4 6", "triple: body 2 = {2, 4, 6}")
T.assert_equal(body(tr, 3), "3 5 6", "triple: body 3 = {3, 5, 6}")
for _, q in ipairs(tr:quadruple_points()) do
  local x = tr:vertex(q)
  T.assert_true(math.abs(x[1]) < 1e-9 and math.abs(x[2]) < 1e-9 and math.abs(math.abs(x[3]) - 1) < 1e-9,
                "triple: quadruple points at the poles")
end
-- the seed's sigma = (1.25, 1, 1, 1, 1, 1) and (1.5, 1, ...)
local t125 = froth.triple_bubble{h = 0.2, sigma = {1.25}}
T.assert_equal(t125:sigma(1), 1.25, "triple: sigma_1 = 1.25")
for k = 2, 6 do T.assert_equal(t125:sigma(k), 1, "triple: sigma_" .. k .. " = 1") end
local t15 = froth.triple_bubble{h = 0.2, sigma = {1.5, 1, 1, 1, 1, 1}}
T.assert_equal(t15:sigma(1), 1.5, "triple: sigma_1 = 1.5 (full list)")
T.assert_near(t15:energy(), t15:area() + 0.5 * t15:area(1), 1e-12, "triple: energy with sigma_1 = 1.5")
local t2 = froth.triple_bubble{h = 0.2, sigma = 2}
T.assert_near(t2:energy(), 2 * t2:area(), 1e-12, "triple: sigma = 2 everywhere")

-- Quadruple bubble: 9 films, 8 triple lines, 4 quadruple points; about 7300 vertices
-- (seed K = 7305); volumes 2, 1, 1, 2 exactly (flat faces).
local qb = froth.quadruple_bubble()
T.assert_equal(counts(qb), "9/8/4/4", "quadruple bubble")
T.assert_true(math.abs(qb:info().vertices - 7300) < 730, "quadruple: about 7300 vertices", qb:info().vertices)
local expected = {2, 1, 1, 2}
for k = 1, 4 do T.assert_near(qb:volumes()[k], expected[k], 1e-9, "quadruple: volume " .. k) end
T.assert_equal(body(qb, 1), "1 5 6", "quadruple: body 1 = {1, 5, 6}")
T.assert_equal(body(qb, 2), "2 5 7 8", "quadruple: body 2 = {2, 5, 7, 8}")
T.assert_equal(body(qb, 4), "4 8 9", "quadruple: body 4 = {4, 8, 9}")
local qs = froth.quadruple_bubble{h = 0.25, sigma = {[7] = 1.5}}
T.assert_equal(qs:sigma(7), 1.5, "quadruple: sigma[7]")
T.assert_equal(qs:sigma(6), 1, "quadruple: sigma[6]")

-- Errors name the builder.
T.check_error("torus_bubble: r must be in (0, R) = (0, 2), got 2", froth.torus_bubble, {r = 2})
T.check_error("torus_bubble: r must be in (0, R) = (0, 2), got 0", froth.torus_bubble, {r = 0})
T.check_error("torus_bubble: R must be positive, got -1", froth.torus_bubble, {R = -1})
T.check_error("torus_bubble: option 'stretch' must be true or false", froth.torus_bubble, {stretch = 1})
T.check_error("torus_bubble: option 'layout' must be \"ball\" or \"halves\", got 'half'",
              froth.torus_bubble, {layout = "half"})
T.check_error("torus_bubble: option 'r' must be a number", froth.torus_bubble, {r = "1"})
T.check_error("torus_bubble: unknown option 'radius'", froth.torus_bubble, {radius = 1})
T.check_error("torus_bubble: h = 0.001 gives about", froth.torus_bubble, {h = 0.001})
T.check_error("torus_bubble: sigma[5] names surface 5, but the cluster has 4 surfaces",
              froth.torus_bubble, {h = 0.5, sigma = {[5] = 2}})
T.check_error("triple_bubble: h must be positive, got 0", froth.triple_bubble, {h = 0})
T.check_error("triple_bubble: sigma must be positive, got -1", froth.triple_bubble, {h = 0.3, sigma = -1})
T.check_error("triple_bubble: expected an option table {...}, got number", froth.triple_bubble, 0.1)
T.check_error("triple_bubble: option keys must be names", froth.triple_bubble, {0.1})
T.check_error("quadruple_bubble: unknown option 'sigmas'", froth.quadruple_bubble, {sigmas = 1})
T.check_error("quadruple_bubble: h = 5 is larger than the cluster (extent 3); use h <= 3",
              froth.quadruple_bubble, {h = 5})

T.summary()
