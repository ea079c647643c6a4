-- Films spanning wires: a free boundary edge between two fixed vertices on no wall is a wire
-- (Evolver's fixed edges), so a film need not enclose a body. Exact answer: the catenoid
-- between two coaxial unit rings at z = -z0, z0, r(z) = a cosh(z / a) with a cosh(z0 / a) = 1
-- (the larger root, the stable one) and area 2 pi a z0 + pi a^2 sinh(2 z0 / a). The rings are
-- regular K-gons (chords), so the discrete area converges as K^-2.
local T = require("froth.test")

--- A tube of radius 1 from z = -z0 to z0: K vertices a ring, M + 1 rings (alternate rings
--- turned by half a step), the end rings fixed. Also returns the ids of the end rings.
local function tube(K, M, z0, bump)
  local V, F, fixed = {}, {}, {}
  local function id(i, j) return j * K + (i % K) + 1 end
  for j = 0, M do
    for i = 0, K - 1 do
      local t = 2 * math.pi * (i + 0.5 * (j % 2)) / K
      local z = -z0 + 2 * z0 * j / M
      local r = 1 + (bump or 0) * math.cos(math.pi * z / (2 * z0)) * math.cos(3 * t)
      V[#V + 1] = {r * math.cos(t), r * math.sin(t), z}
      if j == 0 or j == M then fixed[#fixed + 1] = #V end
    end
  end
  for j = 0, M - 1 do
    for i = 0, K - 1 do
      if j % 2 == 0 then
        F[#F + 1] = {id(i, j), id(i + 1, j), id(i, j + 1)}
        F[#F + 1] = {id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)}
      else
        F[#F + 1] = {id(i, j), id(i + 1, j + 1), id(i, j + 1)}
        F[#F + 1] = {id(i, j), id(i + 1, j), id(i + 1, j + 1)}
      end
    end
  end
  return {vertices = V, surfaces = {F}, fixed = fixed}, fixed
end

local z0 = 0.5
local a = 0.85
for _ = 1, 50 do a = a - (a * math.cosh(z0 / a) - 1) / (math.cosh(z0 / a) - z0 / a * math.sinh(z0 / a)) end
local exact = 2 * math.pi * a * z0 + math.pi * a * a * math.sinh(2 * z0 / a)

local function waist(c)
  local w = math.huge
  for _, v in ipairs(c:vertices{where = function(v) return math.abs(v.x[3]) < 1e-12 end}) do
    w = math.min(w, math.sqrt(v.x[1] ^ 2 + v.x[2] ^ 2))
  end
  return w
end

local errors = {}
for k, KM in ipairs{{24, 8}, {48, 16}} do
  local spec, rings = tube(KM[1], KM[2], z0)
  local c = froth.cluster(spec)
  T.assert_equal(c:info().bodies, 0, "a film without bodies")
  local X = T.positions(c)
  local r = c:minimize{tol = 1e-6}
  T.assert_true(r.converged, "catenoid: minimize converges", r.stop_reason)
  for _, v in ipairs(rings) do
    local x = c:vertex(v)
    T.assert_true(x[1] == X[v][1] and x[2] == X[v][2] and x[3] == X[v][3], "the rings stay put")
  end
  errors[k] = (c:area() - exact) / exact
  print(("catenoid K = %d: %d vertices, %d iterations, area %.10f (exact %.10f, error %.2e), waist %.5f (a = %.5f)")
        :format(KM[1], c:info().vertices, r.iterations, c:area(), exact, errors[k], waist(c), a))
  T.assert_true(math.abs(errors[k]) < 2e-3 / k ^ 2, "catenoid area within the K^-2 chord error",
                tostring(errors[k]))
  T.assert_true(math.abs(waist(c) - a) < 1e-2 / k ^ 2, "catenoid waist radius a", tostring(waist(c)))
end
T.assert_true(math.abs(errors[1] / errors[2]) > 3.5, "second order in 1/K",
              tostring(errors[1] / errors[2]))

-- Refine keeps the wire: each ring edge's midpoint is fixed on its chord, so the refined film
-- spans the same 24-gons (froth has no parametric wires yet to put it on the circle). The
-- unrefined film is a film of the refined mesh too, so the minimum can only be lower.
local c = froth.cluster((tube(24, 8, z0)))
c:minimize{tol = 1e-6}
local rings, coarse = #c:fixed(), c:area()
c:refine()
T.assert_equal(#c:fixed(), 2 * rings, "refine: each ring edge's midpoint is fixed")
T.assert_near(c:area(), coarse, 1e-12 * coarse, "refine alone keeps the area")
c:minimize{tol = 1e-6, tau_start = 1e4}
T.assert_true(c:area() < coarse, "the refined film on the same polygons has a lower area",
              c:area() .. " vs " .. coarse)

-- Edge records say which free edges are wires; a wire film written as MSH reads back with
-- its fixed vertices given (MSH has no place for them).
local film = froth.cluster((tube(24, 8, z0)))
T.assert_equal(#film:edges{where = function(e) return e.wire end}, 48, "48 wire edges (two 24-gons)")
T.assert_equal(#film:edges{where = function(e) return e.boundary and not e.wire end}, 0, "no wall edges")
local path = T.temp_path(".msh")
film:write(path)
T.check_error("no wall is attached", froth.read, path)
local back = froth.read(path, {fixed = film:fixed()})
os.remove(path)
T.assert_equal(#back:fixed(), 48, "read back with its fixed vertices")
T.assert_near(back:area(), film:area(), 1e-12 * film:area(), "the same film")

-- The flows on a wire: MCF falls to the catenoid, SD of a bumpy tube lowers the energy with
-- the rings held.
local flat = froth.cluster((tube(24, 8, z0)))
local E = flat:energy()
flat:evolve{flow = "mcf", tau = 1e-2, steps = 40, progress = false}
T.assert_true(flat:energy() < E and math.abs(flat:energy() - exact) < 2e-3 * exact,
              "MCF on a wire reaches the catenoid", tostring(flat:energy()))
local bumpy = froth.cluster((tube(24, 8, z0, 0.1)))
X = T.positions(bumpy)
E = bumpy:energy()
local rose = false
bumpy:evolve{flow = "sd", tau = 1e-3, steps = 10, progress = false, on_step = function(s)
  rose = rose or s.energy > s.energy_before * (1 + 1e-13)
end}
T.assert_true(bumpy:energy() < E and not rose, "SD on a wire lowers the energy every step",
              bumpy:energy() .. " vs " .. E)
for _, v in ipairs(bumpy:fixed()) do
  local x = bumpy:vertex(v)
  T.assert_true(x[1] == X[v][1] and x[2] == X[v][2] and x[3] == X[v][3], "SD holds the rings")
end

-- Errors: a free edge with one end free, unfixing a wire vertex, a wire around a body.
local open = tube(24, 8, z0)
open.fixed = {table.unpack(open.fixed, 1, 24)} -- the bottom ring only
T.check_error("is a free boundary edge (in one facet only) and no wall is attached; close the surface, "
              .. "give walls (froth.plane, ...) or fix both its vertices (a wire)", froth.cluster, open)
local w = froth.cluster((tube(24, 8, z0)))
T.check_error("unfix: vertex 1 ends the free boundary edge", w.unfix, w, {1})
T.assert_equal(#w:fixed(), 48, "a refused unfix changes nothing")

-- A body whose films end on wires (Evolver's catbody.fe). Without volconst its volume is what
-- the band and flat lids over the rings enclose; the divergence theorem with the field (x, 0, 0),
-- which the horizontal lids do not feel, gives it from the band alone. With volconst it is
-- Evolver's: z dx dy over the band plus the constant. Each sum is over the band's facets
-- (mean coordinate times the area vector's component), oriented out of the body.
local function band_integrals(c)
  local X, sx, sz = T.positions(c), 0, 0
  for _, f in ipairs(c:facets()) do
    local a, b, d = X[f.vertices[1]], X[f.vertices[2]], X[f.vertices[3]]
    local u, w = {b[1] - a[1], b[2] - a[2], b[3] - a[3]}, {d[1] - a[1], d[2] - a[2], d[3] - a[3]}
    local n = {0.5 * (u[2] * w[3] - u[3] * w[2]), 0.5 * (u[3] * w[1] - u[1] * w[3]), 0.5 * (u[1] * w[2] - u[2] * w[1])}
    sx = sx + (a[1] + b[1] + d[1]) / 3 * n[1]
    sz = sz + (a[3] + b[3] + d[3]) / 3 * n[3]
  end
  local sign = sx < 0 and -1 or 1 -- the body's orientation of the surface
  return sign * sx, sign * sz
end
local body = tube(24, 8, z0, 0.1)
body.bodies = {{1}}
local closed = froth.cluster(body)
local enclosed = band_integrals(closed)
T.assert_near(closed:volumes()[1], enclosed, 1e-12, "wire lids: the volume the band and the flat lids enclose")
body.bodies = {{1, volconst = 2 * math.pi * z0}}
local ev = froth.cluster(body)
local _, z_content = band_integrals(ev)
T.assert_near(ev:volumes()[1], z_content + 2 * math.pi * z0, 1e-12, "volconst: Evolver's z dx dy over the band plus volconst")
T.assert_true(math.abs(ev:volumes()[1] - closed:volumes()[1]) > 1e-3, "volconst: not the enclosed volume")
ev:refine()
_, z_content = band_integrals(ev)
T.assert_near(ev:volumes()[1], z_content + 2 * math.pi * z0, 1e-12, "volconst: Evolver's volume after refine")
ev:set_volume(1, 1.5)
local r = ev:minimize{max_iterations = 200}
T.assert_near(ev:volumes()[1], 1.5, 1e-12, "volconst: minimize holds Evolver's volume")
local file = T.temp_path(".froth")
ev:save(file)
local back = froth.load(file)
os.remove(file)
T.assert_equal(back:volumes()[1], ev:volumes()[1], "volconst: save and load keep the body's convention")
-- Below the stable catenoid's volume (about 2.6 here) the film bows in: negative pressure.
T.assert_true(ev:pressures()[1] < 0, "volconst: the pressure below the catenoid's volume is negative", ev:pressures()[1])
-- On a wall the same: a pyramid on the plane z = 0.3 (its lid faces down). The x field does not
-- see the flat lid, so the band integral is the enclosed volume; with volconst the lid counts
-- nothing and the volume is z dx dy over the films plus the constant (Evolver without content).
local function pyramid(volconst)
  return {vertices = {{-1, -1, 0.3}, {1, -1, 0.3}, {1, 1, 0.3}, {-1, 1, 0.3}, {0.1, 0.2, 1.3}},
          surfaces = {{{1, 2, 5}, {2, 3, 5}, {3, 4, 5}, {4, 1, 5}}},
          bodies = {{1, volconst = volconst}}, walls = froth.plane{normal = {0, 0, 1}, offset = 0.3}}
end
local tent = froth.cluster(pyramid())
T.assert_near(tent:volumes()[1], 4 / 3, 1e-14, "a pyramid on a plane: base 4 times height 1 over 3")
T.assert_near(tent:volumes()[1], (band_integrals(tent)), 1e-14, "the x-field integral over its films")
local ev_tent = froth.cluster(pyramid(0.25))
_, z_content = band_integrals(ev_tent)
T.assert_near(ev_tent:volumes()[1], z_content + 0.25, 1e-14, "volconst on a wall: z dx dy over the films plus volconst")
T.assert_near(ev_tent:volumes()[1], 4 / 3 + 0.3 * 4 + 0.25, 1e-14, "volconst on a wall: the enclosed volume plus the lid's 0.3 * 4")
body.bodies = {{1, volconst = "x"}}
T.check_error("cluster: bodies[1].volconst must be a number, got string", froth.cluster, body)
body.bodies = {{1, volconst = math.huge}}
T.check_error("cluster: body 1: volconst must be a finite number, got inf", froth.cluster, body)
-- A body whose film lies in its own lid encloses nothing.
T.check_error("cluster: body 1 encloses no volume", froth.cluster,
              {vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, surfaces = {{{1, 2, 3}}}, bodies = {{1}}, fixed = {1, 2, 3}})

-- Wire curves: the rings given as curves keep refined midpoints on the circles, so the refined
-- film converges to the catenoid between the circles (without curves it keeps the 8-gons).
local function with_rings(K, M)
  local spec = tube(K, M, z0)
  local lower, upper = {vertices = {}, parameters = {}}, {vertices = {}, parameters = {}}
  for i = 0, K - 1 do
    table.insert(lower.vertices, i + 1)
    table.insert(lower.parameters, 2 * math.pi * i / K)
    table.insert(upper.vertices, M * K + i + 1)
    table.insert(upper.parameters, 2 * math.pi * (i + 0.5 * (M % 2)) / K)
  end
  lower.x = function(p) return math.cos(p), math.sin(p), -z0 end
  upper.x = function(p) return math.cos(p), math.sin(p), z0 end
  lower.name, upper.name = "lower ring", "upper ring"
  spec.curves = {lower, upper}
  return spec
end
local on_curves, chords = froth.cluster(with_rings(8, 4)), froth.cluster(tube(8, 4, z0))
for _ = 1, 2 do on_curves:refine(); chords:refine() end
on_curves:minimize{}
chords:minimize{}
T.assert_true(math.abs(on_curves:area() / exact - 1) < 0.2 * math.abs(chords:area() / exact - 1),
              "curves: the refined film is far closer to the catenoid than the polygon's",
              on_curves:area() .. " / " .. chords:area() .. " / " .. exact)
local bad = with_rings(8, 4)
bad.curves[1].parameters[1] = 0.1
T.check_error("cluster: vertex 1 on curve 'lower ring' is at distance", froth.cluster, bad)
bad = with_rings(8, 4)
bad.fixed = nil
T.check_error("cluster: vertex 1 on curve 'lower ring' must be fixed", froth.cluster, bad)
bad = with_rings(8, 4)
bad.curves[1].x = 1
T.check_error("cluster: curves[1]: option 'x' must be a function p -> x, y, z", froth.cluster, bad)
bad = with_rings(8, 4)
bad.curves[1].parameters = {0}
T.check_error("option 'parameters' must be an array of one number per vertex", froth.cluster, bad)
bad = with_rings(8, 4)
bad.curves[2].vertices[1] = 1
T.check_error("cluster: vertex 1 on curve 'upper ring' is on two curves", froth.cluster, bad)
T.summary()
