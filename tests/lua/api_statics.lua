-- Statics: c:minimize, c:pressures, c:set_volume, c:target_volumes, c:refine, and volume-exact
-- surface diffusion (exact_volumes = true). Exact answers: the standard double bubble
-- (froth.measure.standard_double_bubble), spheres (pressure 2 / R), flat refinement.
local T = require("froth.test")
local M = require("froth.measure")
if not froth.has("gmsh") then
  T.assert_equal(froth.double_bubble, nil, "no double_bubble without gmsh")
  return T.summary()
end

local positions, same = T.positions, T.same_positions

-- minimize: equal double bubble, against the standard double bubble of its volumes.
local c = froth.double_bubble{h = 0.12}
local r = c:minimize{}
local V = c:volumes()
local exact = M.standard_double_bubble(V[1], V[2])
T.assert_true(r.converged, "equal double bubble converges", r.stop_reason)
T.assert_true(r.residual <= 1e-6, "residual <= tol", tostring(r.residual))
T.assert_true(r.volume_error <= 1e-12, "volumes exact to 1e-12", tostring(r.volume_error))
for b = 1, 2 do
  T.assert_true(T.rel(V[b], c:target_volumes()[b]) <= 1e-12, "body volume = target")
end
T.assert_true(T.rel(r.energy, exact.area) <= 2e-3, "area within 0.2% of the exact double bubble",
              ("%.6f vs %.6f"):format(r.energy, exact.area))
T.assert_true(r.energy >= exact.area * (1 - 1e-4), "an inscribed polyhedron's area is not below it much")
T.assert_true(T.rel(r.pressures[1], exact.p1) <= 0.01 and T.rel(r.pressures[2], exact.p2) <= 0.01,
              "pressures 2 / r within 1%", ("%.5f %.5f vs %.5f"):format(r.pressures[1], r.pressures[2], exact.p1))
local a = c:report().angles
T.assert_true(a.min >= 118 and a.max <= 122, "triple-line angles 118..122",
              ("%.2f .. %.2f"):format(a.min, a.max))
local p, res = c:pressures()
T.assert_near(p[1], r.pressures[1], 1e-12, "c:pressures() after minimize = its pressures")
T.assert_true(res <= 1e-6, "c:pressures() residual")

-- Unequal volumes by set_volume: the smaller bubble has the larger pressure, 2 / r1.
local u = froth.double_bubble{h = 0.12}
local v1 = u:volumes()[1]
u:set_volume(2, 2 * v1)
T.assert_near(u:target_volumes()[2], 2 * v1, 1e-15, "target_volumes after set_volume")
local ru = u:minimize{}
local eu = M.standard_double_bubble(v1, 2 * v1)
T.assert_true(ru.converged, "unequal double bubble converges", ru.stop_reason)
T.assert_true(T.rel(u:volumes()[2], 2 * v1) <= 1e-12, "body 2 reaches its target volume exactly")
T.assert_true(T.rel(ru.energy, eu.area) <= 2e-3, "unequal area within 0.2%",
              ("%.6f vs %.6f"):format(ru.energy, eu.area))
T.assert_true(T.rel(ru.pressures[1], eu.p1) <= 0.01 and T.rel(ru.pressures[2], eu.p2) <= 0.01,
              "unequal pressures 2 / r1, 2 / r2 within 1%",
              ("%.5f %.5f vs %.5f %.5f"):format(ru.pressures[1], ru.pressures[2], eu.p1, eu.p2))

-- Pressures converge at O(h^2) to 2 / R (R from the volume) on minimised spheres.
local errors = {}
for k, h in ipairs{0.3, 0.15} do
  local s = froth.sphere{R = 1, h = h}
  s:minimize{}
  local R = (3 * s:volumes()[1] / (4 * math.pi)) ^ (1 / 3)
  errors[k] = math.abs(s:pressures()[1] * R / 2 - 1)
end
T.assert_true(errors[2] < errors[1] / 2.5, "sphere pressure error falls like h^2",
              ("%.3e -> %.3e"):format(errors[1], errors[2]))

-- A drop on a plane becomes a half sphere meeting it at 90 degrees; the volume is held.
local d = froth.cube_on_plane{h = 0.15}
local vd = d:volumes()[1]
local rd = d:minimize{}
local R = (3 * vd / (2 * math.pi)) ^ (1 / 3)
T.assert_true(rd.converged and T.rel(d:volumes()[1], vd) <= 1e-12, "drop: converged, volume exact")
T.assert_true(T.rel(rd.energy, 2 * math.pi * R * R) <= 5e-3, "drop: area of the half sphere",
              ("%.5f vs %.5f"):format(rd.energy, 2 * math.pi * R * R))
local ca = d:report().contact_angles
T.assert_true(ca.min >= 88 and ca.max <= 92, "drop: contact angles 90 +- 2",
              ("%.2f .. %.2f"):format(ca.min, ca.max))

-- refine: facets x 4, vertices V + E, junctions kept, volumes unchanged (flat facets).
local f = froth.triple_bubble{h = 0.3}
local info, vols = f:info(), f:volumes()
local q = f:refine()
local after = f:info()
T.assert_equal(q.facets, 4 * info.facets, "refine: facets x 4")
T.assert_equal(after.facets, q.facets, "refine: info agrees")
T.assert_equal(after.triple_lines, info.triple_lines, "refine: triple lines kept")
T.assert_equal(after.quadruple_points, info.quadruple_points, "refine: quadruple points kept")
T.assert_true(q.volume_change <= 1e-12, "refine: volumes unchanged", tostring(q.volume_change))
for b = 1, #vols do T.assert_true(T.rel(f:volumes()[b], vols[b]) <= 1e-12, "refine: body volume") end
local w = froth.cube_on_plane{h = 0.3}
local vw = w:volumes()[1]
T.assert_true(w:refine().volume_change <= 1e-12 and T.rel(w:volumes()[1], vw) <= 1e-12,
              "refine on a plane: volume unchanged")
T.assert_true(w:report().wall_drift <= 1e-12, "refine on a plane: rim on the wall")
local sw = froth.drop_on_sphere_wall{h = 0.2}
local qs = sw:refine()
T.assert_true(sw:report().wall_drift <= 1e-9, "refine on a sphere wall: midpoints projected onto it")
T.assert_true(qs.volume_change > 0 and qs.volume_change < 1e-2, "refine on a sphere wall: volume change reported",
              tostring(qs.volume_change))

-- Volume-exact surface diffusion: every step exact to 1e-12, energy non-increasing for
-- tau = 1e-4 ... 10; the seed's scheme (default) loses volume.
for _, tau in ipairs{1e-4, 1e-2, 1, 10} do
  local s = froth.double_bubble{h = 0.25, split = 0.3}
  local V0 = s:volumes()
  local st = s:step{flow = "sd", tau = tau, exact_volumes = true}
  local V1 = s:volumes()
  T.assert_true(T.rel(V1[1], V0[1]) <= 1e-12 and T.rel(V1[2], V0[2]) <= 1e-12,
                ("exact sd tau = %g: volumes to 1e-12"):format(tau), st.volume_error)
  T.assert_true(st.energy <= st.energy_before, ("exact sd tau = %g: energy does not rise"):format(tau))
  T.assert_true(st.volume_iterations >= 2, "exact sd reports its solves")
end
local e = froth.double_bubble{h = 0.25, split = 0.3}
local E0 = e:volumes()
local re = e:evolve{flow = "sd", tau = 1e-3, steps = 100, exact_volumes = true, progress = false}
T.assert_true(T.rel(e:volumes()[1], E0[1]) <= 1e-10 and T.rel(e:volumes()[2], E0[2]) <= 1e-10,
              "exact sd: volumes to 1e-10 over 100 steps", tostring(re.volume_loss))
T.assert_true(re.max_energy_increase <= 0, "exact sd: energy non-increasing over 100 steps")
local l = froth.double_bubble{h = 0.25, split = 0.3}
local rl = l:evolve{flow = "sd", tau = 1e-3, steps = 100, exact_volumes = false, progress = false}
T.assert_true(rl.volume_loss > 1e-5, "the seed's scheme (exact_volumes = false) loses volume",
              tostring(rl.volume_loss))
local d0 = froth.double_bubble{h = 0.25, split = 0.3}
local sd = d0:step{flow = "sd", tau = 1e-3}
T.assert_true(sd.volume_iterations >= 2 and sd.volume_error <= 1e-12,
              "surface diffusion is volume-exact by default", tostring(sd.volume_error))

-- froth.box_cells: Evolver's box cells without gmsh; exact volumes, the junction counts of the
-- standard double and triple bubbles, and refine + minimize to the double bubble.
local cubes = froth.box_cells{x = {0, 1, 2}, y = {0, 1}, z = {0, 1}, cell = function(i) return i end}
T.assert_equal(T.counts(cubes), "3/1/0/2", "two cubes: 3 films, 1 triple line, 2 bodies")
T.assert_equal(cubes:info().vertices, 12 + 11, "two cubes: 12 corners and 11 face centres")
T.assert_true(cubes:volumes()[1] == 1 and cubes:volumes()[2] == 1, "two cubes: volumes 1 exactly")
T.assert_near(cubes:area(), 11, 1e-13, "two cubes: 11 unit faces")
local cells = froth.box_cells{x = {0, 1, 2}, y = {0, 1}, z = {0, 1, 1.5},
                              cell = function(i, _, k) return k == 1 and i or 3 end}
T.assert_equal(T.counts(cells), "6/4/2/3", "three cells: 6 films, 4 triple lines, 2 quadruple points")
cubes:refine(); cubes:refine()
local rc = cubes:minimize{tol = 1e-2}
T.assert_true(T.rel(rc.energy, 3 * (9 * math.pi) ^ (1 / 3)) <= 5e-3,
              "two cubes refined twice and minimised: the double bubble within 0.5%", tostring(rc.energy))
T.check_error("box_cells: x must be an array of at least 2 numbers", froth.box_cells,
              {x = {0}, y = {0, 1}, z = {0, 1}, cell = function() return 1 end})
T.check_error("box_cells: y must be increasing numbers, y[2] = 0", froth.box_cells,
              {x = {0, 1}, y = {0, 0}, z = {0, 1}, cell = function() return 1 end})
T.check_error("box_cells: cell(1, 1, 1) must be a body id >= 0, got -1", froth.box_cells,
              {x = {0, 1}, y = {0, 1}, z = {0, 1}, cell = function() return -1 end})
T.check_error("box_cells: body 1 has no cells", froth.box_cells,
              {x = {0, 1}, y = {0, 1}, z = {0, 1}, cell = function() return 2 end})
T.check_error("box_cells: cell must be a function", froth.box_cells, {x = {0, 1}, y = {0, 1}, z = {0, 1}})

-- Bad input: a Lua error naming the value; the cluster unchanged.
local b = froth.double_bubble{h = 0.3}
local X = positions(b)
T.check_error("minimize: tol", b.minimize, b, {tol = -1})
T.check_error("unknown option 'tolerance'", b.minimize, b, {tolerance = 1})
T.check_error("minimize: expected an option table", b.minimize, b, "fast")
T.check_error("max_iterations", b.minimize, b, {max_iterations = 0})
T.check_error("body 3", b.set_volume, b, 3, 1)
local film = froth.cluster{vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
                           surfaces = {{{1, 3, 2}, {1, 2, 4}, {2, 3, 4}, {3, 1, 4}}}}
T.check_error("set_volume: the cluster has no bodies", film.set_volume, film, 1, 1)
T.check_error("must be positive and finite, got -1", b.set_volume, b, 1, -1)
T.check_error("must be positive and finite, got nan", b.set_volume, b, 1, 0 / 0)
T.check_error("expected a volume", b.set_volume, b, 1, "big")
T.check_error("exact_volumes", b.step, b, {flow = "sd", tau = 1e-3, exact_volumes = "yes"})
T.assert_true(same(b, X), "positions unchanged after the errors")
T.assert_true(b:target_volumes()[1] == b:volumes()[1], "targets unchanged after the errors")
-- A mesh that starts with a sliver (a facet angle below minimize's 1-degree collapse limit, as
-- transitions leave them) is not a collapsing one: minimize stops only if the smallest angle
-- halves. A film vertex moved 98.5% of the way to its neighbour makes a 0.7-degree facet.
local sl = froth.double_bubble{h = 0.2}
local v = sl:vertices{where = function(x) return not x.triple_line end}[1].id
local edge = sl:edges{where = function(e) return e.vertices[1] == v or e.vertices[2] == v end}[1]
local w = edge.vertices[1] == v and edge.vertices[2] or edge.vertices[1]
local xv, xw = sl:vertex(v), sl:vertex(w)
sl:set_vertex(v, {xw[1] + 0.015 * (xv[1] - xw[1]), xw[2] + 0.015 * (xv[2] - xw[2]),
                  xw[3] + 0.015 * (xv[3] - xw[3])})
local rs = sl:minimize{}
T.assert_equal(rs.stop_reason, "converged", "a sliver at the start does not stop minimize",
               rs.stop_reason)

-- With transitions, a cluster that needs none minimises as without: one round, no events.
local plain, with = froth.double_bubble{h = 0.25}, froth.double_bubble{h = 0.25}
local rp, rw = plain:minimize{}, with:minimize{transitions = true}
T.assert_equal(rw.rounds, 1, "one round")
T.assert_equal(#rw.events, 0, "no transitions")
T.assert_equal(rw.iterations, rp.iterations, "the same iterations")
T.assert_near(rw.energy, rp.energy, 1e-14 * rp.energy, "the same energy")
T.assert_equal(rp.events, nil, "without transitions no events field")
T.check_error("minimize: option 'min_line_fraction' must lie in (0, 1)", with.minimize, with,
              {transitions = true, min_line_fraction = 2})

-- settle: with a tol no mesh reaches, minimize stops once the energy has stopped falling (by at
-- most settle |E| over settle_window steps), not at max_iterations; the energy is that of the
-- converged state, and the next steps lower it by less than the window did.
local conv = froth.double_bubble{h = 0.3}
local rconv = conv:minimize{}
for _, transitions in ipairs{false, true} do
  local st = froth.double_bubble{h = 0.3}
  local rst = st:minimize{tol = 1e-300, settle = 1e-11, settle_window = 5, max_iterations = 500,
                          transitions = transitions}
  local what = transitions and " (with transitions)" or ""
  T.assert_true(rst.stop_reason:find("^settled: the energy changed by .* in the last 5 steps$") ~= nil,
                "settle stops minimize" .. what, rst.stop_reason)
  T.assert_true(not rst.converged and rst.iterations < 500, "settled is not converged, before max_iterations" .. what,
                rst.iterations)
  T.assert_true(T.rel(rst.energy, rconv.energy) <= 1e-9, "settled at the converged energy" .. what,
                ("%.15g vs %.15g"):format(rst.energy, rconv.energy))
  local next5 = st:minimize{tol = 1e-300, max_iterations = 5}
  T.assert_true((rst.energy - next5.energy) / rst.energy <= 1e-11, "five more steps gain less than settle" .. what,
                tostring(rst.energy - next5.energy))
end
-- hessian: Newton's steps near the equilibrium reach the same double bubble (the area within
-- 1e-5: the normal steps keep the mesh's tangential layout) in fewer steps; an anisotropic
-- cluster takes none and minimises as without.
local hb = froth.double_bubble{h = 0.2}
local rh = hb:minimize{hessian = true}
local pb = froth.double_bubble{h = 0.2}
local rpb = pb:minimize{}
T.assert_true(rh.converged and rh.hessian_steps > 0 and rh.iterations < rpb.iterations,
              "hessian: converged, with Newton's steps, in fewer steps",
              rh.iterations .. " (" .. rh.hessian_steps .. ") vs " .. rpb.iterations)
T.assert_true(T.rel(rh.energy, rpb.energy) <= 1e-5, "hessian: the same area within 1e-5",
              ("%.10f vs %.10f"):format(rh.energy, rpb.energy))
T.assert_true(rh.volume_error <= 1e-12 and T.rel(rh.pressures[1], rpb.pressures[1]) <= 1e-4,
              "hessian: volumes exact, the same pressures", tostring(rh.pressures[1]))
local ab, ab2 = froth.double_bubble{h = 0.3}, froth.double_bubble{h = 0.3}
for _, x in ipairs{ab, ab2} do x:set_anisotropy("all", froth.anisotropies.ellipsoidal{1, 1, 1.44}) end
local ra, ra2 = ab:minimize{hessian = true, max_iterations = 30}, ab2:minimize{max_iterations = 30}
T.assert_equal(ra.hessian_steps, 0, "hessian: none for an anisotropic cluster")
T.assert_near(ra.energy, ra2.energy, 0, "hessian: an anisotropic cluster minimises as without")
T.check_error("minimize: settle must be 0 or positive and finite, got -1", with.minimize, with, {settle = -1})
T.check_error("minimize: hessian_below must be positive and finite, got 0", with.minimize, with,
              {hessian = true, hessian_below = 0})
T.check_error("minimize: option 'hessian' must be true or false", with.minimize, with, {hessian = 1})
T.check_error("minimize: settle_window must be at least 1, got 0", with.minimize, with, {settle_window = 0})
T.summary()
