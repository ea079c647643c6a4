-- bench/bench_walls.lua — the cost of walls (issue 4): the seed's cube on a plane (§5.1.4)
-- evolved by surface diffusion towards a half sphere, against the same cube without the plane
-- (a closed cube becoming a sphere), at several mesh sizes. Prints markdown table rows for
-- docs/benchmarks.md: vertices, steps, seconds per step, and the errors at the end (area against
-- the half sphere of the same discrete volume, worst contact angle, volume loss, wall drift).
--
--   build-bench/froth bench/bench_walls.lua                 (about two minutes on 2 cores)
--   build-bench/froth bench/bench_walls.lua hs=0.1 T=0.05   (shorter)
local script = require("froth.script")
local opts = script.options({hs = "0.1,0.07,0.05", tau = 1e-3, T = 0.3}, arg)

local function run(h, walls)
  local box = {"box", min = {-0.5, -0.5, walls and 0 or -0.5}, size = {1, 1, 1}}
  local c = froth.fragment{solids = {box}, h = h, walls = walls and froth.plane{} or nil}
  local r = c:evolve{flow = "sd", exact_volumes = false, tau = opts.tau, tau_start = 1e-7, T = opts.T, progress = false}
  local V = c:volumes()[1]
  -- the half sphere of volume V has area 2 pi R^2 with 2/3 pi R^3 = V; the sphere 4 pi R^2
  local exact = walls and 2 * math.pi * (3 * V / (2 * math.pi)) ^ (2 / 3)
                      or 4 * math.pi * (3 * V / (4 * math.pi)) ^ (2 / 3)
  return c:info().vertices, r, 100 * (r.energy / exact - 1)
end

print(("SD, tau = %g after a ramp from 1e-7, T = %g; wall s from the engine (steps + reports)")
      :format(opts.tau, opts.T))
print("| scene | h | vertices | steps | s/step | area error | contact angles | volume loss | wall drift |")
print("|---|--:|--:|--:|--:|--:|--:|--:|--:|")
for h in tostring(opts.hs):gmatch("[^,]+") do
  h = tonumber(h)
  for _, walls in ipairs({true, false}) do
    local n, r, err = run(h, walls)
    print(("| %s | %g | %d | %d | %.4f | %+.3f%% | %s | %.3f%% | %s |"):format(
      walls and "cube on plane" or "closed cube", h, n, r.steps, r.wall_s / r.steps, err,
      walls and ("%.2f..%.2f"):format(r.contact_angles.min, r.contact_angles.max) or "-",
      100 * r.volume_loss, walls and ("%.0e"):format(r.wall_drift) or "-"))
  end
end
