-- froth.test: the few helpers our Lua tests need (cf. Lua's testes/errors.lua checkerr).
--   local T = require("froth.test")
--   T.check_error("tau must be positive", c.step, c, {flow = "sd", tau = 0})
--   T.assert_near(x, 1.0, 1e-12, "what x is")
--   T.summary()   -- prints "N passed, 0 failed" and exits non-zero on failures
local M = {passed = 0, failed = 0}

local function report(ok, what, detail)
  if ok then
    M.passed = M.passed + 1
  else
    M.failed = M.failed + 1
    io.stderr:write("FAIL: ", what, detail and (": " .. detail) or "", "\n",
                    debug.traceback("", 3), "\n")
  end
  return ok
end

--- Passes if f(...) raises an error whose message contains `text` (plain search).
function M.check_error(text, f, ...)
  local ok, msg = pcall(f, ...)
  if ok then return report(false, "expected an error containing '" .. text .. "'", "no error") end
  msg = tostring(msg)
  return report(msg:find(text, 1, true) ~= nil, "error message", "'" .. msg ..
                "' does not contain '" .. text .. "'")
end

function M.assert_near(actual, expected, tol, what)
  local ok = type(actual) == "number" and math.abs(actual - expected) <= tol
  return report(ok, what or "value", ("%s, expected %s within %g"):format(tostring(actual),
                tostring(expected), tol))
end

function M.assert_true(cond, what, detail)
  return report(cond and true or false, what or "condition", detail)
end

function M.assert_equal(actual, expected, what)
  return report(actual == expected, what or "value",
                ("%s, expected %s"):format(tostring(actual), tostring(expected)))
end

--- Asserts that every quadruple point of c meets four triple-line edges (a Plateau point).
function M.assert_plateau_points(c)
  for _, q in ipairs(c:quadruple_points()) do
    local at = c:edges{where = function(e)
      return e.triple_line and (e.vertices[1] == q or e.vertices[2] == q)
    end}
    M.assert_equal(#at, 4, "quadruple point " .. q .. " meets four triple-line edges")
  end
end

--- Relative difference |a - b| / |b|.
function M.rel(a, b) return math.abs(a - b) / math.abs(b) end

--- A fresh temporary path ending in `suffix`: os.tmpname's name, whose empty file it removes
--- (os.tmpname creates it, and a test that writes name .. suffix would leave it behind).
function M.temp_path(suffix)
  local name = os.tmpname()
  os.remove(name)
  return name .. (suffix or "")
end

--- The positions of all vertices of c, for checking that a failed call changed nothing.
function M.positions(c)
  local X = {}
  for v = 1, c:info().vertices do X[v] = c:vertex(v) end
  return X
end

--- True if c has exactly the positions X (M.positions).
function M.same_positions(c, X)
  for v = 1, c:info().vertices do
    local x = c:vertex(v)
    if x[1] ~= X[v][1] or x[2] ~= X[v][2] or x[3] ~= X[v][3] then return false end
  end
  return #X == c:info().vertices
end

--- The largest coordinate difference between two clusters with the same vertices.
function M.max_difference(a, b)
  local d = 0
  for v = 1, a:info().vertices do
    local x, y = a:vertex(v), b:vertex(v)
    for k = 1, 3 do d = math.max(d, math.abs(x[k] - y[k])) end
  end
  return d
end

--- "surfaces/triple_lines/quadruple_points/bodies" of a cluster, for compact count checks.
function M.counts(c)
  local i = c:info()
  return ("%d/%d/%d/%d"):format(i.surfaces, i.triple_lines, i.quadruple_points, i.bodies)
end

--- Prints the closing line ctest and CI read, and exits 1 if anything failed.
function M.summary()
  print(("%d passed, %d failed"):format(M.passed, M.failed))
  if M.failed > 0 then os.exit(1) end
end

return M
