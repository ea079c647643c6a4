-- Regression: volume-exact surface diffusion (exact_volumes = true) on every kind of cluster:
-- unequal tensions, quadruple points, flat walls (plane, slab), curved walls (sphere, cylinder,
-- a Lua F = 0 wall), anisotropy with r = 1 and r > 1. Each step must leave every body at its target
-- volume to 1e-12 (relative) and not raise the energy (beyond 1e-13 relative: round-off of the
-- kappa rows' volume term); a 1000-step run must hold the volumes to 1e-10.
local T = require("froth.test")

local function run(name, c, tau, steps)
  local V0 = c:volumes()
  local worst, rise, solves = 0, 0, 0
  local r = c:evolve{flow = "sd", tau = tau, steps = steps, exact_volumes = true, progress = false,
    on_step = function(s)
      worst = math.max(worst, s.volume_error)
      rise = math.max(rise, (s.energy - s.energy_before) / s.energy_before)
      solves = math.max(solves, s.volume_iterations)
    end}
  local V = c:volumes()
  local drift = 0
  for b = 1, #V do drift = math.max(drift, math.abs(V[b] - V0[b]) / V0[b]) end
  print(("%-26s %3d steps: volume error per step <= %.1e, over the run %.1e; energy rise %.1e;"
         .. " at most %d solves a step"):format(name, r.steps, worst, drift, rise, solves))
  T.assert_equal(r.steps, steps, name .. ": all steps taken (" .. r.stop_reason .. ")")
  T.assert_true(worst <= 1e-12, name .. ": volumes exact to 1e-12 per step", tostring(worst))
  T.assert_true(drift <= 1e-12 * steps, name .. ": volumes exact over the run", tostring(drift))
  T.assert_true(rise <= 1e-13, name .. ": energy non-increasing", tostring(rise))
  return drift
end

run("double bubble, sigma 1/1.3/0.8", froth.double_bubble{h = 0.2, split = 0.3, sigma = {1, 1.3, 0.8}},
    1e-3, 20)
run("triple bubble (quadruple pts)", froth.triple_bubble{h = 0.25}, 1e-3, 10)
run("cube on a plane", froth.cube_on_plane{h = 0.2}, 1e-3, 10)
run("cylinder in a slab", froth.cylinder_in_slab{h = 0.3}, 1e-3, 10)
run("drop on a sphere wall", froth.drop_on_sphere_wall{h = 0.2}, 1e-3, 10)
-- A half ball sheared onto the cylinder y^2 + z^2 = 4 (x3 += sqrt(4 - x2^2): volume-preserving,
-- the flat face onto the wall); its lid is a fan of cylinder patches (lua_api.md, External
-- boundaries) drawn on the unrolled cylinder; with a flat fan (before) the energy rose by 1e-5
-- a step from the third step on, as the films were pushed by the change of the bulge.
run("drop on a cylinder wall", froth.fragment{solids = {{"ball", r = 0.7, latitude = {0, math.pi / 2}}},
    h = 0.15, transform = function(x, y, z) return x, y, z + math.sqrt(4 - y * y) end,
    walls = froth.cylinder_wall{axis = {1, 0, 0}, radius = 2}}, 1e-3, 10)
run("half ball on a Lua F = 0 wall", froth.fragment{solids = {{"ball", r = 0.5, latitude = {0, math.pi / 2}}},
    h = 0.15, walls = froth.wall{name = "z = 0 from Lua", F = function(_, _, z) return z end}}, 1e-3, 10)
local e = froth.sphere{h = 0.3}
e:set_anisotropy(1, froth.anisotropy{{G = {{1, 0, 0}, {0, 1, 0}, {0, 0, 4}}}})
run("sphere, ellipsoidal r = 1", e, 1e-3, 10)
local n = froth.sphere{h = 0.3}
n:set_anisotropy(1, froth.anisotropy{{G = {{1, 0, 0}, {0, 1, 0}, {0, 0, 4}}},
                                     {G = {{4, 0, 0}, {0, 1, 0}, {0, 0, 1}}}, r = 2})
run("sphere, two terms r = 2", n, 1e-3, 10)
local big = froth.double_bubble{h = 0.3, split = 0.3}
run("double bubble, tau = 10", big, 10, 5)
local long = froth.double_bubble{h = 0.3, split = 0.3}
local drift = run("double bubble, 1000 steps", long, 1e-3, 1000)
T.assert_true(drift <= 1e-10, "1000 steps: volumes to 1e-10", tostring(drift))
T.summary()
