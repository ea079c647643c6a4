-- The T1 of a line whose two ends meet the same fourth cell D (t1_line_to_film, D = E): D wraps
-- around the line, so no film D|D forms; A, B and C part and D meets itself through the gap,
-- its films with A, B and C at the two ends joining. Grain networks meet it when a grain wraps
-- around a shrinking line (27 grains of seed 1 and 3 and 64 of seed 2 stopped on it).
-- The case: three wedge cells of a flat disk around a short vertical axis, the outside above
-- and below. The axis's T1 opens a triangular hole through the disk: the two quadruple points
-- go, and the three lines (wedge, wedge, outside) that ran from one to the other over the rim
-- close into loops through the hole's corners.
local T = require("froth.test")

-- The disk of radius R and thickness l: wedge k spans the angles 2 pi k / 3 .. 2 pi (k + 1) / 3,
-- its film with the outside (top, bottom and rim) is surface k, the radial film between
-- wedges k and k + 1 surface 3 + k; m rings, n angular segments per wedge.
local function wedge_disk(l, R, m, n)
  local V, id = {}, {}
  local J = 3 * n
  local function vertex(i, j, s) -- ring i, angle j, s = 1 top, -1 bottom
    if i == 0 then j = 0 end
    j = j % J
    local key = i .. ":" .. j .. ":" .. s
    if not id[key] then
      local r, a = R * i / m, 2 * math.pi * j / J
      V[#V + 1] = {r * math.cos(a), r * math.sin(a), s * l / 2}
      id[key] = #V
    end
    return id[key]
  end
  local outer, radial = {{}, {}, {}}, {{}, {}, {}}
  for k = 0, 2 do
    local F = outer[k + 1]
    for j = n * k, n * (k + 1) - 1 do
      for i = 0, m - 1 do
        for _, s in ipairs({1, -1}) do
          local a, b, c, d = vertex(i, j, s), vertex(i + 1, j, s), vertex(i + 1, j + 1, s),
                             vertex(i, j + 1, s)
          local tris = i == 0 and {{a, b, c}} or {{a, b, c}, {a, c, d}}
          for _, t in ipairs(tris) do F[#F + 1] = s == 1 and t or {t[1], t[3], t[2]} end
        end
      end
      local a, b, c, d = vertex(m, j, -1), vertex(m, j + 1, -1), vertex(m, j + 1, 1), vertex(m, j, 1)
      F[#F + 1] = {a, b, c}
      F[#F + 1] = {a, c, d}
    end
    local j = n * (k + 1)
    for i = 0, m - 1 do
      local a, b, c, d = vertex(i, j, -1), vertex(i + 1, j, -1), vertex(i + 1, j, 1), vertex(i, j, 1)
      radial[k + 1][#radial[k + 1] + 1] = {a, b, c}
      radial[k + 1][#radial[k + 1] + 1] = {a, c, d}
    end
  end
  return froth.cluster{vertices = V,
                       surfaces = {outer[1], outer[2], outer[3], radial[1], radial[2], radial[3]},
                       bodies = {{1, 4, 6}, {2, 4, 5}, {3, 5, 6}}}
end

local l = 0.1
local c = wedge_disk(l, 1, 6, 4)
T.assert_equal(#c:quadruple_points(), 2, "the axis's ends are quadruple points")
T.assert_equal(#c:triple_lines(), 4, "the axis and three lines over the rim")
local axis
for i, tl in ipairs(c:triple_lines()) do
  if #tl.vertices == 2 then axis = i end
end
T.assert_true(axis ~= nil, "the axis is one edge")
local A0, V0 = c:area(), c:volumes()
local rim_vertices = #c:triple_lines()[axis % 4 + 1].vertices

local r = c:t1(axis)
T.assert_equal(r.cells[1], 0, "D is the outside (id 0)")
T.assert_equal(r.cells[2], 0, "at both ends")
T.assert_true(r.where:find("through which the outside meets itself", 1, true) ~= nil,
              "the event says so", r.where)
T.assert_equal(#c:quadruple_points(), 0, "both quadruple points went")
T.assert_equal(#c:triple_lines(), 3, "three lines are left")
for _, tl in ipairs(c:triple_lines()) do
  T.assert_true(tl.closed, "each is a loop through the hole")
  -- it lost its two ends, the quadruple points, and gained the hole's corner
  T.assert_equal(#tl.vertices, rim_vertices - 1, "its vertices")
end
T.assert_equal(c:info().surfaces, 6, "no film formed, none went (each wedge's film with the "
               .. "outside is one surface at both ends)")
T.assert_true(c:area() < A0, "the radial films lost their strips along the axis",
              ("%.6f -> %.6f"):format(A0, c:area()))
-- the three wedges are alike, and each lost the volume the hole took
local V = c:volumes()
for k = 1, 3 do
  T.assert_near(V[k] - V0[k], V[1] - V0[1], 1e-12, "wedge " .. k .. " changed as wedge 1")
  T.assert_true(V[k] < V0[k] and V[k] > 0.98 * V0[k], "a hole of side l in a disk of thickness l",
                ("%g -> %g"):format(V0[k], V[k]))
end
local step = c:evolve{flow = "mcf", tau = 1e-3, steps = 2, progress = false}
T.assert_equal(step.stop_reason, "steps done", "the ring steps on")

-- a cell that meets itself twice at one end (a tiny periodic foam) is refused, unchanged
local f = froth.foam{n = 4, seed = 3, h = 0.3, lloyd = 5}
local n_lines, Xf = #f:triple_lines(), T.positions(f)
T.check_error("the films of the cell that meets itself across it do not pair up", f.t1, f, 1)
T.assert_equal(#f:triple_lines(), n_lines, "nothing changed")
T.assert_true(T.same_positions(f, Xf), "no vertex moved")
T.summary()
