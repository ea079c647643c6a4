-- froth.structured_clusters: clusters meshed by uniform refinement rather than by gmsh, for
-- convergence studies where the vertex counts must follow the seed's K = (2^k + 1)^2
-- (Table 1: 289, 1089, 4225, 16641). Copied into the froth table at startup like the named
-- clusters; needs no gmsh.
local M = {}

local check = require("froth.options")
local fail, options, number, positive = check.fail, check.options, check.number, check.positive

-- The unit upper half sphere as the octahedral refinement of 8 triangles: the pole and 8 points
-- on the equator (every 45 degrees), each level splitting every triangle in 4 at its edge
-- midpoints, pushed out to the sphere (equator midpoints stay on the equator). After k - 1
-- levels (k >= 1): (2^k + 1)^2 vertices, 2 * 4^k triangles, 2^(k+3) of the vertices on the rim;
-- indices (i, j) on the square grid [-2^(k-1), 2^(k-1)]^2 name the vertices.
local function half_sphere(levels)
  local pts, index = {}, {}
  local function key(i, j) return i .. "," .. j end
  local function add(i, j, x)
    pts[#pts + 1] = x
    index[key(i, j)] = #pts
  end
  add(0, 0, {0, 0, 1})
  local ring = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}
  for _, ij in ipairs(ring) do
    local a = math.atan(ij[2], ij[1])
    add(ij[1], ij[2], {math.cos(a), math.sin(a), 0})
  end
  local tris = {}
  for q = 1, 8 do
    local a, b = ring[q], ring[q % 8 + 1]
    tris[#tris + 1] = {{0, 0}, {a[1], a[2]}, {b[1], b[2]}}
  end
  for _ = 2, levels do
    local new_index, new_tris = {}, {}
    for k, v in pairs(index) do -- double every grid index
      local i, j = k:match("^(-?%d+),(-?%d+)$")
      new_index[key(2 * tonumber(i), 2 * tonumber(j))] = v
    end
    index = new_index
    local function mid(u, v)
      local i, j = (u[1] + v[1]) // 2, (u[2] + v[2]) // 2
      if not index[key(i, j)] then
        local p, q = pts[index[key(u[1], u[2])]], pts[index[key(v[1], v[2])]]
        local m = {(p[1] + q[1]) / 2, (p[2] + q[2]) / 2, (p[3] + q[3]) / 2}
        local n = math.sqrt(m[1] ^ 2 + m[2] ^ 2 + m[3] ^ 2)
        add(i, j, {m[1] / n, m[2] / n, m[3] / n})
      end
      return {i, j}
    end
    for _, t in ipairs(tris) do
      local a = {2 * t[1][1], 2 * t[1][2]}
      local b = {2 * t[2][1], 2 * t[2][2]}
      local c = {2 * t[3][1], 2 * t[3][2]}
      local ab, bc, ca = mid(a, b), mid(b, c), mid(c, a)
      new_tris[#new_tris + 1] = {a, ab, ca}
      new_tris[#new_tris + 1] = {ab, b, bc}
      new_tris[#new_tris + 1] = {ca, bc, c}
      new_tris[#new_tris + 1] = {ab, bc, ca}
    end
    tris = new_tris
  end
  local faces = {}
  for f, t in ipairs(tris) do
    faces[f] = {index[key(t[1][1], t[1][2])], index[key(t[2][1], t[2][2])],
                index[key(t[3][1], t[3][2])]}
  end
  return pts, faces
end

--- The half ellipsoid {sum (x_i / a_i)^2 = 1, x3 >= 0} on the plane x3 = 0 (the wall is
--- attached): the structured half sphere above, scaled by the semi-axes. With axes =
--- (1, eps, eps) it is the upper half of the Wulff shape of gamma(p) = sqrt(p.Gp),
--- G = diag(1, eps^2, eps^2): the initial surface of the seed's Table 1 ((5.5)).
--- Options: levels (k, 1..8; (2^k + 1)^2 vertices), axes {a1, a2, a3}.
--- Returns the cluster and h, its largest facet diameter.
function M.half_ellipsoid_on_plane(opts)
  local name = "half_ellipsoid_on_plane"
  opts = options(name, opts, {levels = true, axes = true})
  local levels = number(name, opts, "levels", 4)
  if math.type(levels) ~= "integer" and levels ~= math.floor(levels) or levels < 1 or levels > 8 then
    fail(name, "levels must be an integer in 1..8, got %s", tostring(levels))
  end
  local axes = opts.axes or {1, 1, 1}
  if type(axes) ~= "table" or #axes ~= 3 then fail(name, "axes must be {a1, a2, a3}") end
  for d = 1, 3 do
    if type(axes[d]) ~= "number" or not (axes[d] > 0) or axes[d] == math.huge then
      fail(name, "axes[%d] must be a positive number, got %s", d, tostring(axes[d]))
    end
  end
  local pts, faces = half_sphere(math.floor(levels))
  for _, x in ipairs(pts) do
    for d = 1, 3 do x[d] = axes[d] * x[d] end
  end
  -- h = the largest facet diameter (the seed's h_X0 of Table 1).
  local h = 0
  for _, f in ipairs(faces) do
    for e = 1, 3 do
      local p, q = pts[f[e]], pts[f[e % 3 + 1]]
      h = math.max(h, math.sqrt((p[1] - q[1]) ^ 2 + (p[2] - q[2]) ^ 2 + (p[3] - q[3]) ^ 2))
    end
  end
  local froth = require("froth")
  return froth.cluster{vertices = pts, surfaces = {faces}, bodies = {{1}},
                       walls = froth.plane{normal = {0, 0, 1}}}, h
end

--- Box cells on a lattice, meshed without gmsh as Surface Evolver's box datafiles are: the
--- lattice planes x = x[1] < x[2] < ..., y = ..., z = ... cut space into cells, cell (i, j, k)
--- (1-based, i < #x) belongs to body cell(i, j, k) (0 or nil: outside), and every lattice
--- rectangle between two different regions is a face, split into 4 triangles at its centre. One
--- surface per pair of regions (its facets oriented from the lower region id to the higher), so
--- a film between two cells, or between a cell and the outside, is one surface. Options: x, y, z
--- (arrays of increasing numbers, at least 2 each), cell (a function (i, j, k) -> body id or 0).
--- Refine with c:refine(). The double bubble from two unit cubes:
---   froth.box_cells{x = {0, 1, 2}, y = {0, 1}, z = {0, 1}, cell = function(i) return i end}
function M.box_cells(opts)
  local name = "box_cells"
  opts = options(name, opts, {x = true, y = true, z = true, cell = true})
  local grid = {}
  for d, key in ipairs{"x", "y", "z"} do
    local g = opts[key]
    if type(g) ~= "table" or #g < 2 then fail(name, "%s must be an array of at least 2 numbers", key) end
    for n = 1, #g do
      if type(g[n]) ~= "number" or (n > 1 and not (g[n] > g[n - 1])) then
        fail(name, "%s must be increasing numbers, %s[%d] = %s", key, key, n, tostring(g[n]))
      end
    end
    grid[d] = g
  end
  if type(opts.cell) ~= "function" then fail(name, "cell must be a function (i, j, k) -> body id") end
  local n = {#grid[1], #grid[2], #grid[3]}
  local bodies = 0
  local function region(c) -- c = {i, j, k} 1-based cell indices
    for d = 1, 3 do
      if c[d] < 1 or c[d] >= n[d] then return 0 end
    end
    local b = opts.cell(c[1], c[2], c[3]) or 0
    if math.type(b) ~= "integer" or b < 0 then
      fail(name, "cell(%d, %d, %d) must be a body id >= 0, got %s", c[1], c[2], c[3], tostring(b))
    end
    bodies = math.max(bodies, b)
    return b
  end
  local vertices, index = {}, {}
  local function corner(p) -- p = {i, j, k} 1-based lattice point
    local key = p[1] .. "," .. p[2] .. "," .. p[3]
    if not index[key] then
      vertices[#vertices + 1] = {grid[1][p[1]], grid[2][p[2]], grid[3][p[3]]}
      index[key] = #vertices
    end
    return index[key]
  end
  local surfaces, surface_of, pairs_of = {}, {}, {}
  for d = 1, 3 do
    local u, v = d % 3 + 1, (d + 1) % 3 + 1 -- e_u x e_v = e_d
    local p = {}
    for a = 1, n[d] do
      for b = 1, n[u] - 1 do
        for c = 1, n[v] - 1 do
          local lo, hi = {}, {}
          lo[d], lo[u], lo[v] = a - 1, b, c
          hi[d], hi[u], hi[v] = a, b, c
          local r1, r2 = region(lo), region(hi)
          if r1 ~= r2 then
            local key = math.min(r1, r2) .. "," .. math.max(r1, r2)
            if not surface_of[key] then
              surfaces[#surfaces + 1] = {}
              surface_of[key] = #surfaces
              pairs_of[#surfaces] = {r1, r2}
            end
            local q = {}
            for e, off in ipairs{{0, 0}, {1, 0}, {1, 1}, {0, 1}} do
              p[d], p[u], p[v] = a, b + off[1], c + off[2]
              q[e] = corner(p)
            end
            local centre = {}
            for m = 1, 3 do
              centre[m] = (vertices[q[1]][m] + vertices[q[3]][m]) / 2
            end
            vertices[#vertices + 1] = centre
            local mid, facets = #vertices, surfaces[surface_of[key]]
            for e = 1, 4 do -- counterclockwise about e_d: normal +e_d, from r1 to r2
              local f = {q[e], q[e % 4 + 1], mid}
              if r1 > r2 then f[1], f[2] = f[2], f[1] end
              facets[#facets + 1] = f
            end
          end
        end
      end
    end
  end
  local body_surfaces = {}
  for b = 1, bodies do body_surfaces[b] = {} end
  for s, pr in ipairs(pairs_of) do
    for _, r in ipairs(pr) do
      if r > 0 then table.insert(body_surfaces[r], s) end
    end
  end
  for b = 1, bodies do
    if #body_surfaces[b] == 0 then fail(name, "body %d has no cells", b) end
  end
  return require("froth").cluster{vertices = vertices, surfaces = surfaces, bodies = body_surfaces}
end

return M
