-- froth.measure: measurements of clusters that datafiles and tests share.
--   local measure = require("froth.measure")
--   local mean, lo, hi = measure.axis_distances(c)
local M = {}

--- Mean, smallest and largest distance of the cluster's vertices from the x3 axis; with
--- `keep(x)` (x = {x1, x2, x3}) only over the vertices it accepts (nil if it accepts none).
function M.axis_distances(c, keep)
  local n, sum, lo, hi = 0, 0, math.huge, -math.huge
  for v = 1, c:info().vertices do
    local x = c:vertex(v)
    if not keep or keep(x) then
      local d = math.sqrt(x[1] ^ 2 + x[2] ^ 2)
      n, sum, lo, hi = n + 1, sum + d, math.min(lo, d), math.max(hi, d)
    end
  end
  if n == 0 then return nil end
  return sum / n, lo, hi
end

return M
