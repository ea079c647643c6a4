--- Readable text for Lua values: what the REPL prints for a table result (a report, the result
-- of c:evolve or c:minimize) instead of "table: 0x55d0...".
--
--   pretty.format({t = 0.1, volumes = {2.08, 2.08}})  --> {t = 0.1, volumes = {2.08, 2.08}}
--
-- Arrays print inline (at most 12 items, then "... (n items)"), records with their keys
-- sorted; a line longer than `width` (default 96) breaks into one field per line, indented.
-- Nested tables deeper than `depth` (default 3) print as {...}; a table met again inside
-- itself as <cycle>. Numbers print with up to 10 significant digits, strings quoted.
local M = {}

local function is_array(t)
  local n = #t
  if n == 0 then return false end
  local count = 0
  for _ in pairs(t) do count = count + 1 end
  return count == n
end

local function scalar(v)
  if type(v) == "number" then
    if math.type(v) == "integer" then return tostring(v) end
    if v ~= v then return "nan" end
    if v == math.huge then return "inf" end
    if v == -math.huge then return "-inf" end
    return (("%.10g"):format(v))
  elseif type(v) == "string" then
    return ("%q"):format(v)
  end
  return tostring(v)
end

local function key_text(k)
  if type(k) == "string" and k:match("^[%a_][%w_]*$") then return k end
  return "[" .. scalar(k) .. "]"
end

local function sorted_keys(t)
  local keys = {}
  for k in pairs(t) do keys[#keys + 1] = k end
  table.sort(keys, function(a, b)
    local ta, tb = type(a), type(b)
    if ta ~= tb then return ta == "number" end -- array-like keys first
    if ta == "number" or ta == "string" then return a < b end
    return tostring(a) < tostring(b)
  end)
  return keys
end

local format

local function parts_of(t, opts, level, seen)
  local parts = {}
  if is_array(t) then
    local n = #t
    for i = 1, math.min(n, 12) do parts[i] = format(t[i], opts, level + 1, seen) end
    if n > 12 then parts[#parts + 1] = ("... (%d items)"):format(n) end
  else
    for _, k in ipairs(sorted_keys(t)) do
      parts[#parts + 1] = key_text(k) .. " = " .. format(t[k], opts, level + 1, seen)
    end
  end
  return parts
end

format = function(v, opts, level, seen)
  if type(v) ~= "table" then return scalar(v) end
  local mt = getmetatable(v)
  if mt ~= nil and (type(mt) ~= "table" or mt.__tostring) then return tostring(v) end
  if seen[v] then return "<cycle>" end
  if next(v) == nil then return "{}" end
  if level >= opts.depth then return "{...}" end
  seen[v] = true
  local parts = parts_of(v, opts, level, seen)
  seen[v] = nil
  local line = "{" .. table.concat(parts, ", ") .. "}"
  local indent = ("  "):rep(level)
  if #line + #indent <= opts.width and not line:find("\n", 1, true) then return line end
  return "{\n" .. indent .. "  " .. table.concat(parts, ",\n" .. indent .. "  ") .. "\n" .. indent .. "}"
end

--- The readable text of v; opts: {width = 96, depth = 3}.
function M.format(v, opts)
  opts = opts or {}
  return format(v, {width = opts.width or 96, depth = opts.depth or 3}, 0, {})
end

return M
