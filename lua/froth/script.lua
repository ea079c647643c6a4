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

function M.keys(t)
  local names = {}
  for k in pairs(t) do names[#names + 1] = k end
  table.sort(names)
  return table.concat(names, ", ")
end

return M
