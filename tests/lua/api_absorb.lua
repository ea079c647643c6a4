-- c:absorb_body and evolve's absorb of a vanishing cell that cannot pop (issue 15 item 4): the
-- films between the cell and a neighbour go and its other films become the neighbour's. No
-- vertex moves, so the neighbour's volume becomes exactly the sum of the two and the energy
-- falls by exactly the area of the films that went (equal tensions).
local T = require("froth.test")

--- The area of the films between bodies a and b.
local function shared_area(c, a, b)
  local on_a, area = {}, 0
  for _, s in ipairs(c:bodies()[a]) do on_a[math.abs(s)] = true end
  for _, s in ipairs(c:bodies()[b]) do
    if on_a[math.abs(s)] then area = area + c:area(math.abs(s)) end
  end
  return area
end

-- 1. Three unit cubes in a row (exact volumes): the middle one joins the neighbour it names.
local function row(n)
  local x = {}
  for i = 0, n do x[#x + 1] = i end
  return froth.box_cells{x = x, y = {0, 1}, z = {0, 1}, cell = function(i) return i end}
end
local c = row(3)
local E0 = c:energy()
T.assert_near(E0, 16, 1e-12, "three cubes in a row: 14 outer unit faces, 2 between")
local r = c:absorb_body(2, 3)
T.assert_equal(r.body, 2, "the body that went")
T.assert_equal(r.into, 2, "body 3 is body 2 now (ids after the absorbed one move down)")
T.assert_equal(r.neighbours, 3, "body 1, body 3 and the outside")
T.assert_near(r.energy_before - r.energy_after, 1, 1e-12, "the energy falls by the shared face")
T.assert_near(c:energy(), 15, 1e-12, "a unit cube and a 2 x 1 x 1 box with a face between them")
T.assert_equal(c:info().bodies, 2, "two bodies left")
T.assert_near(c:volumes()[1], 1, 1e-12, "body 1 keeps its volume")
T.assert_near(c:volumes()[2], 2, 1e-12, "the joined body's volume is the sum")
T.assert_near(c:target_volumes()[2], 2, 1e-12, "its target too")
-- the outside films of the two cubes joined into one across the face that went
T.assert_equal(c:info().surfaces, 3, "outer film of body 1, of the joined body, the face between")
T.assert_true(r.where:find("body 2 (volume 1, 3 neighbouring cells) joined body 3", 1, true) ~= nil,
              "where names both", r.where)
-- the joined box relaxes like any cluster: SD holds both volumes
c:evolve{flow = "sd", tau = 1e-3, steps = 3, progress = false}
T.assert_near(c:volumes()[2], 2, 1e-9, "SD holds the joined volume after")

-- Without `into`, the body joins the one it shares the most film with: body 1 is a 1 x 1 x 2
-- column, body 2 a unit cube beside its lower half (shared area 1), body 3 the rest of the
-- 2 x 2 x 2 block (shared area 3).
local block = froth.box_cells{x = {0, 1, 2}, y = {0, 1, 2}, z = {0, 1, 2}, cell = function(i, j, k)
  return (i == 1 and j == 1) and 1 or (i == 2 and j == 1 and k == 1) and 2 or 3
end}
T.assert_near(shared_area(block, 1, 2), 1, 1e-12, "body 1 | body 2")
T.assert_near(shared_area(block, 1, 3), 3, 1e-12, "body 1 | body 3")
local rb = block:absorb_body(1)
T.assert_equal(rb.into, 2, "body 3 (2 now), the larger contact")
T.assert_near(rb.energy_before - rb.energy_after, 3, 1e-12, "its three faces went")
T.assert_near(block:volumes()[2], 7, 1e-12, "2 + 5")

-- 2. Errors change nothing.
local e = row(3)
local X = T.positions(e)
T.check_error("absorb_body: body 1 does not meet body 3", e.absorb_body, e, 1, 3)
T.check_error("absorb_body: body 2: body 2 cannot absorb it (not another body of the cluster)",
              e.absorb_body, e, 2, 2)
T.check_error("body 4 does not exist (the cluster has bodies 1..3)", e.absorb_body, e, 4)
T.assert_true(T.same_positions(e, X) and e:info().bodies == 3, "failed absorbs change nothing")
local one = row(1)
T.check_error("absorb_body: body 1 does not meet another body", one.absorb_body, one, 1)
local dome = froth.half_ellipsoid_on_plane{levels = 2}
T.check_error("absorb_body: body 1 meets walls or wires; only a cell bounded by films alone " ..
              "can be absorbed", dome.absorb_body, dome, 1)

if not froth.has("gmsh") or not froth.has("cgal") then
  T.assert_true(true, "skipped the foams: no gmsh or CGAL")
  return T.summary()
end

-- 3. A triple bubble loses a bubble and is a double bubble: its two quadruple points become
-- points of one closed triple line.
local tb = froth.triple_bubble{h = 0.3}
local V = tb:volumes()
local best, best_area = 2, shared_area(tb, 1, 2)
if shared_area(tb, 1, 3) > best_area then best, best_area = 3, shared_area(tb, 1, 3) end
local rt = tb:absorb_body(1)
T.assert_equal(rt.into, best - 1, "into the bubble it shares the most film with")
T.assert_near(rt.energy_before - rt.energy_after, best_area, 1e-12 * rt.energy_before,
              "the energy falls by the film that went")
T.assert_near(tb:volumes()[best - 1], V[1] + V[best], 1e-12 * V[best], "volumes add exactly")
T.assert_equal(#tb:quadruple_points(), 0, "no quadruple point is left")
T.assert_equal(#tb:triple_lines(), 1, "one closed triple line")
T.assert_true(tb:triple_lines()[1].closed, "closed")
T.assert_equal(tb:info().surfaces, 3, "a double bubble's three films")

-- 4. In a periodic grain network a cell with many neighbours joins one; MCF goes on.
local foam = froth.foam{n = 27, seed = 2, h = 0.4, lloyd = 5, equal_volumes = false}
local Vf, n0 = foam:volumes(), foam:info().bodies
local rf = foam:absorb_body(5)
T.assert_true(rf.neighbours > 4, "a Voronoi cell has many neighbours", tostring(rf.neighbours))
local partner = rf.into >= 5 and rf.into + 1 or rf.into -- its id before
T.assert_near(foam:volumes()[rf.into], Vf[5] + Vf[partner], 1e-12 * Vf[partner],
              "volumes add exactly across the box")
local total = 0
for _, v in ipairs(foam:volumes()) do total = total + v end
local total0 = 0
for _, v in ipairs(Vf) do total0 = total0 + v end
T.assert_near(total, total0, 1e-12 * total0, "the cells still fill the box")
local rm = foam:evolve{flow = "mcf", tau = 2e-3, steps = 10, progress = false}
T.assert_equal(rm.stop_reason, "steps done", "MCF runs on", rm.stop_reason)

-- 5. evolve: a vanishing cell with more than four neighbours joins one. With
-- min_volume_fraction = 0.999 every grain that shrinks in the first step is vanishing at once.
local g = froth.foam{n = 27, seed = 2, h = 0.4, lloyd = 5, equal_volumes = false}
local rs = g:clone():evolve{flow = "mcf", tau = 2e-3, steps = 3, progress = false,
                            transitions = false, watch = {min_volume_fraction = 0.999}}
T.assert_equal(rs.event and rs.event.kind, "vanishing body", "without transitions it stops")
local rg = g:evolve{flow = "mcf", tau = 2e-3, steps = 3, progress = false,
                    watch = {min_volume_fraction = 0.999}}
local absorbed = 0
for _, ev in ipairs(rg.events) do
  if ev.kind == "absorb body" then
    absorbed = absorbed + 1
    T.assert_true(ev.neighbours > 4, "it had too many neighbours to pop", tostring(ev.neighbours))
    T.assert_true(ev.into ~= ev.body and ev.into >= 1 and ev.into <= n0, "into another body")
    T.assert_true(ev.energy_after < ev.energy_before, "the energy falls", ev.where)
  end
end
T.assert_true(absorbed > 0, "some grains joined a neighbour", tostring(absorbed))
T.assert_equal(g:info().bodies, n0 - absorbed, "one body less for each")
T.assert_equal(rg.stop_reason, "steps done", "and the run went on", rg.stop_reason)

-- 6. evolve: a cell below the mesh's resolution beside a defect the upkeep cannot mend joins a
-- neighbour (grain networks tangle there: the 200-grain network stopped at t = 1.540 beside a
-- grain of 11 faces and 2.7 mean edges cubed). Box cells: two slabs below (bodies 1 and 3, split
-- at x = 1.2), two above (4 and 5, split at y = 1.2), and between them at (1..1.1)^2 a cell 0.004
-- thick, body 2 (volume 4e-5: far below a ball of the mean edge, 0.44, and a tenth of the mean
-- cell). In its floor (film 1|2, which stays) the centre vertex is pulled to 0.0005 from a corner
-- and both are fixed: a collapsing edge no upkeep can mend.
local function thin_cell()
  return froth.box_cells{x = {0, 1, 1.1, 1.2, 2.2}, y = {0, 1, 1.1, 1.2, 2.2}, z = {0, 1, 1.004, 2.004},
                         cell = function(i, j, k)
                           if k == 1 then return i <= 3 and 1 or 3 end
                           if k == 2 and i == 2 and j == 2 then return 2 end
                           return j <= 3 and 4 or 5
                         end}
end
--- Pulls the film vertex at (cx, cy, cz) to `to` and fixes it and the vertex at `at`.
local function short_fixed_edge(c, centre, at, to)
  local ids = {}
  for _, v in ipairs(c:vertices()) do
    local x = v.x
    local function near(p) return math.abs(x[1] - p[1]) + math.abs(x[2] - p[2]) + math.abs(x[3] - p[3]) < 1e-12 end
    if near(centre) then ids.centre = v.id elseif near(at) then ids.at = v.id end
  end
  c:set_vertex(ids.centre, to)
  c:fix({ids.centre, ids.at})
end
local near = thin_cell()
T.assert_equal(#near:quadruple_points(), 5, "a network: quadruple points where the slabs' films meet")
T.assert_near(near:volumes()[2], 4e-5, 1e-15, "body 2 is 0.1 x 0.1 x 0.004")
short_fixed_edge(near, {1.05, 1.05, 1}, {1, 1, 1}, {1.0004, 1.0003, 1})
local stopped = near:clone():evolve{flow = "mcf", tau = 1e-3, steps = 2, progress = false, transitions = false}
T.assert_equal(stopped.event and stopped.event.kind, "collapsing edge", "without transitions the edge stops the run")
local rn = near:evolve{flow = "mcf", tau = 1e-3, steps = 2, progress = false}
T.assert_equal(rn.stop_reason, "steps done", "with them the run goes on", rn.stop_reason)
T.assert_equal(#rn.events, 1, "through one transition")
local ev = rn.events[1]
T.assert_equal(ev.kind, "absorb body", "the thin cell joins a neighbour", ev.where)
T.assert_true(ev.where:find("below the mesh's resolution", 1, true) ~= nil, "the event says why", ev.where)
T.assert_equal(ev.body, 2, "body 2")
T.assert_equal(ev.into, 4, "the one it shares the most film with: its roof and walls")
T.assert_true(ev.energy_after < ev.energy_before, "the energy falls", ev.where)
T.assert_equal(near:info().bodies, 4, "one body less")
T.assert_equal(rn.deferred, 2, "the fixed edge itself is left to later steps")
-- the same edge far from it (1.5 away, in film 1|3 near the box's corner): no cell goes
local far = thin_cell()
short_fixed_edge(far, {1.2, 1.7, 0.5}, {1.2, 2.2, 0}, {1.2, 2.1996, 0.0003})
local rf = far:evolve{flow = "mcf", tau = 1e-3, steps = 2, progress = false}
T.assert_equal(rf.stop_reason, "steps done", "the run goes on", rf.stop_reason)
T.assert_equal(#rf.events, 0, "no transition")
T.assert_equal(far:info().bodies, 5, "the thin cell stays")
T.assert_equal(rf.deferred, 2, "the edge is left to later steps")

-- 7. absorb_body refuses where a fixed vertex would go with the films (nothing changed).
local pinned = thin_cell()
local roof = {}
for _, f in ipairs(pinned:facets{where = function(f) return f.bodies[1] == 2 or f.bodies[2] == 2 end}) do
  if f.bodies[1] == 4 or f.bodies[2] == 4 then
    for _, v in ipairs(f.vertices) do if pinned:vertex(v)[3] > 1.002 then roof[#roof + 1] = v end end
  end
end
pinned:fix(roof)
local nv = pinned:info().vertices
local ok, err = pcall(function() return pinned:absorb_body(2, 4) end)
T.assert_true(not ok, "refused")
T.assert_true(tostring(err):find("fixed or on a wall or wire, lies inside the films that would go", 1, true) ~= nil,
              "the message says why", tostring(err))
T.assert_equal(pinned:info().vertices, nv, "nothing changed")

T.summary()
