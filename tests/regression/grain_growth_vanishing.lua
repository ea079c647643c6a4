-- Regression: the 27-grain network of grain_growth_mcf.lua run on to T = 1.0 (500 MCF steps,
-- about 90 s), through its vanishing grains (8 of them, 138 other transitions). Grains reach
-- the mesh's scale flattened, with more than four neighbours (grain 6: 8), before their faces
-- have shrunk away, so they cannot pop; each joins the neighbour it shares the most film with
-- (absorb), and the run goes on. History of where this run stopped (one evolve call;
-- datafiles/grain_growth.lua n=27 seed=2 lloyd=5 T=2, one step per call, takes another path):
-- t = 0.642 before the absorb ("it cannot pop: body 6 has 8 neighbouring cells"); 0.65 without
-- flat films being due (a lens squeezed to a cap); 0.73, then 0.694 with the zips, forced
-- transitions and moved film vertices of 2026-12-06 (ba1ac47; this test ran to 0.68 then);
-- T = 1.0 since slivers no upkeep mends are deferred while above a tenth of the watch's limits,
-- a transition's corners are fitted off slivers, and the upkeeps take turns at one defect
-- (0027471 .. d134702; ba1ac47 stops at t = 0.694, "no T1 could be made").
local T = require("froth.test")
if not froth.has("gmsh") then
  T.assert_true(true, "skipped: no gmsh")
  return T.summary()
end

local c = froth.foam{n = 27, seed = 2, h = 0.4, lloyd = 5, equal_volumes = false}
local n0 = c:info().bodies
local box = 0
for _, v in ipairs(c:volumes()) do box = box + v end
local r = c:evolve{flow = "mcf", tau = 2e-3, T = 1.0, progress = false}
T.assert_equal(r.stop_reason, "T reached", "the network coarsens on to T = 1.0", r.stop_reason)
local absorbed, kinds = 0, {}
for _, e in ipairs(r.events) do
  kinds[e.kind] = (kinds[e.kind] or 0) + 1
  if e.kind == "absorb body" then
    absorbed = absorbed + 1
    T.assert_true(e.neighbours > 4, "a grain with too many neighbours to pop", e.where)
    T.assert_true(e.into >= 1 and e.into <= n0 and e.into ~= e.body, "joined another grain")
    T.assert_true(e.energy_after < e.energy_before, "the energy falls", e.where)
  end
end
for kind, n in pairs(kinds) do print(kind, n) end
T.assert_true(absorbed >= 1, "grains vanished on the way", tostring(absorbed))
T.assert_equal(c:info().bodies, n0 - absorbed, "one grain less for each")
local filled = 0
for _, v in ipairs(c:volumes()) do filled = filled + v end
T.assert_near(filled, box, 1e-9 * box, "the grains still fill the box")
T.summary()
