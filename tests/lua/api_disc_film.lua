-- c:collapse_disc_film: a film bounded by one closed triple line (a contact of two cells
-- through a hole in a third's films; grain networks leave them after a T1 of a cell that meets
-- itself, and the 27-grain network of seed 3 stopped at t = 0.748 on one of perimeter 0.003)
-- goes. Built with box_cells: body 1 below (z in 0..1), above it a thin column, body 2, inside
-- a ring, body 3. Films: the disc 1|2 (the column's foot, 0.2 x 0.2), 1|3 (the ring's floor),
-- 2|3 (the column's walls); the disc's border is a closed line of cells 1, 2, 3.
local T = require("froth.test")

local function column(refinements)
  local c = froth.box_cells{x = {0, 1, 1.2, 2.2}, y = {0, 1, 1.2, 2.2}, z = {0, 1, 2},
                            cell = function(i, j, k)
                              if k == 1 then return 1 end
                              return (i == 2 and j == 2) and 2 or 3
                            end}
  for _ = 1, refinements or 0 do c:refine() end
  return c
end

--- The surface between bodies a and b, or nil.
local function film_between(c, a, b)
  local of = {}
  for _, s in ipairs(c:bodies()[a]) do of[math.abs(s)] = true end
  for _, s in ipairs(c:bodies()[b]) do if of[math.abs(s)] then return math.abs(s) end end
  return nil
end

local function closed_lines(c)
  local n = 0
  for _, l in ipairs(c:triple_lines()) do if l.closed then n = n + 1 end end
  return n
end

local function total(v) local s = 0 for _, x in ipairs(v) do s = s + x end return s end

-- 1. The loop collapses: unrefined, the loop has 4 edges and each face a centre vertex.
local c = column()
local disc = film_between(c, 1, 2)
T.assert_true(disc ~= nil, "the column's foot is a film of bodies 1 and 2")
local info, lines, E0, V0 = c:info(), closed_lines(c), c:energy(), total(c:volumes())
T.assert_equal(lines, 3, "three closed lines: the disc's border and two rims")

local r = c:collapse_disc_film(disc)
T.assert_equal(r.surface, disc, "the result names the film")
T.assert_true(r.where:find("^disc film ") ~= nil and r.where:find("body 3 closes between them") ~= nil
              and not r.where:find("caps"), "the event says which cell closes the gap", r.where)
T.assert_equal(c:info().surfaces, info.surfaces - 1, "the disc goes")
T.assert_equal(closed_lines(c), lines - 1, "its border goes")
T.assert_true(film_between(c, 1, 2) == nil, "bodies 1 and 2 no longer touch")
T.assert_true(film_between(c, 1, 3) ~= nil and film_between(c, 2, 3) ~= nil, "body 3 touches both")
-- the new points: the last two vertices, in film 1|3 towards body 1 and in 2|3 towards body 2,
-- on the disc's axis, the loop's length over pi (0.8 / pi) apart
local n = c:info().vertices
local a, b = c:vertex(n - 1), c:vertex(n)
local below = r.cells[1] == 1 and a or b
local above = r.cells[1] == 1 and b or a
T.assert_near(below[3], 1 - 0.4 / math.pi, 1e-12, "the point in 1|3 lies below the disc, into body 1")
T.assert_near(above[3], 1 + 0.4 / math.pi, 1e-12, "the point in 2|3 lies above it, into body 2")
T.assert_near(below[1], 1.1, 1e-12, "on the disc's axis (x)")
T.assert_near(above[2], 1.1, 1e-12, "on the disc's axis (y)")
for _, v in ipairs(c:vertices{where = function(v) return v.id >= n - 1 end}) do
  T.assert_true(not v.triple_line and #v.surfaces == 1, "a new point lies inside one film", v.id)
end
-- the outer films are untouched, so the cells fill the same box; the foot's area goes and the
-- walls shorten to a funnel
T.assert_near(total(c:volumes()), V0, 1e-12, "the three volumes add up as before")
T.assert_true(r.energy_after < r.energy_before and r.energy_before == E0, "the energy falls",
              ("%.6f -> %.6f"):format(r.energy_before, r.energy_after))
T.assert_equal(c:evolve{flow = "mcf", tau = 1e-3, steps = 5, progress = false}.stop_reason,
               "steps done", "MCF goes on from the collapse")

-- 2. Caps: refined once, moving the loop's 8 vertices to the axis would turn the walls' facets
-- over (the loop's corners pass their neighbours), so the loop stays: the floor 1|3 closes
-- with a fan to a, the walls' loop moves up by eps and closes with a fan to b.
local k = column(1)
disc = film_between(k, 1, 2)
info, E0, V0 = k:info(), k:energy(), total(k:volumes())
local loop
for _, l in ipairs(k:triple_lines()) do
  if l.closed and #l.vertices == 8 and l.surfaces[3] == disc then loop = l end
end
T.assert_true(loop ~= nil, "the disc's border: a loop of 8 vertices")
local loop_points = {}
for _, v in ipairs(loop.vertices) do loop_points[#loop_points + 1] = k:vertex(v) end
r = k:collapse_disc_film(disc)
T.assert_true(r.where:find("closed by caps") ~= nil, "the caps' event says so", r.where)
T.assert_equal(k:info().surfaces, info.surfaces - 1, "caps: the disc goes")
T.assert_true(film_between(k, 1, 2) == nil and film_between(k, 1, 3) ~= nil, "caps: 1 and 2 part")
-- vertices: the disc's 5 inner ones go, its 8 on the loop stay in 1|3; a, b and 8 copies come
T.assert_equal(k:info().vertices, info.vertices - 5 + 2 + 8, "caps: a, b and the copies")
n = k:info().vertices
local delta = 0.5 * 0.8 / (2 * math.pi) -- half the loop's radius (its length over 2 pi)
local apex = {k:vertex(n - 9), k:vertex(n - 8)}
local lo = r.cells[1] == 1 and apex[1] or apex[2]
local hi = r.cells[1] == 1 and apex[2] or apex[1]
T.assert_near(lo[3], 1 - delta, 1e-12, "caps: a below the disc")
T.assert_near(hi[3], 1 + delta, 1e-12, "caps: b above it")
-- (ids move down past the disc's inner vertices: the loop is found by its points)
local function vertex_at(p)
  for _, v in ipairs(k:vertices()) do
    if v.x[1] == p[1] and v.x[2] == p[2] and math.abs(v.x[3] - p[3]) < 1e-12 then return v end
  end
end
for _, p in ipairs(loop_points) do
  local kept, copy = vertex_at(p), vertex_at({p[1], p[2], p[3] + 0.5 * delta})
  T.assert_true(kept and #kept.surfaces == 1 and kept.bodies[1] == 1 and kept.bodies[2] == 3,
                "caps: the loop's vertex stays, in 1|3 only")
  T.assert_true(copy and #copy.surfaces == 1 and copy.bodies[1] == 2 and copy.bodies[2] == 3,
                "caps: its copy in 2|3 is eps = delta / 2 up")
end
for _, v in ipairs(k:vertices{where = function(v) return v.id > n - 10 end}) do
  T.assert_true(not v.triple_line and #v.surfaces == 1, "caps: a new vertex lies inside one film", v.id)
end
T.assert_near(total(k:volumes()), V0, 1e-12, "caps: the volumes add up as before")
-- the caps add a little more than the disc's area (0.04) twice
T.assert_true(r.energy_after > E0 and r.energy_after < E0 + 0.04, "caps: the energy rises by less than the disc's area",
              ("%.6f -> %.6f"):format(E0, r.energy_after))
T.assert_equal(k:evolve{flow = "mcf", tau = 1e-3, steps = 5, progress = false}.stop_reason,
               "steps done", "MCF goes on from the caps")

-- refusals name the film and change nothing
local d = column()
local X = T.positions(d)
T.check_error("collapse_disc_film: surface " .. film_between(d, 1, 3) .. " is not a disk",
              d.collapse_disc_film, d, film_between(d, 1, 3))
T.check_error("surface 99 does not exist (the cluster has surfaces 1..6)", d.collapse_disc_film, d, 99)
T.check_error("collapse_two_sided_film: surface " .. film_between(d, 1, 2) .. " is bounded by the closed",
              d.collapse_two_sided_film, d, film_between(d, 1, 2))
T.assert_true(T.same_positions(d, X) and d:info().surfaces == info.surfaces, "refused: nothing changed")
T.summary()
