-- froth.script: small helpers for datafiles.
--   local opts = require("froth.script").options({h = 0.08, T = 1}, arg)
-- reads key=value words from the command line (numbers stay numbers) over the defaults and
-- errors on unknown keys, so `froth datafiles/double_bubble.lua h=0.1 T=0.2` just works.
-- FROTH_SMOKE=1 in the environment sets opts.smoke = true: datafiles then take a few steps only.
local M = {}

function M.options(defaults, argv)
  local opts = {}
  for k, v in pairs(defaults) do opts[k] = v end
  for i = 1, #(argv or {}) do
    local key, value = argv[i]:match("^([%w_]+)=(.*)$")
    if not key then
      error(("bad argument '%s' (expected key=value, keys: %s)"):format(argv[i], M.keys(defaults)), 2)
    end
    if defaults[key] == nil then
      error(("unknown option '%s' (known: %s)"):format(key, M.keys(defaults)), 2)
    end
    opts[key] = tonumber(value) or value
  end
  opts.smoke = os.getenv("FROTH_SMOKE") == "1"
  return opts
end

--- The c:evolve options of a datafile run: `fields` (not changed) plus T = opts.T, and
--- output = opts.output and history = opts.history where those are set and not ""; with
--- opts.smoke instead 3 steps and no files.
function M.evolve_options(opts, fields)
  local o = {}
  for k, v in pairs(fields) do o[k] = v end
  if opts.smoke then
    o.steps = 3
    return o
  end
  o.T = opts.T
  if opts.output ~= "" then o.output = opts.output end
  if opts.history ~= "" then o.history = opts.history end
  return o
end

function M.keys(t)
  local names = {}
  for k in pairs(t) do names[#names + 1] = k end
  table.sort(names)
  return table.concat(names, ", ")
end

return M
