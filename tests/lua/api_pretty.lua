-- froth.pretty.format: what the REPL prints for table results (exact strings).
local T = require("froth.test")
local P = require("froth.pretty")
T.assert_equal(P.format({t = 0.1, volumes = {2.08, 2.08}}), "{t = 0.1, volumes = {2.08, 2.08}}", "record with an array")
T.assert_equal(P.format({1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13}),
               "{1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, ... (13 items)}", "long arrays are cut")
T.assert_equal(P.format({}), "{}", "empty")
T.assert_equal(P.format({b = 1, a = "x", [3] = true}), '{[3] = true, a = "x", b = 1}', "keys sorted, numbers first")
T.assert_equal(P.format({1 / 3, 0 / 0, math.huge, -math.huge, 7}), "{0.3333333333, nan, inf, -inf, 7}", "numbers")
local t = {}
t.self = t
T.assert_equal(P.format(t), "{self = <cycle>}", "cycles")
T.assert_equal(P.format({a = {b = {c = {d = 1}}}}), "{a = {b = {c = {...}}}}", "depth limit")
T.assert_equal(P.format(setmetatable({}, {__tostring = function() return "custom" end})), "custom", "__tostring wins")
T.assert_equal(P.format({froth.plane{}}), "{froth.Wall (plane (0, 0, 1) . x = 0)}", "userdata by tostring")
local long = P.format({alpha = 1.5, beta = {1, 2, 3}, gamma = "a long string to push the line past the width",
                       delta = 4, epsilon = 5})
T.assert_equal(long, '{\n  alpha = 1.5,\n  beta = {1, 2, 3},\n  delta = 4,\n  epsilon = 5,\n' ..
               '  gamma = "a long string to push the line past the width"\n}', "one field per line when too wide")
T.assert_equal(P.format({x = 1}, {width = 3}), "{\n  x = 1\n}", "width option")
T.assert_equal(P.format(42), "42", "non-tables as scalars")
T.summary()
