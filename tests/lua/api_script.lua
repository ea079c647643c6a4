-- froth.script, the datafiles' helpers: options (key=value words over defaults, numbers kept
-- as numbers, errors on unknown keys and on words without '='), keys, evolve_options (T and
-- files for a run, 3 steps and no files for a smoke run) and its use in a real evolve.
local T = require("froth.test")
local check_error, eq, yes = T.check_error, T.assert_equal, T.assert_true
local script = require("froth.script")

local defaults = {h = 0.08, T = 1, output = "out/x.pvd", name = "a"}
local opts = script.options(defaults, {"h=0.1", "output=", "name=7b"})
eq(opts.h, 0.1, "a number word becomes a number")
eq(math.type(opts.h), "float", "h is a float")
eq(opts.output, "", "an empty value stays an empty string")
eq(opts.name, "7b", "a word that is not a number stays a string")
eq(opts.T, 1, "defaults fill the rest")
eq(defaults.h, 0.08, "the defaults are not changed")
eq(opts.smoke, os.getenv("FROTH_SMOKE") == "1", "smoke follows FROTH_SMOKE")
eq(script.options({tau = 1}, nil).tau, 1, "no arguments: the defaults")
check_error("unknown option 'x' (known: T, h, name, output)", script.options, defaults, {"x=1"})
check_error("bad argument 'h' (expected key=value, keys: T, h, name, output)", script.options,
            defaults, {"h"})
eq(script.keys({b = 1, a = 2}), "a, b", "keys are sorted and comma-separated")

-- evolve_options: a run gets T and its files, a smoke run 3 steps and none; fields are copied.
local fields = {flow = "sd", tau = 1e-3}
local run = script.evolve_options({T = 0.5, output = "o.pvd", history = "h"}, fields)
eq(run.T, 0.5, "a run ends at T")
eq(run.steps, nil, "a run has no step count")
eq(run.output, "o.pvd", "a run writes its output")
eq(run.history, "h", "a run records its history")
eq(run.flow, "sd", "the fields are kept")
eq(fields.T, nil, "the fields table is not changed")
local quiet = script.evolve_options({T = 0.5, output = "", history = ""}, fields)
eq(quiet.output, nil, "output = '' writes nothing")
eq(quiet.history, nil, "history = '' records nothing")
local smoke = script.evolve_options({smoke = true, T = 0.5, output = "o.pvd", history = "h"},
                                    fields)
eq(smoke.steps, 3, "a smoke run takes 3 steps")
yes(smoke.T == nil and smoke.output == nil and smoke.history == nil,
    "a smoke run has no T and writes no files")

-- In a real evolve: the smoke options take exactly 3 steps.
local c = froth.half_ellipsoid_on_plane{levels = 2}
local r = c:evolve(script.evolve_options({smoke = true}, {flow = "mcf", tau = 1e-3}))
eq(r.steps, 3, "evolve with smoke options: 3 steps")
eq(r.stop_reason, "steps done", "evolve with smoke options: stopped by the step count")
T.summary()
