-- froth.wall_clusters: the seed's surfaces attached to an external boundary (§5.1.4, Figs.
-- 14-15, (5.3)) and a drop on a curved wall, built on froth.fragment{walls = ...}. The froth
-- executable copies every function of this module into the froth table at startup (in builds
-- with gmsh), so scripts call froth.cube_on_plane{...}, froth.cylinder_in_slab{...}, ...
-- Each builder meshes a solid, drops the faces resting on its walls (the lids) and returns the
-- cluster with the walls attached: the films' free edges lie on the walls.
-- See docs/lua_api.md "Named clusters on walls" for the options and the seed's numbers.
local M = {}

local pi = math.pi
local check = require("froth.options")
local fail, options, number, positive = check.fail, check.options, check.number, check.positive

-- The mesh size: h, or about `vertices` vertices on the films that remain. fragment aims its
-- vertex count at the films *and* the lids on the walls, so the count asked of it is scaled by
-- (all faces) / (films) = `lid_factor`.
local function size(name, opts, default_vertices, lid_factor)
  local h = number(name, opts, "h", nil)
  local n = number(name, opts, "vertices", nil)
  if h ~= nil and n ~= nil then fail(name, "give h or vertices, not both") end
  if h ~= nil then return {h = h} end
  n = n or default_vertices
  if math.type(n) ~= "integer" and n ~= math.floor(n) then
    fail(name, "option 'vertices' must be an integer")
  end
  if n < 100 then fail(name, "vertices must be at least 100, got %s", n) end
  return {vertices = math.floor(n * lid_factor + 0.5)}
end

-- froth.fragment with its messages renamed ("fragment: ..." -> "cube_on_plane: ...").
local function fragment(name, args, sz)
  local froth = require("froth")
  args.h, args.vertices = sz.h, sz.vertices
  local ok, result = pcall(froth.fragment, args)
  if ok then return result end
  local msg = tostring(result)
  error((msg:gsub("^fragment:", name .. ":", 1)), 0)
end

--- Unit cube on a plane (seed §5.1.4, Fig. 14 left; D = R^2 x (0, inf)): the cube
--- [-s/2, s/2]^2 x [0, s] with its bottom face on the wall x3 = 0; one surface (the other five
--- faces), one body. Under surface diffusion it becomes the half sphere of the same volume,
--- meeting the plane at 90 degrees. Seed K = 5185.
function M.cube_on_plane(opts)
  local name = "cube_on_plane"
  opts = options(name, opts, {size = true, h = true, vertices = true})
  local s = positive(name, opts, "size", 1)
  local froth = require("froth")
  return fragment(name, {
    solids = {{"box", min = {-s / 2, -s / 2, 0}, size = {s, s, s}}},
    walls = froth.plane{normal = {0, 0, 1}, offset = 0},
  }, size(name, opts, 5185, 6 / 5))
end

--- Half sphere on a plane: the upper half of the ball |x| <= R resting on x3 = 0, already the
--- equilibrium of the cube on a plane (a check of the walls' 90-degree contact). Seed K = 4225.
function M.half_sphere_on_plane(opts)
  local name = "half_sphere_on_plane"
  opts = options(name, opts, {R = true, h = true, vertices = true})
  local R = positive(name, opts, "R", 1)
  local froth = require("froth")
  return fragment(name, {
    solids = {{"ball", r = R, latitude = {0, pi / 2}}},
    walls = froth.plane{normal = {0, 0, 1}, offset = 0},
  }, size(name, opts, 4225, 3 / 2))
end

--- The perturbed cylinder (5.3) in the slab 0 < x3 < rho: the tube of radius
--- r(x3) = 1 + alpha cos(2 pi x3 / rho), x3 in [0, rho], its two ends on the slab's planes
--- (one wall, froth.slab). Made by meshing the unit cylinder and scaling x1, x2 by r(x3).
--- Seed: rho = 4, alpha = 0.5 (K = 4160) tends to a cylinder; rho = 8, alpha = 0.25
--- (K = 4128) pinches off at t ~ 1.487.
function M.cylinder_in_slab(opts)
  local name = "cylinder_in_slab"
  opts = options(name, opts, {rho = true, alpha = true, h = true, vertices = true})
  local rho = positive(name, opts, "rho", 4)
  local alpha = number(name, opts, "alpha", 0.5)
  if not (alpha > -1 and alpha < 1) then
    fail(name, "alpha must be in (-1, 1) (the radius 1 + alpha cos(...) must stay positive), got %s",
         alpha)
  end
  local froth = require("froth")
  local k = 2 * pi / rho
  return fragment(name, {
    solids = {{"cylinder", base = {0, 0, 0}, axis = {0, 0, rho}, r = 1}},
    walls = froth.slab{normal = {0, 0, 1}, from = 0, to = rho},
    transform = function(x, y, z)
      local r = 1 + alpha * math.cos(k * z)
      return r * x, r * y, z
    end,
  }, size(name, opts, rho == 8 and 4128 or 4160, (rho + 1) / rho))
end

--- A cuboid of size {a, b, rho} standing in the slab 0 < x3 < rho (seed §5.1.4: 1 x 1 x 8):
--- [-a/2, a/2] x [-b/2, b/2] x [0, rho], its ends on the slab's planes. Under surface diffusion
--- it becomes the cylinder of the same volume (a square becoming a circle, in every section).
--- The seed gives no vertex count; default about 4100 like its other slab runs.
function M.cuboid_in_slab(opts)
  local name = "cuboid_in_slab"
  opts = options(name, opts, {size = true, h = true, vertices = true})
  local s = opts.size or {1, 1, 8}
  if type(s) ~= "table" or #s ~= 3 or math.type(s[1]) == nil or math.type(s[2]) == nil
     or math.type(s[3]) == nil then
    fail(name, "option 'size' must be {a, b, rho}")
  end
  for d = 1, 3 do
    if not (s[d] > 0 and s[d] < math.huge) then
      fail(name, "size must be positive in x, y and z, got {%s, %s, %s}", s[1], s[2], s[3])
    end
  end
  local froth = require("froth")
  local side, ends = 2 * (s[1] + s[2]) * s[3], 2 * s[1] * s[2]
  return fragment(name, {
    solids = {{"box", min = {-s[1] / 2, -s[2] / 2, 0}, size = {s[1], s[2], s[3]}}},
    walls = froth.slab{normal = {0, 0, 1}, from = 0, to = s[3]},
  }, size(name, opts, 4100, (side + ends) / side))
end

--- A drop resting on the sphere wall |x| = R (outside it): the half ball of radius r on the
--- north pole, sheared vertically onto the wall, x3 -> x3 + sqrt(R^2 - x1^2 - x2^2), so that
--- its flat face lies on the sphere (the shear keeps volumes; the film meets the wall at about
--- 90 - asin(r / R) degrees at first). Under surface diffusion it tends to the spherical cap
--- meeting the wall at 90 degrees (the sphere of radius a centred at (0, 0, sqrt(R^2 + a^2))
--- cut by the wall) with the same volume. Not a seed experiment.
function M.drop_on_sphere_wall(opts)
  local name = "drop_on_sphere_wall"
  opts = options(name, opts, {R = true, r = true, h = true, vertices = true})
  local R = positive(name, opts, "R", 2)
  local r = positive(name, opts, "r", 0.7)
  if not (r < R) then fail(name, "r must be smaller than R = %s, got %s", R, r) end
  local froth = require("froth")
  return fragment(name, {
    solids = {{"ball", r = r, latitude = {0, pi / 2}}},
    walls = froth.sphere_wall{center = {0, 0, 0}, radius = R},
    transform = function(x, y, z)
      return x, y, z + math.sqrt(R * R - x * x - y * y)
    end,
  }, size(name, opts, 3000, 3 / 2))
end

return M
