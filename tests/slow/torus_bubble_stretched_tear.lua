-- Slow regression: the seed's stretched torus bubble (§5.1.1, Fig. 9: R = 2, r = 0.5, then
-- the stretchings G1, G2) under surface diffusion. The seed: "the instability ... results in
-- the thinning of the toroidal ring at one point", tearing at t ~ 0.91. For both layouts of
-- froth.torus_bubble (docs/lua_api.md) at h = 0.17, tau = 1e-3 after a start ramp.
-- Required: the run ends with a topology stop before T = 1 (after the seed's 0.91 would
-- contradict it), on a film of the ring (surface 3 or 4); at the end the ring's thinnest
-- cross-section (its height in z, initially 2r = 1 all round) is under half its start and lies
-- at azimuth 90-180 degrees, where G1 lengthens the ring, while elsewhere the ring keeps at
-- least its initial height (thinning at one point, not all round); energy never increases;
-- volume loss <= 0.3% (the ramp from 90-degree junctions costs the most).
-- Measured when written (h = 0.17): "ball" (3151 vertices) stops at t = 0.269 with the ring
-- 0.28 high at azimuth 120-130 degrees, "halves" (3748) at t = 0.630, 0.19 high at 110-120;
-- 50 s for both. The seed's 0.91 is reached by neither (datafiles/torus_bubble_stretched.lua).
local T = require("froth.test")

-- The ring's vertices: those on or inside the closed tube before stretching (the stretched
-- mesh has the unstretched one's vertex numbering).
local function ring_vertices(layout, h)
  local plain = froth.torus_bubble{layout = layout, r = 0.5, h = h}
  local ring = {}
  for v = 1, plain:info().vertices do
    local x = plain:vertex(v)
    local rho = math.sqrt(x[1] ^ 2 + x[2] ^ 2)
    if (2 - rho) ^ 2 + x[3] ^ 2 <= 0.25 + 1e-6 then ring[#ring + 1] = v end
  end
  return ring
end

-- Height in z of the ring in 36 azimuth sectors about the z axis.
local function heights(c, ring)
  local lo, hi = {}, {}
  for _, v in ipairs(ring) do
    local x = c:vertex(v)
    local k = math.floor((math.atan(x[2], x[1]) % (2 * math.pi)) / (2 * math.pi) * 36) + 1
    lo[k], hi[k] = math.min(lo[k] or x[3], x[3]), math.max(hi[k] or x[3], x[3])
  end
  local out = {}
  for k = 1, 36 do out[k] = hi[k] - lo[k] end
  return out
end

for _, layout in ipairs({"ball", "halves"}) do
  local h = 0.17
  local ring = ring_vertices(layout, h)
  local c = froth.torus_bubble{layout = layout, r = 0.5, h = h, stretch = true}
  T.assert_true(#ring > 0.2 * c:info().vertices, layout .. ": ring vertices found", #ring)
  local r = c:evolve{flow = "sd", exact_volumes = false, tau = 1e-3, tau_start = 1e-7, T = 1, progress = false}
  local hz = heights(c, ring)
  local thin, thick = 1, 1
  for k = 2, 36 do
    if hz[k] < hz[thin] then thin = k end
    if hz[k] > hz[thick] then thick = k end
  end
  print(("%-6s %d vertices: t = %.3f (seed 0.91), %s; ring height %.3f at azimuth %d-%d deg,"
         .. " up to %.3f; volume loss %.3f%%, %.0f s"):format(layout, c:info().vertices, r.t,
         r.stop_reason, hz[thin], 10 * (thin - 1), 10 * thin, hz[thick], 100 * r.volume_loss,
         r.wall_s))
  T.assert_true(r.stop_reason:find("^topology: ") ~= nil, layout .. ": a topology stop", r.stop_reason)
  local surface = tonumber(r.event and r.event.message:match("of surface (%d+)"))
  T.assert_true(surface == 3 or surface == 4, layout .. ": on a film of the ring", r.stop_reason)
  T.assert_true(hz[thin] < 0.5, layout .. ": the ring is thinner than half its height", hz[thin])
  T.assert_true(thin >= 10 and thin <= 18, layout .. ": thinnest at azimuth 90-180 degrees",
                10 * (thin - 1))
  T.assert_true(hz[thick] >= 1, layout .. ": elsewhere the ring keeps its height", hz[thick])
  T.assert_true(r.max_energy_increase <= 0, layout .. ": energy non-increasing",
                tostring(r.max_energy_increase))
  T.assert_true(r.volume_loss <= 0.003, layout .. ": volume loss <= 0.3%", r.volume_loss)
end
T.summary()
