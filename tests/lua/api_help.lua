-- help(topic) (lua/froth/help.lua): entries come from docs/lua_api.md, and every function of
-- the froth table and every method of froth's objects has one, so the manual covers the API.
local T = require("froth.test")
local H = require("froth.help")

T.assert_true(froth._manual ~= nil and froth._manual:find("lua_api.md", 1, true) ~= nil,
              "the manual is found", tostring(froth._manual_searched))
local e = assert(H.text("evolve"))
T.assert_true(e:find("^### c:evolve{") ~= nil, "help('evolve') is the c:evolve section", e:sub(1, 60))
T.assert_true(e:find("on_step", 1, true) ~= nil and e:find("\n## ", 1, true) == nil,
              "the section's body, up to the next heading")
T.assert_equal(assert(H.text("c:evolve")), e, "help('c:evolve') is the same")
local d = assert(H.text(froth.double_bubble or froth.read))
T.assert_true(d:find("^### froth%.") ~= nil, "help(function) by value", d:sub(1, 60))
local row = assert(H.text("energy"))
T.assert_true(row:find("^| `c:energy%(%)`") ~= nil, "a method documented in a table: its row", row)
local none, why = H.text("no_such_function_xyz")
T.assert_true(none == nil and why:find("nothing in the manual about 'no_such_function_xyz'", 1, true) ~= nil,
              "unknown topics say so", why)
none, why = H.text(42)
T.assert_true(none == nil and why:find("expected a name", 1, true) ~= nil, "a number is not a topic", why)
none, why = H.text(print)
T.assert_true(none == nil and why:find("not part of froth's API", 1, true) ~= nil, "foreign function", why)

-- Coverage: every public function and method is in the manual.
local function covered(where, names)
  for _, name in ipairs(names) do
    T.assert_true(H.text(name) ~= nil, where .. " " .. name .. " is documented in lua_api.md")
  end
end
local function keys(t)
  local r = {}
  for k, v in pairs(t) do
    if type(v) == "function" and not k:find("^_") then r[#r + 1] = k end
  end
  table.sort(r)
  return r
end
covered("froth.", keys(froth))
local cell = froth.box_cells{x = {0, 1}, y = {0, 1}, z = {0, 1}, cell = function() return 1 end}
covered("c:", keys(debug.getmetatable(cell).__index))
covered("wall:", keys(debug.getmetatable(froth.plane{}).__index))
covered("gamma:", keys(debug.getmetatable(froth.anisotropy{{G = {1, 1, 1}}}).__index))
T.summary()
