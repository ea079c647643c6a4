-- evolve's topology watch, history files and start ramp, as a script sees them.
local T = require("froth.test")
if not froth.has("gmsh") then
  T.assert_true(true, "skipped: no gmsh")
  return T.summary()
end

-- 1. A sphere under MCF vanishes at t = R^2/4 = 0.25: the watch stops the run just before.
local s = froth.sphere{h = 0.3}
local r = s:evolve{flow = "mcf", tau = 1e-3, T = 0.4, progress = false}
T.assert_equal(r.event and r.event.kind, "vanishing body", "event kind")
T.assert_true(math.abs(r.t - 0.25) < 0.01, "stops near the extinction time 0.25", tostring(r.t))
T.assert_equal(r.event.t, s:time(), "event time is the time of the kept state")
T.assert_equal(r.stop_reason, "topology: " .. r.event.message, "stop_reason carries the message")
T.assert_true(r.event.message:find("body 1 is vanishing", 1, true) ~= nil, "names the body",
              r.event.message)
T.assert_true(s:volumes()[1] > 0, "a valid state is kept")

-- the same run with the watch off goes on until a step cannot be taken
local s2 = froth.sphere{h = 0.3}
local r2 = s2:evolve{flow = "mcf", tau = 1e-3, T = 0.4, progress = false, watch = false}
T.assert_true(r2.t > r.t, "without the watch the run goes further", tostring(r2.t))

-- 2. History files: one row per state, CSV and SVG.
local dir = os.tmpname()
os.remove(dir)
local d = froth.double_bubble{h = 0.3}
local rd = d:evolve{flow = "sd", tau = 1e-3, steps = 4, history = dir .. "/db", progress = false}
local rows = {}
for line in io.lines(dir .. "/db.csv") do rows[#rows + 1] = line end
T.assert_equal(rows[1], "t,tau,energy,volume_loss,V1,V2", "CSV header")
T.assert_equal(#rows, 1 + 5, "the start and 4 steps")
local t_last, tau_last, e_last = rows[#rows]:match("^([^,]+),([^,]+),([^,]+),")
T.assert_equal(tonumber(t_last), rd.t, "last row time")
T.assert_equal(tonumber(tau_last), 1e-3, "last row tau")
T.assert_equal(tonumber(rows[2]:match("^[^,]+,([^,]+),")), 0, "the start row has tau 0")
T.assert_equal(tonumber(rows[3]:match("^[^,]+,([^,]+),")), 1e-3, "a step row has its tau")
T.assert_equal(tonumber(e_last), rd.energy, "last row energy (round-trip exact)")
local svg = io.open(dir .. "/db.svg"):read("a")
T.assert_true(svg:find("<polyline", 1, true) ~= nil, "the SVG has the energy curve")

-- 3. A start ramp: the first step is tau_start, each next one tau_growth times longer.
local d2 = froth.double_bubble{h = 0.3}
local taus = {}
local r3 = d2:evolve{flow = "sd", tau = 1e-3, T = 5e-3, tau_start = 1e-5, tau_growth = 2,
                     progress = false, on_step = function(step) taus[#taus + 1] = step.tau end}
T.assert_near(taus[1], 1e-5, 1e-20, "first step is tau_start")
T.assert_near(taus[2], 2e-5, 1e-20, "then doubled")
T.assert_near(taus[8], 1e-3, 1e-20, "capped at tau")
T.assert_equal(r3.t, 5e-3, "a T-run still ends exactly at T")

-- 4. Bad watch, history and ramp options are errors that change nothing.
local c = froth.double_bubble{h = 0.3}
local function bad(text, opts) T.check_error(text, c.evolve, c, opts) end
bad("evolve: watch: unknown option 'x'", {flow = "sd", tau = 1e-3, steps = 1, watch = {x = 1}})
bad("evolve: option 'watch' must be false or a table", {flow = "sd", tau = 1e-3, steps = 1, watch = 1})
bad("evolve: watch thresholds must be", {flow = "sd", tau = 1e-3, steps = 1,
    watch = {min_volume_fraction = 2}})
bad("evolve: tau_start must be in (0, tau]", {flow = "sd", tau = 1e-3, steps = 1, tau_start = 1})
bad("evolve: tau_growth must be in (1, 10]", {flow = "sd", tau = 1e-3, steps = 1,
    tau_start = 1e-4, tau_growth = 0.5})
bad("history: cannot", {flow = "sd", tau = 1e-3, steps = 1, history = "/proc/froth/x"})
T.assert_equal(c:time(), 0, "failed calls took no step (a bad history path fails first)")
T.summary()
