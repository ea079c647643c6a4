-- c:step{flow, tau}: the step report, and errors that leave the cluster as it was.
local T = require("froth.test")
if not froth.has("gmsh") then -- the meshed builders are needed here
  T.assert_equal(froth.double_bubble, nil, "no double_bubble without gmsh")
  return T.summary()
end

local function same_positions(a, b)
  for v = 1, a:info().vertices do
    local x, y = a:vertex(v), b:vertex(v)
    if x[1] ~= y[1] or x[2] ~= y[2] or x[3] ~= y[3] then return false end
  end
  return true
end

-- One surface-diffusion step of the (non-equilibrium) half-ball double bubble.
local c0 = froth.double_bubble{h = 0.3}
local K = c0:info().vertices
local L = #c0:triple_lines()[1].vertices
local r0 = c0:report()
local c = c0:clone()
local tau = 1e-3
local r = c:step{flow = "sd", tau = tau}
T.assert_equal(r.flow, "sd", "report flow")
T.assert_equal(r.tau, tau, "report tau")
T.assert_equal(r.t, tau, "t advances by tau")
T.assert_equal(c:time(), tau, "c:time() after the step")
T.assert_equal(r.energy_before, c0:energy(), "energy_before is the energy before")
T.assert_equal(r.energy, c:energy(), "energy is the energy after")
T.assert_true(r.energy < r.energy_before, "surface diffusion decreases the energy",
              r.energy .. " >= " .. r.energy_before)
local V, V0 = c:volumes(), c0:volumes()
T.assert_true(#r.volumes == 2 and r.volumes[1] == V[1] and r.volumes[2] == V[2], "report volumes")
local loss = math.max(math.abs(V[1] - V0[1]) / V0[1], math.abs(V[2] - V0[2]) / V0[2])
T.assert_near(r.volume_loss, loss, 1e-15, "volume_loss = max |V - V0| / V0")
T.assert_true(r.volume_loss < 1e-3, "surface diffusion nearly keeps the volumes", r.volume_loss)
-- positions 3K plus one kappa per (surface, vertex) pair less one per line vertex: K + 2L - L
T.assert_equal(r.unknowns, 4 * K + L, "sd unknowns")
T.assert_true(r.solve_s >= 0 and r.assemble_s >= 0, "timings present")
-- The half balls meet at 90, 90 and 180 degrees; one step moves all angles towards 120.
T.assert_near(r0.angles.min, 90, 3, "initial smallest angle")
T.assert_near(r0.angles.max, 180, 3, "initial largest angle")
T.assert_near(r.angles.mean, 120, 1e-9, "the three angles at a line vertex add up to 360")
T.assert_equal(r.angles.count, 3 * L, "three angles per vertex of the closed triple line")
T.assert_true(r.angles.min > r0.angles.min + 5 and r.angles.max < r0.angles.max - 5,
              "angles move towards 120", r.angles.min .. " .. " .. r.angles.max)
T.assert_true(r.mesh.min_angle > 0 and r.mesh.min_angle <= 60 and r.mesh.max_angle >= 60 and
              r.mesh.max_angle < 180, "facet angles", r.mesh.min_angle .. " " .. r.mesh.max_angle)
T.assert_true(r.mesh.max_edge_ratio >= 1 and r.mesh.min_area > 0, "mesh quality fields")
local rep = c:report()
T.assert_true(rep.t == r.t and rep.energy == r.energy and rep.angles.min == r.angles.min and
              rep.mesh.min_area == r.mesh.min_area, "c:report() agrees with the step report")
T.assert_true(c0:time() == 0 and same_positions(c0, c0:clone()), "the original is untouched")

-- Mean curvature flow of a sphere: R^2 = R0^2 - 4t, so the area shrinks by about 1 - 4 tau.
local s = froth.sphere{h = 0.3}
local rs = s:step{flow = "mcf", tau = tau}
T.assert_equal(rs.flow, "mcf", "mcf flow name")
T.assert_equal(rs.unknowns, 3 * s:info().vertices, "mcf unknowns: the positions")
T.assert_near(rs.energy / rs.energy_before, 1 - 4 * tau, 5e-4, "mcf area decay")
T.assert_true(rs.volumes[1] < s:clone():volumes()[1] + 1e-12, "the sphere shrinks")
T.assert_true(rs.volume_loss > 2e-3, "mcf does not keep the volume", rs.volume_loss)
T.assert_equal(rs.angles, nil, "no triple lines: no angles")
-- Surface diffusion keeps a sphere: the energy hardly changes; flows may alternate.
local e1 = s:energy()
local rd = s:step{flow = "sd", tau = tau}
T.assert_equal(rd.unknowns, 4 * s:info().vertices, "sd unknowns of a sphere")
T.assert_near(rd.energy, e1, 1e-3 * e1, "a sphere is stationary under sd")
T.assert_true(rd.energy <= rd.energy_before, "sd does not increase the energy")
T.assert_near(s:time(), 2 * tau, 1e-18, "time after two steps")

-- Errors: the option table is checked before anything moves.
local t1, E1 = c:time(), c:energy()
local snapshot = c:clone()
local function bad(text, opts) T.check_error(text, c.step, c, opts) end
bad("step: tau must be positive and finite, got 0", {flow = "sd", tau = 0})
bad("step: tau must be positive and finite, got -0.001", {flow = "mcf", tau = -1e-3})
bad("step: tau must be positive and finite", {flow = "sd", tau = 0 / 0})
bad("step: tau must be positive and finite, got inf", {flow = "sd", tau = math.huge})
bad("step: option 'tau' is required", {flow = "sd"})
bad("step: option 'flow' is required", {tau = tau})
bad("step: option 'tau' must be a number", {flow = "sd", tau = "0.001"})
bad("step: option 'flow' must be a string", {flow = 1, tau = tau})
bad("step: unknown flow 'xyz' (use \"mcf\" for mean curvature flow or \"sd\" for surface diffusion)",
    {flow = "xyz", tau = tau})
bad("step: unknown option 'taux'", {flow = "sd", tau = tau, taux = 1})
bad("step: option keys must be names", {flow = "sd", tau = tau, 5})
bad("step: expected an option table {...}, got number", 1e-3)
T.check_error("step: expected an option table {...}, got no value", c.step, c)
T.check_error("froth.Cluster expected", c.step, {}, {flow = "sd", tau = tau})
T.assert_equal(c:time(), t1, "failed steps keep the time")
T.assert_equal(c:energy(), E1, "failed steps keep the energy")
T.assert_true(same_positions(c, snapshot), "failed steps keep the positions")

-- A step that fails in the engine: a huge mcf step would take the sphere past its extinction
-- (t = 1/4), so it is refused, leaving the cluster as it was.
local tiny = froth.sphere{h = 0.3}
local Et = tiny:energy()
T.check_error("step: with tau = 1e+06 body 1 would vanish", tiny.step, tiny, {flow = "mcf", tau = 1e6})
T.assert_equal(tiny:time(), 0, "a failed step keeps the time")
T.assert_equal(tiny:energy(), Et, "a failed step keeps the energy")

T.summary()
