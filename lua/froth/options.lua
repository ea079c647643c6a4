-- froth.options: option-table checks for builders written in Lua (froth.clusters,
-- froth.wall_clusters), with the messages of the C builders: errors start with the builder's
-- name and carry no position, unknown keys and wrong types are rejected.
local M = {}

--- Raises "<name>: <formatted message>" without a position.
function M.fail(name, fmt, ...)
  error(name .. ": " .. fmt:format(...), 0)
end

--- The option table (or {} for nil), checked against the set of known keys.
function M.options(name, opts, known)
  if opts == nil then return {} end
  if type(opts) ~= "table" then
    M.fail(name, "expected an option table {...}, got %s", type(opts))
  end
  for k in pairs(opts) do
    if type(k) ~= "string" then M.fail(name, "option keys must be names") end
    if not known[k] then M.fail(name, "unknown option '%s'", k) end
  end
  return opts
end

--- opts[key] as a number, or default when absent.
function M.number(name, opts, key, default)
  local v = opts[key]
  if v == nil then return default end
  if math.type(v) == nil then M.fail(name, "option '%s' must be a number", key) end
  return v
end

--- opts[key] as a finite positive number, or default when absent.
function M.positive(name, opts, key, default)
  local v = M.number(name, opts, key, default)
  if not (v > 0 and v < math.huge) then M.fail(name, "%s must be positive, got %s", key, v) end
  return v
end

--- opts[key] as a boolean, or default when absent.
function M.boolean(name, opts, key, default)
  local v = opts[key]
  if v == nil then return default end
  if type(v) ~= "boolean" then M.fail(name, "option '%s' must be true or false", key) end
  return v
end

--- opts[key] as one of the strings in `choices` (an array), or default when absent.
function M.choice(name, opts, key, choices, default)
  local v = opts[key]
  if v == nil then return default end
  for _, c in ipairs(choices) do
    if v == c then return v end
  end
  M.fail(name, "option '%s' must be \"%s\", got %s", key, table.concat(choices, "\" or \""),
         type(v) == "string" and ("'" .. v .. "'") or type(v))
end

return M
