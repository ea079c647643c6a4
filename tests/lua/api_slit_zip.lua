-- c:collapse_edges zips a slit (mesh/corner_zip.cpp, zip_slit): a film's corner at a quadruple
-- point q closed over a whole edge, the first vertex a of one line lying on the first edge
-- (q, b) of another line of the same film. No edge is short there, so before zip_slit nothing
-- collapsed (grain networks stopped on such slits: 27 grains of seed 1 at t = 0.69). The zip
-- splits (q, b) at a's foot and moves q up the slit to it: the lines and
-- quadruple points stay, the line of a loses a vertex, q's two other lines reach along.
local T = require("froth.test")

local function sub(x, y) return {x[1] - y[1], x[2] - y[2], x[3] - y[3]} end
local function dot(x, y) return x[1] * y[1] + x[2] * y[2] + x[3] * y[3] end
local function along(x, d, s) return {x[1] + s * d[1], x[2] + s * d[2], x[3] + s * d[3]} end
local function norm(x) return math.sqrt(dot(x, x)) end

-- The lines at vertex q: their ids, first vertices after q, vertex counts and films.
local function lines_at(c, q)
  local out = {}
  for i, l in ipairs(c:triple_lines()) do
    local v = l.vertices
    if v[1] == q then out[#out + 1] = {id = i, first = v[2], n = #v, films = l.surfaces}
    elseif v[#v] == q then out[#out + 1] = {id = i, first = v[#v - 1], n = #v, films = l.surfaces} end
  end
  return out
end

local function shares_a_film(l1, l2)
  for _, s in ipairs(l1.films) do
    for _, t in ipairs(l2.films) do if s == t then return true end end
  end
  return false
end

-- The triple bubble's quadruple point q (three bubbles and the outside): the first vertex a of
-- one of its lines goes to 0.002 from the midpoint of another line's first edge (q, b), the
-- two lines bounding one film: its corner at q is a slit 0.002 wide over half an edge.
local c = froth.triple_bubble{}
local q = c:quadruple_points()[1]
local at_q = lines_at(c, q)
T.assert_equal(#at_q, 4, "a Plateau quadruple point has four lines")
local L1, L2
for _, l in ipairs(at_q) do
  for _, m in ipairs(at_q) do
    if not L1 and l ~= m and l.n > 2 and shares_a_film(l, m) then L1, L2 = l, m end
  end
end
T.assert_true(L1 ~= nil, "two lines of one film leave q")
local a, b = L1.first, L2.first
local foot = along(c:vertex(q), sub(c:vertex(b), c:vertex(q)), 0.5)
local off = sub(c:vertex(a), foot)
c:set_vertex(a, along(foot, off, 0.002 / norm(off)))
-- where the lines part: the midpoint of a and its foot m on (q, b)
local qb = sub(c:vertex(b), c:vertex(q))
local m = along(c:vertex(q), qb, dot(sub(c:vertex(a), c:vertex(q)), qb) / dot(qb, qb))
local part = along(m, sub(c:vertex(a), m), 0.5)
local n_lines, n_points = #c:triple_lines(), #c:quadruple_points()
local V0, angle0 = c:volumes(), c:report().mesh.min_angle

T.assert_equal(c:collapse_edges{shorter_than = 0.001}.collapsed, 0,
               "a slit wider than shorter_than is left")
local r = c:collapse_edges{shorter_than = 0.01}
T.assert_equal(r.collapsed, 2, "a and a's foot went onto q")
T.assert_equal(#c:triple_lines(), n_lines, "the lines stay")
T.assert_equal(#c:quadruple_points(), n_points, "the quadruple points stay")
T.assert_equal(c:quadruple_points()[1], q, "q keeps its id (the vertices before a)")
T.assert_near(norm(sub(c:vertex(q), part)), 0, 1e-12, "q went to where the lines part")
T.assert_true(norm(sub(m, foot)) < 0.01, "half way up the edge")
local after = lines_at(c, q)
T.assert_equal(#after, 4, "q still has four lines")
local lengths = {}
for _, l in ipairs(after) do lengths[l.id] = l.n end
T.assert_equal(lengths[L1.id], L1.n - 1, "a's line lost a, its first vertex")
T.assert_equal(lengths[L2.id], L2.n, "b's line keeps its vertex count (its foot went)")
T.assert_true(c:report().mesh.min_angle >= angle0 - 0.5,
              "no worse facet than the slit's neighbours had",
              ("%g -> %g"):format(angle0, c:report().mesh.min_angle))
local V1 = c:volumes()
for i = 1, #V0 do
  T.assert_near(V1[i], V0[i], 1e-4 * V0[i], "bubble " .. i .. "'s volume changes by the slit's sliver")
end
T.assert_plateau_points(c)
T.summary()
