-- c:evolve{...}: steps and T, the on_step callback, ParaView output, result fields, errors.
local T = require("froth.test")
if not froth.has("gmsh") then
  T.assert_equal(froth.sphere, nil, "no sphere without gmsh")
  return T.summary()
end

local tau = 1e-3
local base = froth.double_bubble{h = 0.3}

-- steps = n: the result describes the final state, and the callback saw every step.
local c = base:clone()
local seen, worst, solve = {}, 0, 0
local r = c:evolve{flow = "sd", tau = tau, steps = 4, on_step = function(s)
  seen[#seen + 1] = s
  worst = math.max(worst, (s.energy - s.energy_before) / s.energy_before)
  solve = solve + s.solve_s
end}
T.assert_equal(r.steps, 4, "steps")
T.assert_equal(r.stop_reason, "steps done", "stop_reason")
T.assert_near(r.t, 4 * tau, 1e-17, "t = 4 tau")
T.assert_equal(r.t, c:time(), "result t is the cluster time")
T.assert_equal(r.energy, c:energy(), "result energy is the final energy")
local V, V0 = c:volumes(), base:volumes()
T.assert_true(r.volumes[1] == V[1] and r.volumes[2] == V[2], "result volumes")
T.assert_near(r.volume_loss, math.max(math.abs(V[1] - V0[1]) / V0[1],
                                      math.abs(V[2] - V0[2]) / V0[2]), 1e-15, "volume_loss")
T.assert_equal(#seen, 4, "on_step called once per step")
for k, s in ipairs(seen) do
  T.assert_near(s.t, k * tau, 1e-17, "on_step report " .. k .. " time")
  T.assert_true(s.flow == "sd" and s.tau == tau and s.unknowns > 0, "on_step report " .. k .. " fields")
end
T.assert_equal(seen[4].energy, r.energy, "last report energy")
T.assert_equal(r.max_energy_increase, worst, "max_energy_increase from the step reports")
T.assert_true(r.max_energy_increase == 0, "sd never increases the energy here", r.max_energy_increase)
T.assert_near(r.solve_s, solve, 1e-12, "solve_s sums the steps")
T.assert_true(r.wall_s >= r.solve_s and r.wall_s < 60, "wall_s", r.wall_s)
T.assert_equal(r.angles.count, seen[4].angles.count, "result angles")
-- The same steps one at a time give the same cluster.
local d = base:clone()
for _ = 1, 4 do d:step{flow = "sd", tau = tau} end
T.assert_equal(d:energy(), c:energy(), "evolve = repeated step")

-- T is a duration from the current time; the last step is shortened to land on it.
local taus = {}
r = c:evolve{flow = "sd", tau = tau, T = 2.5e-3, on_step = function(s) taus[#taus + 1] = s.tau end}
T.assert_equal(r.stop_reason, "T reached", "stop_reason for T")
T.assert_equal(r.steps, 3, "ceil(T / tau) steps")
T.assert_near(r.t, 4e-3 + 2.5e-3, 1e-17, "t = start + T")
T.assert_near(taus[3], 5e-4, 1e-15, "the last step is shortened")
local s = froth.sphere{h = 0.3}
r = s:evolve{flow = "sd", tau = 1e-3, T = 2.5e-3}
T.assert_equal(r.t, 2.5e-3, "t lands exactly on T")
r = s:evolve{flow = "mcf", tau = 0.02, T = 0.05}
T.assert_equal(r.t, 2.5e-3 + 0.05, "t lands exactly on start + T")
T.assert_equal(r.steps, 3, "0.02 + 0.02 + 0.01")
r = s:evolve{flow = "sd", tau = tau, steps = 0}
T.assert_true(r.steps == 0 and r.t == s:time() and r.stop_reason == "steps done", "steps = 0")

-- on_step returning false stops; nil or true go on.
c = base:clone()
local n = 0
r = c:evolve{flow = "mcf", tau = tau, steps = 10, on_step = function()
  n = n + 1
  if n == 3 then return false end
  return n == 1 or nil
end}
T.assert_equal(r.stop_reason, "on_step", "stop_reason on_step")
T.assert_true(r.steps == 3 and n == 3, "stopped after the third step")
T.assert_near(c:time(), 3 * tau, 1e-17, "time after the stop")

-- An error in on_step propagates; the cluster keeps the last completed step.
c = base:clone()
local energies = {}
n = 0
local ok, msg = pcall(c.evolve, c, {flow = "sd", tau = tau, steps = 10, on_step = function(rep)
  n = n + 1
  energies[n] = rep.energy
  if n == 2 then error("stop here") end
end})
T.assert_true(not ok and tostring(msg):find("stop here", 1, true) ~= nil, "the error propagates", msg)
T.assert_near(c:time(), 2 * tau, 1e-17, "the cluster keeps step 2")
T.assert_equal(c:energy(), energies[2], "the energy of step 2")
local ok2, obj = pcall(c.evolve, c, {flow = "sd", tau = tau, steps = 1, on_step = function()
  error({code = 7})
end})
T.assert_true(not ok2 and type(obj) == "table" and obj.code == 7, "error objects pass unchanged")

-- ParaView output: the first state, every `every` steps, and the last state.
local dir = os.tmpname()
os.remove(dir) -- a fresh name; evolve creates the folder
local files = {}
local function pvd_check(steps, every, want)
  local pvd = dir .. "/run" .. steps .. "_" .. every .. ".pvd"
  local e = base:clone()
  e:evolve{flow = "sd", tau = tau, steps = steps, every = every, output = pvd}
  local f = io.open(pvd)
  T.assert_true(f ~= nil, pvd .. " written")
  if not f then return end
  local text = f:read("a")
  f:close()
  files[#files + 1] = pvd
  local count, found = 0, 0
  for name in text:gmatch('<DataSet [^>]*file="([^"]+)"') do
    count = count + 1
    local g = io.open(dir .. "/" .. name)
    if g then
      found = found + 1
      local head = g:read(400)
      g:close()
      T.assert_true(head:find('NumberOfPoints="' .. base:info().vertices .. '"', 1, true) ~= nil,
                    name .. " is a snapshot of the cluster")
      files[#files + 1] = dir .. "/" .. name
    end
  end
  T.assert_equal(count, want, ("steps = %d, every = %d: DataSets"):format(steps, every))
  T.assert_equal(found, want, "every listed .vtu exists")
  local times = {}
  for t in text:gmatch('timestep="([^"]+)"') do times[#times + 1] = tonumber(t) end
  T.assert_true(times[1] == 0 and math.abs(times[#times] - steps * tau) < 1e-15,
                "snapshots from t = 0 to the end")
end
pvd_check(5, 2, 4) -- t = 0, steps 2 and 4, and the last step 5
pvd_check(4, 2, 3) -- t = 0, steps 2 and 4 (the last is not repeated)
pvd_check(3, 0, 2) -- every = 0: first and last only
for _, f in ipairs(files) do os.remove(f) end
os.remove(dir)

-- Errors, with the cluster unchanged.
-- T-runs end exactly at t0 + T even when the summed steps fall short by round-off
-- (ten steps of 0.1 add up to 0.9999999999999999).
do
  local s = froth.has("gmsh") and froth.sphere{h = 0.3}
  if s then
    local r = s:evolve{flow = "sd", tau = 0.1, T = 1, progress = false}
    T.assert_equal(r.t, 1, "T = 1 in steps of 0.1 ends exactly at 1")
    T.assert_equal(r.steps, 10, "ten steps")
    T.assert_equal(s:time(), 1, "cluster time exactly 1")
  end
end

c = base:clone()
local E = c:energy()
local function bad(text, opts) T.check_error(text, c.evolve, c, opts) end
bad("evolve: option 'T' and option 'steps' exclude each other", {flow = "sd", tau = tau, T = 1, steps = 1})
bad("evolve: option 'T' or option 'steps' is required", {flow = "sd", tau = tau})
bad("evolve: every must be >= 0", {flow = "sd", tau = tau, steps = 1, every = -1})
bad("evolve: option 'on_step' must be a function", {flow = "sd", tau = tau, steps = 1, on_step = 5})
bad("evolve: option 'steps' must be >= 0", {flow = "sd", tau = tau, steps = -1})
bad("evolve: option 'steps' must be an integer", {flow = "sd", tau = tau, steps = 1.5})
bad("evolve: option 'every' must be an integer", {flow = "sd", tau = tau, steps = 1, every = "x"})
bad("evolve: tau must be positive and finite, got 0", {flow = "sd", tau = 0, steps = 1})
bad("evolve: option 'tau' is required", {flow = "sd", steps = 1})
bad("evolve: option 'T' must be positive and finite", {flow = "sd", tau = tau, T = 0})
bad("evolve: option 'T' must be positive and finite", {flow = "sd", tau = tau, T = math.huge})
bad("evolve: option 'T' must be positive and finite", {flow = "sd", tau = tau, T = -1})
bad("evolve: option 'T' must be positive and finite", {flow = "sd", tau = tau, T = 0 / 0})
bad("evolve: option 'steps' is out of range", {flow = "sd", tau = tau, steps = 4294967296})
bad("step: unknown flow 'xyz'", {flow = "xyz", tau = tau, steps = 1})
bad("evolve: unknown option 'bogus'", {flow = "sd", tau = tau, steps = 1, bogus = true})
bad("evolve: option 'output' must be a string", {flow = "sd", tau = tau, steps = 1, output = 1})
bad("evolve: option 'progress' must be true or false", {flow = "sd", tau = tau, steps = 1, progress = 1})
bad("pvd: 'x.vtu' is not a .pvd file name", {flow = "sd", tau = tau, steps = 1, output = "x.vtu"})
bad("evolve: expected an option table {...}, got string", "sd")
T.assert_true(c:time() == 0 and c:energy() == E, "failed evolves leave the cluster")

T.summary()
