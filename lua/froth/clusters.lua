-- froth.clusters: the named clusters of the seed (§5.1), built on froth.fragment. The froth
-- executable copies every function of this module into the froth table at startup (in builds
-- with gmsh), so scripts call froth.torus_bubble{...}, froth.triple_bubble{...}, ...
-- See docs/lua_api.md "Named clusters" for options, surface and body numbering.
local M = {}

local pi = math.pi
local check = require("froth.options")
local fail, options, number, boolean, choice =
  check.fail, check.options, check.number, check.boolean, check.choice

-- froth.fragment with its messages renamed ("fragment: ..." -> "torus_bubble: ...") so that
-- errors name the builder the user called. h = nil asks fragment for about `vertices`.
local function fragment(name, args, h, vertices)
  local froth = require("froth")
  if h == nil then args.vertices = vertices else args.h = h end
  local ok, result = pcall(froth.fragment, args)
  if ok then return result end
  local msg = tostring(result)
  error((msg:gsub("^fragment:", name .. ":", 1)), 0)
end

-- The seed's two stretchings of the torus bubble (§5.1.1, after (5.2)), as one map:
-- G_1 scales x by e^{-0.2 x} where x < 0, G_2 scales y by e^{-0.1 y} where y < 0. Each moves
-- only its own coordinate and only by that coordinate, so G_2 o G_1 = G_1 o G_2.
local function torus_stretch(x, y, z)
  if x < 0 then x = x * math.exp(-0.2 * x) end
  if y < 0 then y = y * math.exp(-0.1 * y) end
  return x, y, z
end

-- The torus bubble's solids for each layout; body 1 = the dumbbell, body 2 = the torus, and
-- the surfaces come out as 1, 2 = lower, upper cap, 3 = outer torus, 4 = the wall between them.
local function torus_bubble_solids(layout, R, r)
  local torus = {"torus", R = R, r = r}
  if layout == "ball" then return {{"ball", r = R}, torus} end
  -- "halves": the torus comes first so that it keeps its whole tube; the dumbbell is the two
  -- half balls standing on the circles z = +-r plus the cylinder between them, minus the tube.
  torus.body = 2
  return {torus,
          {"ball", center = {0, 0, r}, r = R, latitude = {0, pi / 2}, body = 1},
          {"ball", center = {0, 0, -r}, r = R, latitude = {-pi / 2, 0}, body = 1},
          {"cylinder", base = {0, 0, -r}, axis = {0, 0, 2 * r}, r = R, body = 1}}
end

--- Torus bubble (unstable double bubble, seed §5.1.1), from the torus (R - sqrt(x^2 +
--- y^2))^2 + z^2 <= r^2 about the z axis (5.2) and two half spheres of radius R; two layouts:
---  "ball" (default): the ball |x| <= R fragmented with the torus, whose tube is centered on
---   the sphere's equator. Body 1 = the ball (the "dumbbell"), body 2 = the torus outside it.
---   Surfaces: 1 = lower cap, 2 = upper cap, 3 = outer part of the torus, 4 = the band of
---   the sphere inside the torus (ball | torus).
---  "halves": the half spheres stand on the torus's top and bottom circles (centers (0, 0,
---   +-r)), so the films are exactly two half spheres and the torus surface. Body 1 = the
---   dumbbell (half balls joined through the torus's hole), body 2 = the whole tube.
---   Surfaces: 1, 2 = the half spheres, 3 = the outer half of the torus, 4 = its inner half.
function M.torus_bubble(opts)
  local name = "torus_bubble"
  opts = options(name, opts, {R = true, r = true, h = true, vertices = true, stretch = true,
                              sigma = true, layout = true})
  local R = number(name, opts, "R", 2)
  local r = number(name, opts, "r", 1)
  if not (R > 0 and R < math.huge) then fail(name, "R must be positive, got %s", R) end
  if not (r > 0 and r < R) then
    fail(name, "r must be in (0, R) = (0, %s), got %s", R, r)
  end
  local stretch = boolean(name, opts, "stretch", false)
  local layout = choice(name, opts, "layout", {"ball", "halves"}, "ball")
  return fragment(name, {
    solids = torus_bubble_solids(layout, R, r),
    sigma = opts.sigma,
    transform = stretch and torus_stretch or nil,
  }, number(name, opts, "h", nil), number(name, opts, "vertices", stretch and 5300 or 4800))
end

--- Triple bubble (seed §5.1.2): the unit ball in three 120-degree wedges about the z axis.
--- Body k = the wedge of azimuth [120 (k-1), 120 k] degrees. Surfaces: 1, 2, 3 = the spherical
--- lunes of bodies 1, 2, 3; 4 = the wall between bodies 1 and 2 (azimuth 120), 5 = between 1
--- and 3 (azimuth 0), 6 = between 2 and 3 (azimuth 240). So body 1 = {1, 4, 5}, as in the seed.
function M.triple_bubble(opts)
  local name = "triple_bubble"
  opts = options(name, opts, {h = true, vertices = true, sigma = true})
  local solids = {}
  for k = 0, 2 do
    -- analytic wedges: no seam splits a lune (dependencies.md §3, triple_wedge)
    solids[k + 1] = {"ball", r = 1, angle = 2 * pi / 3,
                     rotate = {axis = {0, 0, 1}, angle = 2 * pi * k / 3}}
  end
  return fragment(name, {solids = solids, sigma = opts.sigma},
                  number(name, opts, "h", nil), number(name, opts, "vertices", 6500))
end

--- Quadruple bubble (seed §5.1.3): a 2x1x1 cuboid [0,2]x[0,1]x[0,1] (body 1), on it two unit
--- cubes [0,1]x[0,1]x[1,2] (body 2) and [1,2]x[0,1]x[1,2] (body 3), on them a second cuboid
--- [0,2]x[0,1]x[2,3] (body 4). Surfaces ordered by their pair of regions (0 = outside):
--- 1 = (0,1), 2 = (0,2), 3 = (0,3), 4 = (0,4), 5 = (1,2), 6 = (1,3), 7 = (2,3), 8 = (2,4),
--- 9 = (3,4).
function M.quadruple_bubble(opts)
  local name = "quadruple_bubble"
  opts = options(name, opts, {h = true, vertices = true, sigma = true})
  return fragment(name, {
    solids = {{"box", min = {0, 0, 0}, size = {2, 1, 1}},
              {"box", min = {0, 0, 1}, size = {1, 1, 1}},
              {"box", min = {1, 0, 1}, size = {1, 1, 1}},
              {"box", min = {0, 0, 2}, size = {2, 1, 1}}},
    sigma = opts.sigma,
  }, number(name, opts, "h", nil), number(name, opts, "vertices", 7300))
end

return M
