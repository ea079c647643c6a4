-- Topological transitions: c:pop_body and evolve's automatic pop of a vanishing cell
-- (issue 15 item 4). Each Plateau case of a pop: a lens on a film (2 neighbouring cells), on a
-- triple line (3) and a tetrahedral cell at a quadruple point (4).
local T = require("froth.test")
if not froth.has("gmsh") then
  T.assert_true(true, "skipped: no gmsh")
  return T.summary()
end
local pi = math.pi

-- 1. c:pop_body on the small bubble of a double bubble: one sphere is left.
local d = froth.double_bubble{h = 0.15, split = 0.3}
local V0, E0, n0 = d:volumes(), d:energy(), d:info().vertices
local p = d:pop_body(2)
T.assert_equal(p.body, 2, "pop_body: which body")
T.assert_equal(p.neighbours, 2, "the small bubble borders the big one and the outside")
T.assert_near(p.energy_before, E0, 1e-12, "energy before")
T.assert_near(p.energy_after, d:energy(), 1e-12, "energy after is the cluster's")
T.assert_true(p.energy_after < p.energy_before, "the pop lowers the energy")
T.assert_equal(d:info().bodies, 1, "one body left")
T.assert_equal(#d:triple_lines(), 0, "the triple line is gone")
T.assert_equal(d:info().vertices, n0 - p.removed_vertices, "removed_vertices counts them")
T.assert_true(p.where:find("body 2 (volume", 1, true) ~= nil, "where names the body", p.where)
-- the big bubble closes over the point: its volume changes by less than the small one's
T.assert_true(math.abs(d:volumes()[1] - V0[1]) < 0.05 * V0[2], "big bubble keeps its volume",
              tostring(d:volumes()[1]))
T.assert_near(d:target_volumes()[1], d:volumes()[1], 1e-12, "target = volume after the pop")
T.assert_true(#p.point == 3 and p.point[3] > 0, "the point is on the small bubble's side")
d:evolve{flow = "sd", tau = 1e-3, steps = 3, progress = false} -- the stepper starts afresh
T.assert_near(d:volumes()[1], d:target_volumes()[1], 1e-9 * d:volumes()[1], "SD holds it after")

-- errors change nothing
local s = froth.sphere{h = 0.4}
local Xs = T.positions(s)
T.check_error("pop_body: body 1 is all the cluster has", s.pop_body, s, 1)
T.check_error("body 2 does not exist (the cluster has bodies 1..1)", s.pop_body, s, 2)
T.check_error("number expected", s.pop_body, s, "one")
T.assert_true(T.same_positions(s, Xs) and s:info().bodies == 1, "failed pops change nothing")

-- 2. evolve pops a vanishing bubble and goes on; transitions = false stops there instead.
local function unequal_double_bubble() return froth.double_bubble{h = 0.15, split = 0.4} end
local stop = unequal_double_bubble()
local rs = stop:evolve{flow = "mcf", tau = 2e-3, T = 0.5, progress = false, transitions = false}
T.assert_equal(rs.event and rs.event.kind, "vanishing body", "transitions = false stops")
T.assert_true(rs.event.message:find("body 2 is vanishing", 1, true) ~= nil, "at the small one",
              rs.event.message)
T.assert_equal(#rs.events, 0, "and makes no transition")

local dir = os.tmpname()
os.remove(dir)
local go = unequal_double_bubble()
local rg = go:evolve{flow = "mcf", tau = 2e-3, T = 0.5, progress = false, history = dir .. "/h"}
T.assert_equal(#rg.events, 1, "one pop")
local e = rg.events[1]
T.assert_equal(e.kind, "pop body", "event kind")
T.assert_equal(e.body, 2, "the small bubble pops")
T.assert_near(e.t, rs.t, 1e-12, "where the watch saw it vanish")
T.assert_equal(e.step, rs.steps, "after the same step")
T.assert_true(e.energy_after < e.energy_before, "energy falls through the pop")
T.assert_true(rg.t > e.t, "the run goes on after the pop", tostring(rg.t))
T.assert_equal(rg.event and rg.event.kind, "vanishing body", "until the last bubble vanishes")
T.assert_true(rg.stop_reason:find("body 1 is vanishing", 1, true) ~= nil and
              rg.stop_reason:find("it cannot pop: body 1 is all the cluster has", 1, true) ~= nil,
              "stop_reason says why it could not pop", rg.stop_reason)
-- the history keeps a column per body of the start: the popped one reads 0 after the pop
local rows, popped_rows = 0, 0
for line in io.lines(dir .. "/h.csv") do
  local t, V1, V2 = line:match("^([^,]+),[^,]+,[^,]+,[^,]+,([^,]+),([^,]+)$")
  T.assert_true(t ~= nil or rows == 0, "two volume columns in every row", line)
  if t and rows > 0 and tonumber(V2) == 0 then popped_rows = popped_rows + 1 end
  rows = rows + 1
end
T.assert_equal(rows, rg.steps + 3, "header, start, every step and the state after the pop")
T.assert_equal(popped_rows, rg.steps - e.step + 1, "V2 = 0 from the pop on")
os.remove(dir .. "/h.csv"); os.remove(dir .. "/h.svg"); os.remove(dir)

-- 3. The three Plateau cases: a small ball on the triple bubble's film, triple line and
-- quadruple point. Body 1 is the ball; it vanishes first and leaves the triple bubble.
local function triple_bubble_with_ball(centre)
  local solids = {{"ball", r = 0.2, translate = centre}}
  for k = 0, 2 do
    solids[k + 2] = {"ball", r = 1, angle = 2 * pi / 3,
                     rotate = {axis = {0, 0, 1}, angle = 2 * pi * k / 3}}
  end
  return froth.fragment{solids = solids, h = 0.15}
end
local plain = froth.triple_bubble{h = 0.15}
for _, case in ipairs{{{0.5, 0, 0}, 2, "film"}, {{0, 0, 0}, 3, "triple line"},
                      {{0, 0, 1}, 4, "quadruple point"}} do
  local c = triple_bubble_with_ball(case[1])
  local r = c:evolve{flow = "mcf", tau = 2e-4, T = 0.02, progress = false}
  T.assert_equal(r.stop_reason, "T reached", case[3] .. ": the run does not stop")
  T.assert_equal(#r.events, 1, case[3] .. ": one pop")
  T.assert_equal(r.events[1] and r.events[1].neighbours, case[2], case[3] .. ": neighbours")
  T.assert_equal(r.events[1] and r.events[1].body, 1, case[3] .. ": the ball pops")
  T.assert_equal(c:info().bodies, 3, case[3] .. ": three bodies left")
  T.assert_equal(#c:triple_lines(), #plain:triple_lines(), case[3] .. ": the triple bubble's lines")
  T.assert_equal(#c:quadruple_points(), #plain:quadruple_points(),
                 case[3] .. ": and its quadruple points")
end

T.summary()
