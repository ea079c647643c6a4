-- Soak benchmark (issue 17): many volume-exact SD steps of a small double bubble, with the
-- process's resident memory sampled, to show that nothing grows with the number of steps
-- (factorisations, the warm start, report tables, Lua garbage).
--
--   build/froth bench/bench_soak.lua [steps] [h]      (defaults 20000 and 0.3)
--
-- Prints one row per tenth of the run: steps, seconds, RSS (MiB), energy, max volume error.
-- The figure in docs/benchmarks.md is the growth of RSS from the first row to the last.
local steps = tonumber(arg and arg[1]) or 20000
local h = tonumber(arg and arg[2]) or 0.3

local function rss_mib()
  local f = assert(io.open("/proc/self/status"))
  local kb
  for line in f:lines() do
    kb = kb or tonumber(line:match("^VmRSS:%s+(%d+)"))
  end
  f:close()
  return kb / 1024
end

local c = froth.double_bubble{h = h}
local target = c:target_volumes()
local info = c:info()
print(("soak: double bubble h = %g (%d vertices), %d SD steps of tau = 1e-3, exact volumes"):format(
  h, info.vertices, steps))
print(("%8s %9s %9s %12s %12s"):format("steps", "seconds", "RSS MiB", "energy", "vol. error"))
local t0 = os.clock()
local rows = {}
local every = math.max(1, steps // 10)
for k = 1, steps do
  c:step{flow = "sd", tau = 1e-3}
  if k % every == 0 or k == 1 then
    collectgarbage()
    local v, err = c:volumes(), 0
    for b = 1, #v do err = math.max(err, math.abs(v[b] - target[b]) / target[b]) end
    rows[#rows + 1] = rss_mib()
    print(("%8d %9.1f %9.1f %12.8f %12.2e"):format(k, os.clock() - t0, rows[#rows], c:energy(), err))
  end
end
-- the first row is after one step (before the factor caches exist), so growth is measured
-- from the second sample
local growth = rows[#rows] - rows[2]
print(("RSS growth from step %d to step %d: %.2f MiB"):format(every, steps, growth))
