-- sd_solver = "auto" | "lu" | "blocks" on c:step and c:evolve: surface diffusion's saddle
-- points solved by GMRES on the block preconditioner of two Cholesky factors
-- (solvers/saddle_point.h) give the LU's steps to the solvers' backward error, on clusters with
-- triple lines, walls and fixed vertices, at order 1 and 2, linear and volume-exact; the
-- iterations do not grow with the mesh; the report names the solver; bad values are errors.
local T = require("froth.test")
local yes, eq = T.assert_true, T.assert_equal

-- Runs `steps` SD steps of tau on a copy of c with the given solver; returns the copy and the
-- last report.
local function run(c, how, steps, tau, extra)
  local d = c:clone()
  local r
  for _ = 1, steps do
    local o = {flow = "sd", tau = tau, sd_solver = how}
    for k, v in pairs(extra or {}) do o[k] = v end
    r = d:step(o)
  end
  return d, r
end

-- The same steps, to a tolerance far below the steps' own size (the backward error of both
-- solvers is 1e-15, so their answers differ by round-off times the system's condition; the
-- order-2 predictor is solved to 1e-10 only, which moves the corrector's geometry by more).
local function same_steps(name, c, steps, tau, extra, rel)
  rel = rel or 1e-9
  local lu, rl = run(c, "lu", steps, tau, extra)
  local bl, rb = run(c, "blocks", steps, tau, extra)
  eq(rl.sd_solver, "lu", name .. ": the LU was used")
  eq(rb.sd_solver, "blocks", name .. ": the blocks were used")
  local moved = T.max_difference(lu, c)
  local diff = T.max_difference(lu, bl)
  yes(moved > 0 and diff <= rel * math.max(moved, 1e-3), name .. ": blocks give the LU's steps",
      ("difference %.3g, motion %.3g"):format(diff, moved))
  yes(T.rel(bl:energy(), lu:energy()) < 1e-11, name .. ": the same energy",
      bl:energy() .. " vs " .. lu:energy())
  for b, v in ipairs(lu:volumes()) do
    yes(T.rel(bl:volumes()[b], v) < 1e-11, name .. ": the same volume of body " .. b)
  end
  return bl, rb
end

-- A perturbed icosphere (an ellipsoid), so that surface diffusion moves it.
local function ellipsoid(levels)
  local c = froth.sphere{levels = levels}
  for _, v in ipairs(c:vertices{}) do
    c:set_vertex(v.id, {1.2 * v.x[1], v.x[2], 0.9 * v.x[3]})
  end
  return c
end

local e = ellipsoid(2)
same_steps("ellipsoid, volume-exact", e, 3, 1e-3)
same_steps("ellipsoid, linear", e, 3, 1e-3, {exact_volumes = false})
same_steps("ellipsoid, order 2", e, 4, 1e-3, {order = 2}, 1e-6)
same_steps("ellipsoid, tau = 1", e, 2, 1.0)
same_steps("ellipsoid, tau = 1e-7", e, 2, 1e-7)
same_steps("double bubble (triple line)", froth.double_bubble{h = 0.3}, 3, 1e-3)
same_steps("cube on a plane (wall)", froth.cube_on_plane{h = 0.25}, 3, 1e-3)
local pinned = ellipsoid(2)
pinned:fix(pinned:vertices{where = function(v) return v.x[3] > 0.6 end})
same_steps("fixed vertices", pinned, 3, 1e-3)

-- The preconditioner's quality does not depend on the mesh (saddle_point.h's Fourier model:
-- the Schur complement's eigenvalues in [1/2, 1] for any h and tau), so the GMRES iterations
-- of a solve stay put as the vertices grow 16x (a mis-scaled sigma, 1 instead of
-- sqrt(tau beta / gamma), took 59 iterations in the unit tests' model).
local function iterations(levels)
  local c = ellipsoid(levels)
  local r = c:step{flow = "sd", tau = 1e-3, sd_solver = "blocks", exact_volumes = false}
  return r.solver_iterations
end
local coarse, fine = iterations(2), iterations(4)
yes(fine <= 1.5 * coarse + 2, "GMRES iterations do not grow with the mesh (162 -> 2562 vertices)",
    coarse .. " -> " .. fine)

-- "auto" is the LU for small systems; evolve takes the option too, and clones continue alike.
local _, auto = run(e, "auto", 1, 1e-3)
eq(auto.sd_solver, "lu", "auto: the LU below 10^5 unknowns")
local a = e:clone()
a:evolve{flow = "sd", tau = 1e-3, steps = 2, sd_solver = "blocks", progress = false}
local b = a:clone()
a:step{flow = "sd", tau = 1e-3, sd_solver = "blocks"}
b:step{flow = "sd", tau = 1e-3, sd_solver = "blocks"}
eq(T.max_difference(a, b), 0, "a clone continues a blocks run bit for bit")
local mcf = e:clone():step{flow = "mcf", tau = 1e-3, sd_solver = "blocks"}
eq(mcf.sd_solver, nil, "MCF reports no sd_solver")

-- Errors, and nothing changed.
local X = T.positions(e)
T.check_error("option 'sd_solver' must be \"auto\", \"lu\" or \"blocks\"",
              function() e:step{flow = "sd", tau = 1e-3, sd_solver = "cg"} end)
T.check_error("option 'sd_solver' must be a string",
              function() e:evolve{flow = "sd", tau = 1e-3, steps = 1, sd_solver = 3} end)
T.check_error("option 'sd_solver' must be \"auto\", \"lu\" or \"blocks\"",
              function() e:evolve{flow = "sd", tau = 1e-3, steps = 1, sd_solver = "LU"} end)
yes(T.same_positions(e, X), "a refused option changes nothing")

T.summary()
