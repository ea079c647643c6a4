--- help(topic): the entry of docs/lua_api.md for a function or method, printed in the REPL.
--
--   help()                      -- what to type first
--   help("evolve")              -- the c:evolve section (also "c:evolve")
--   help(froth.double_bubble)   -- a function of the froth table, by value
--   help("energy")              -- a table row ("| `c:energy()` | ...") when there is no section
--
-- The text is read from the installed manual (share/doc/froth/lua_api.md beside the prefix)
-- or the source tree's docs/lua_api.md, the same file the documentation is, so help cannot
-- drift from it.
local M = {}

local intro = [[
froth -- surface clusters by parametric FEM (plain Lua 5.4 plus the 'froth' table)
  c = froth.double_bubble{h = 0.1}         -- two half balls (seed 5.1.1, gmsh)
  print(c)                                  -- counts; c:energy(), c:volumes()
  r = c:step{flow = "mcf", tau = 1e-3}      -- one step ("sd": surface diffusion)
  r = c:evolve{flow = "sd", tau = 1e-3, steps = 100}  -- Ctrl-C stops it between steps
  r = c:minimize{}                          -- the equilibrium at fixed volumes
  froth.<TAB>   c:<TAB>                     -- complete functions and methods
help("evolve"), help(froth.fragment): that entry of the manual (docs/lua_api.md).
Examples: datafiles/*.lua (run: froth file.lua).]]

local function manual_lines()
  local path = froth._manual
  local f = path and io.open(path)
  if not f then return nil end
  local lines = {}
  for line in f:lines() do lines[#lines + 1] = line end
  f:close()
  return lines
end

-- The name a function has in the froth table or in the methods of froth's userdata.
local function name_of(fn)
  for k, v in pairs(froth) do
    if v == fn then return k end
  end
  local samples = {froth.plane{}, froth.anisotropy{{G = {1, 1, 1}}},
                   froth.box_cells{x = {0, 1}, y = {0, 1}, z = {0, 1}, cell = function() return 1 end}}
  for _, obj in ipairs(samples) do
    local index = debug.getmetatable(obj).__index
    for k, v in pairs(index) do
      if v == fn then return k end
    end
  end
  return nil
end

-- "froth.read", "c:evolve", "evolve" -> "read" / "evolve"
local function bare(topic)
  return (topic:gsub("^froth%.", ""):gsub("^c:", ""):gsub("^g:", ""):gsub("^w:", ""))
end

local function mentions(line, name)
  for _, prefix in ipairs{"froth.", "c:", "g:", "w:", ""} do
    local s, e = line:find(prefix .. name, 1, true)
    while s do
      local before, after = line:sub(s - 1, s - 1), line:sub(e + 1, e + 1)
      local starts = prefix ~= "" or before == "" or before:match("[%s`]")
      if starts and not after:match("[%w_]") then return true end
      s, e = line:find(prefix .. name, e + 1, true)
    end
  end
  return false
end

--- The manual's text for topic (a string or a froth function), or nil and why.
function M.text(topic)
  if type(topic) == "function" then
    local name = name_of(topic)
    if not name then return nil, "help: this function is not part of froth's API" end
    topic = name
  end
  if type(topic) ~= "string" then
    return nil, "help: expected a name (\"evolve\") or a froth function, got " .. type(topic)
  end
  local lines = manual_lines()
  if not lines then
    return nil, "help: the manual lua_api.md was not found (looked for " ..
                tostring(froth._manual_searched) .. ")"
  end
  local name = bare(topic)
  for i, line in ipairs(lines) do -- a section whose heading names it
    local level = line:match("^(#+) ")
    if level and #level >= 3 and mentions(line, name) then
      local out = {line}
      for j = i + 1, #lines do
        local l2 = lines[j]:match("^(#+) ")
        if l2 and #l2 <= #level then break end
        out[#out + 1] = lines[j]
      end
      return table.concat(out, "\n")
    end
  end
  for _, line in ipairs(lines) do -- a table row that starts with it
    local cell = line:match("^| `([^`]*)`")
    if cell and mentions(cell, name) then return line end
  end
  return nil, "help: nothing in the manual about '" .. topic .. "' (try help() or see lua_api.md)"
end

function M.help(topic)
  if topic == nil then
    print(intro)
    return
  end
  local text, why = M.text(topic)
  print(text or why)
end

return M
