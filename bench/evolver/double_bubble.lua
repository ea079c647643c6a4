-- froth: the double bubble from two unit cubes (froth.fragment), surface diffusion to T with a
-- start ramp, at several h; prints vertices, steps, seconds, the area's error against the
-- standard double bubble of the final volumes, and the volume loss. Compare: double_bubble.cmd.
--   froth bench/evolver/double_bubble.lua [tau=0.02] [T=1.5] [hs=0.1,0.05]
local opts = require("froth.script").options({tau = 0.02, T = 1.5, hs = "0.1,0.05"}, arg)
print("froth  h       vertices  steps  seconds  area          error      volume loss")
for h in tostring(opts.hs):gmatch("[^,]+") do
  h = tonumber(h)
  local c = froth.fragment{solids = {{"box", min = {0, 0, 0}, size = {1, 1, 1}},
                                     {"box", min = {1, 0, 0}, size = {1, 1, 1}}}, h = h}
  local r = c:evolve{flow = "sd", exact_volumes = false, tau = opts.tau, tau_start = 1e-6, T = opts.T, progress = false}
  local V = c:volumes()
  local exact = 3 * (9 * math.pi) ^ (1 / 3) * ((V[1] + V[2]) / 2) ^ (2 / 3)
  print(("froth  %-6g  %8d  %5d  %7.2f  %.10f  %.3e  %.2e"):format(h, c:info().vertices, r.steps,
        r.wall_s, r.energy, (r.energy - exact) / exact, r.volume_loss))
end
