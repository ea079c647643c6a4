-- Unconditional stability (Theorems 3.2 and 3.4): the default double bubble stepped with
-- tau = 1 and tau = 10, ten steps each, keeps the energy non-increasing at every step and
-- never produces NaN. Mean curvature flow with such steps shrinks the closed cluster to a
-- point: then the next step must fail with a clear error and leave the cluster unchanged.
local T = require("froth.test")

local function is_finite(x) return x == x and x ~= math.huge and x ~= -math.huge end

for _, flow in ipairs{"sd", "mcf"} do
  for _, tau in ipairs{1, 10} do
    local c = froth.double_bubble{h = 0.08}
    local what = ("%s tau=%g"):format(flow, tau)
    local finite, monotone, steps = true, true, 0
    for _ = 1, 10 do
      local before_t, before_e = c:time(), c:energy()
      local ok, s = pcall(c.step, c, {flow = flow, tau = tau, exact_volumes = false})
      if not ok then
        T.assert_equal(flow, "mcf", what .. ": only MCF may stop (" .. tostring(s) .. ")")
        T.assert_true(tostring(s):find("collapsed to a point", 1, true) ~= nil or
                      tostring(s):find("would vanish", 1, true) ~= nil,
                      what .. ": the error says why", tostring(s))
        T.assert_equal(c:time(), before_t, what .. ": time unchanged after the failed step")
        T.assert_equal(c:energy(), before_e, what .. ": cluster unchanged after the failed step")
        break
      end
      steps = steps + 1
      finite = finite and is_finite(s.energy) and is_finite(s.volumes[1]) and is_finite(s.volumes[2])
      monotone = monotone and s.energy <= s.energy_before * (1 + 1e-13)
    end
    T.assert_true(finite, what .. ": no NaN or Inf")
    T.assert_true(monotone, what .. ": energy non-increasing at every step")
    if flow == "sd" then
      T.assert_equal(steps, 10, what .. ": surface diffusion takes all ten steps")
      -- one huge step conserves volume only to first order; the loss must stay bounded
      local r = c:report()
      T.assert_true(r.volume_loss < 0.05, what .. ": volume loss bounded", tostring(r.volume_loss))
    end
  end
end
T.summary()
