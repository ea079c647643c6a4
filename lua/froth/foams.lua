-- froth.foams: periodic foams on froth.voronoi_foam (the Voronoi foam of given sites in a
-- periodic box, foams/foam.h). Kelvin's foam is the Voronoi foam of the BCC lattice (two
-- truncated octahedra a cubic period), Weaire-Phelan's that of the A15 lattice (two pentagonal
-- dodecahedra and six 14-hedra a cubic period, Weaire and Phelan, Phil. Mag. Lett. 69, 1994).
-- Copied into the froth table at startup like the named clusters; needs no gmsh.
local M = {}

local check = require("froth.options")
local fail, options, positive, number = check.fail, check.options, check.positive, check.number

-- The cubic period of side a and the sites of a lattice given on the cube of side 4.
local function scaled(sites4, a)
  local out = {}
  for i, p in ipairs(sites4) do out[i] = {p[1] * a / 4, p[2] * a / 4, p[3] * a / 4} end
  return out, {{a, 0, 0}, {0, a, 0}, {0, 0, a}}
end

local function lattice_foam(name, opts, sites4)
  opts = options(name, opts, {h = true, volume = true})
  local volume = positive(name, opts, "volume", 1)
  local side = (#sites4 * volume) ^ (1 / 3)
  local h = positive(name, opts, "h", 0.25 * volume ^ (1 / 3))
  local sites, period = scaled(sites4, side)
  local c = froth.voronoi_foam{sites = sites, period = period, h = h}
  for b = 1, c:info().bodies do c:set_volume(b, volume) end -- equal cells (A15's are not yet)
  return c
end

--- froth.kelvin_foam{h = 0.25 V^(1/3), volume = 1}: Kelvin's foam, two cells of the given
--- volume in a cubic period, flat faces until minimized.
function M.kelvin_foam(opts)
  return lattice_foam("kelvin_foam", opts, {{0, 0, 0}, {2, 2, 2}})
end

--- froth.weaire_phelan_foam{h = 0.25 V^(1/3), volume = 1}: the Weaire-Phelan foam, eight
--- cells (sites 1-2 the dodecahedra, 3-8 the 14-hedra) whose target volumes are all `volume`;
--- the flat Voronoi cells start at unequal volumes, c:minimize{} equalises them.
function M.weaire_phelan_foam(opts)
  return lattice_foam("weaire_phelan_foam", opts, {
    {0, 0, 0}, {2, 2, 2},
    {1, 0, 2}, {3, 0, 2}, {0, 2, 1}, {0, 2, 3}, {2, 1, 0}, {2, 3, 0},
  })
end

--- froth.foam{n = 64, seed = 1, volume = 1, h = 0.25 V^(1/3), equal_volumes = true, lloyd = 0,
--- mesher = "gmsh" (with gmsh, else "fan")}: the Voronoi foam of n uniformly random sites in a
--- periodic cube of volume n V (Lua's generator, seeded: the same sites on every machine), the
--- sites first moved `lloyd` times to their cells' centroids; with equal_volumes the target
--- volume of every cell is V (c:minimize{} then equalises them), else each keeps its Voronoi
--- volume.
function M.foam(opts)
  local name = "foam"
  opts = options(name, opts, {n = true, seed = true, volume = true, h = true, equal_volumes = true,
                              lloyd = true, mesher = true})
  local n = number(name, opts, "n", 64)
  if math.type(n) ~= "integer" or n < 2 then fail(name, "n must be an integer >= 2, got %s", n) end
  local seed = number(name, opts, "seed", 1)
  if math.type(seed) ~= "integer" then fail(name, "seed must be an integer, got %s", seed) end
  local volume = positive(name, opts, "volume", 1)
  local h = positive(name, opts, "h", 0.25 * volume ^ (1 / 3))
  local equal = check.boolean(name, opts, "equal_volumes", true)
  local lloyd = number(name, opts, "lloyd", 0)
  if math.type(lloyd) ~= "integer" or lloyd < 0 or lloyd > 10000 then
    fail(name, "lloyd must be an integer >= 0 and at most 10000, got %s", lloyd)
  end
  local side = (n * volume) ^ (1 / 3)
  local rng = math.random
  math.randomseed(seed)
  local sites = {}
  for i = 1, n do sites[i] = {side * rng(), side * rng(), side * rng()} end
  local mesher = opts.mesher
  if mesher == nil then mesher = froth.has("gmsh") and "gmsh" or "fan" end
  if mesher ~= "gmsh" and mesher ~= "fan" then
    fail(name, "mesher must be \"gmsh\" or \"fan\", got %s", tostring(mesher))
  end
  local period = {{side, 0, 0}, {0, side, 0}, {0, 0, side}}
  local c = froth.voronoi_foam{sites = sites, period = period, h = h, lloyd = lloyd, mesher = mesher}
  if equal then
    for b = 1, n do c:set_volume(b, volume) end
  end
  return c
end

return M
