-- Anisotropic surface energies and mobilities: froth.anisotropy and the froth.anisotropies
-- presets against the closed forms of (1.15)-(1.17) and (5.6); gamma', gamma* and their identities;
-- c:set_anisotropy / set_mobility in the energy and in steps; the fixed_point option and the
-- step report fields of the r > 1 iteration; every error naming its problem.
local T = require("froth.test")
local A = froth.anisotropies
local sqrt, pi = math.sqrt, math.pi

local function dot(a, b) return a[1] * b[1] + a[2] * b[2] + a[3] * b[3] end
local function norm(a) return sqrt(dot(a, a)) end
local function scale(t, a) return {t * a[1], t * a[2], t * a[3]} end
local function cross(a, b)
  return {a[2] * b[3] - a[3] * b[2], a[3] * b[1] - a[1] * b[3], a[1] * b[2] - a[2] * b[1]}
end

-- Test vectors: axes, diagonals and a few generic directions of different lengths.
local P = {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}, {1, 1, 1}, {0.3, -0.7, 0.2}, {-2, 0.5, 1.5},
           {0.1, 0.2, -3}, {1e-3, -4e-3, 2e-3}}

-- (1.17) with G_l = R^T diag(1, eps^2, eps^2) R is eps^2 I + (1 - eps^2) d d^T, d the first row
-- of R = R1(t1) R2(t2) R3(t3), so gamma_l(p) = sqrt(eps^2 |p|^2 + (1 - eps^2) (d . p)^2).
-- The rows below are worked out by hand from the rotations (not read from the engine).
local function gamma_from_directions(dirs, eps, r)
  return function(p)
    local s = 0
    for _, d in ipairs(dirs) do
      local dn = scale(1 / norm(d), d)
      s = s + sqrt(eps ^ 2 * dot(p, p) + (1 - eps ^ 2) * dot(dn, p) ^ 2) ^ r
    end
    return s ^ (1 / r)
  end
end
local h3 = sqrt(3) / 2
local L1_DIRS = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}                       -- (5.6)
local HEX_DIRS = {{1, 0, 0}, {0.5, 0, h3}, {-0.5, 0, h3}, {0, 1, 0}}    -- Fig. 2 right
local FIG3R_DIRS = {{1, 0, 0}, {0, 0, 1}, {1, 1, 0}, {1, -1, 0}, {0, -1, 1}, {0, 1, 1}}

-- gamma of every preset against its closed form, at every test vector.
local function check_gamma(g, exact, tol, what)
  local worst = 0
  for _, p in ipairs(P) do
    local e = exact(p)
    worst = math.max(worst, math.abs(g:gamma(p) - e) / e)
  end
  T.assert_true(worst <= tol, what .. ": gamma against its closed form", "relative error " .. worst)
end

-- (5.6) at e_z: 1 + 2 eps for r = 1; (1 + 2 eps^r)^(1/r) for r > 1.
T.assert_near(A.l1{eps = 0.1}:gamma{0, 0, 1}, 1.2, 1e-14, "l1 gamma(e_z) = 1 + 2 eps")
T.assert_near(A.l1{eps = 0.1, r = 3}:gamma(0, 0, 1), (1 + 2e-3) ^ (1 / 3), 1e-14,
              "l1 r = 3 gamma(e_z) = (1 + 2 eps^3)^(1/3)")
T.assert_near(A.l1():gamma{1, 1, 1}, 3 * sqrt(0.01 * 3 + 0.99), 1e-14, "l1 default eps = 0.1")
check_gamma(A.l1{eps = 0.1}, gamma_from_directions(L1_DIRS, 0.1, 1), 1e-14, "l1 eps 0.1")
check_gamma(A.l1{eps = 0.3, r = 3}, gamma_from_directions(L1_DIRS, 0.3, 3), 1e-14, "l1 r 3")
check_gamma(A.hexagonal{}, gamma_from_directions(HEX_DIRS, 1e-2, 1), 1e-14, "hexagonal")
check_gamma(A.hexagonal{eps = 0.2}, gamma_from_directions(HEX_DIRS, 0.2, 1), 1e-14, "hexagonal 0.2")
check_gamma(A.fig3_left{}, gamma_from_directions(L1_DIRS, 1e-2, 30), 1e-13, "fig3_left")
check_gamma(A.fig3_right{eps = 0.05}, gamma_from_directions(FIG3R_DIRS, 0.05, 30), 1e-13,
            "fig3_right")
check_gamma(A.isotropic(2.5), function(p) return 2.5 * norm(p) end, 1e-15, "isotropic(2.5)")
check_gamma(A.isotropic(), norm, 1e-15, "isotropic()")
local G3 = {{2, 0.5, 0}, {0.5, 1, 0.2}, {0, 0.2, 3}}
local function Gp(G, p)
  return {dot(G[1], p), dot(G[2], p), dot(G[3], p)}
end
check_gamma(A.ellipsoidal(G3), function(p) return sqrt(dot(p, Gp(G3, p))) end, 1e-14,
            "ellipsoidal 3x3")
check_gamma(A.ellipsoidal{1, 4, 9}, function(p) return sqrt(p[1]^2 + 4 * p[2]^2 + 9 * p[3]^2) end,
            1e-15, "ellipsoidal diagonal")

-- r, terms, tostring.
T.assert_equal(A.l1{}:r(), 1, "l1 r defaults to 1")
T.assert_equal(A.l1{r = 3}:r(), 3, "l1 r")
T.assert_equal(A.fig3_left{}:r(), 30, "fig3_left has r = 30")
T.assert_equal(A.fig3_right{}:r(), 30, "fig3_right has r = 30")
T.assert_equal(A.hexagonal{}:r(), 1, "hexagonal has r = 1")
T.assert_equal(#A.l1{}:terms(), 3, "l1 has 3 terms")
T.assert_equal(#A.hexagonal{}:terms(), 4, "hexagonal has 4 terms")
T.assert_equal(#A.fig3_right{}:terms(), 6, "fig3_right has 6 terms")
local t1 = A.l1{eps = 0.1}:terms()[1] -- theta = 0: diag(1, eps^2, eps^2)
T.assert_true(#t1 == 3 and t1[1][1] == 1 and math.abs(t1[2][2] - 0.01) < 1e-16 and
              math.abs(t1[3][3] - 0.01) < 1e-16 and t1[1][2] == 0 and t1[2][3] == 0,
              "the first l1 term is diag(1, eps^2, eps^2)")
local te = A.ellipsoidal(G3):terms()[1]
T.assert_true(te[1][2] == 0.5 and te[2][1] == 0.5 and te[2][3] == 0.2 and te[3][3] == 3,
              "terms() returns G")
T.assert_equal(tostring(A.l1{r = 3}), "froth.Anisotropy (3 terms, r = 3)", "tostring")
T.assert_equal(tostring(A.isotropic(2)), "froth.Anisotropy (1 term, r = 1, isotropic)",
               "tostring of an isotropic gamma")

-- Vectors as a table or as three numbers; homogeneity: gamma(t p) = t gamma(p) (t > 0),
-- gamma(-p) = gamma(p) (every G_l term is even), gamma'(t p) = gamma'(p), gamma' . p = gamma(p)
-- (Euler), gamma*(t q) = t gamma*(q); gamma(0) = gamma*(0) = 0.
local presets = {
  {"isotropic(1.5)", A.isotropic(1.5)}, {"ellipsoidal", A.ellipsoidal(G3)},
  {"l1", A.l1{eps = 0.1}}, {"l1 r 3", A.l1{eps = 0.1, r = 3}}, {"hexagonal", A.hexagonal{eps = 0.05}},
  {"fig3_left", A.fig3_left{eps = 0.05}}, {"fig3_right", A.fig3_right{eps = 0.05}},
  {"two G terms r 2", froth.anisotropy{{G = {1, 2, 3}}, {G = G3}, r = 2}},
}
for _, e in ipairs(presets) do
  local name, g = e[1], e[2]
  local hom, euler, fd, ch, sup = 0, 0, 0, 0, 0
  for _, p in ipairs(P) do
    local gp = g:gamma(p)
    T.assert_equal(g:gamma(p[1], p[2], p[3]), gp, name .. ": three numbers or a table")
    hom = math.max(hom, math.abs(g:gamma(scale(3.7, p)) - 3.7 * gp) / gp,
                   math.abs(g:gamma(scale(-1, p)) - gp) / gp)
    local d = g:gamma_prime(p)
    T.assert_equal(#d, 3, name .. ": gamma_prime is a 3-vector")
    local d2 = g:gamma_prime(scale(5, p))
    hom = math.max(hom, norm({d2[1] - d[1], d2[2] - d[2], d2[3] - d[3]}) / norm(d))
    euler = math.max(euler, math.abs(dot(d, p) - gp) / gp)
    -- gamma' against central differences of gamma (step relative to |p|).
    local h = 1e-6 * norm(p)
    for k = 1, 3 do
      local pp, pm = {p[1], p[2], p[3]}, {p[1], p[2], p[3]}
      pp[k], pm[k] = pp[k] + h, pm[k] - h
      fd = math.max(fd, math.abs((g:gamma(pp) - g:gamma(pm)) / (2 * h) - d[k]) / norm(d))
    end
    -- Cahn-Hoffmann: gamma*(gamma'(p)) = 1 (the sup of q . p / gamma(p) is attained at p).
    ch = math.max(ch, math.abs(g:gamma_star(d) - 1))
    local s = g:gamma_star(p)
    hom = math.max(hom, math.abs(g:gamma_star(scale(2.5, p)) - 2.5 * s) / s)
    -- gamma*(q) is a sup: no test direction beats it.
    for _, x in ipairs(P) do sup = math.max(sup, dot(p, x) / g:gamma(x) / s - 1) end
  end
  T.assert_true(hom <= 1e-12, name .. ": homogeneity of gamma, gamma' and gamma*", hom)
  T.assert_true(euler <= 1e-13, name .. ": gamma'(p) . p = gamma(p)", euler)
  T.assert_true(fd <= 2e-6, name .. ": gamma' = finite differences of gamma", fd)
  T.assert_true(ch <= 1e-9, name .. ": gamma*(gamma'(p)) = 1", ch)
  T.assert_true(sup <= 1e-12, name .. ": q . p / gamma(p) <= gamma*(q)", sup)
  T.assert_equal(g:gamma{0, 0, 0}, 0, name .. ": gamma(0) = 0")
  T.assert_equal(g:gamma_star{0, 0, 0}, 0, name .. ": gamma*(0) = 0")
end

-- gamma* in closed form: |q| / s for isotropic(s), sqrt(q . G^-1 q) for ellipsoidal(G).
local Gd = A.ellipsoidal{1, 4, 9}
for _, q in ipairs(P) do
  T.assert_near(A.isotropic(2):gamma_star(q), norm(q) / 2, 1e-12 * norm(q), "isotropic gamma*")
  local exact = sqrt(q[1]^2 + q[2]^2 / 4 + q[3]^2 / 9)
  T.assert_near(Gd:gamma_star(q), exact, 1e-10 * exact, "ellipsoidal gamma* = sqrt(q.G^-1 q)")
end
-- l1 at e_z: by symmetry and Euler gamma'(e_z) = gamma(e_z) e_z = (1 + 2 eps) e_z (the terms
-- give eps, eps and 1), so Cahn-Hoffmann makes gamma*(e_z) = 1 / (1 + 2 eps).
local dz = A.l1{eps = 0.1}:gamma_prime{0, 0, 1}
T.assert_true(math.abs(dz[1]) < 1e-15 and math.abs(dz[2]) < 1e-15 and math.abs(dz[3] - 1.2) < 1e-15,
              "l1 gamma'(e_z) = (1 + 2 eps) e_z", table.concat(dz, " "))
T.assert_near(A.l1{eps = 0.1}:gamma_star{0, 0, 1}, 1 / 1.2, 1e-10, "l1 gamma*(e_z) = 1 / (1 + 2 eps)")

-- froth.anisotropy: {eps, theta} terms and {G} terms reproduce the presets.
local h = pi / 2
local function same_gamma(a, b, tol, what)
  local worst = 0
  for _, p in ipairs(P) do worst = math.max(worst, math.abs(a:gamma(p) - b:gamma(p)) / b:gamma(p)) end
  T.assert_true(worst <= tol, what, worst)
end
same_gamma(froth.anisotropy{{eps = 0.1, theta = {0, 0, 0}}, {eps = 0.1, theta = {h, 0, 0}},
                            {eps = 0.1, theta = {0, h, 0}}}, A.l1{eps = 0.1}, 1e-15,
           "anisotropy{eps, theta} terms = l1")
same_gamma(froth.anisotropy{{eps = 0.2}, {eps = 0.2, theta = {h, 0, 0}},
                            {eps = 0.2, theta = {0, h, 0}}, r = 3}, A.l1{eps = 0.2, r = 3}, 1e-15,
           "anisotropy{eps, theta; r = 3} = l1 r 3 (theta defaults to 0)")
same_gamma(froth.anisotropy{{eps = 1e-2}, {eps = 1e-2, theta = {0, pi / 3, 0}},
                            {eps = 1e-2, theta = {0, 2 * pi / 3, 0}}, {eps = 1e-2, theta = {h, 0, 0}}},
           A.hexagonal{}, 1e-15, "anisotropy{...} = hexagonal")
same_gamma(froth.anisotropy{{G = {1, 4, 9}}}, A.ellipsoidal{1, 4, 9}, 0, "anisotropy{{G}} = ellipsoidal")
same_gamma(froth.anisotropy{{G = {{4, 0, 0}, {0, 4, 0}, {0, 0, 4}}}}, A.isotropic(2), 1e-15,
           "anisotropy{{G = 4 I}} = isotropic(2)")
same_gamma(froth.anisotropy{{G = A.l1{}:terms()[1]}, {G = A.l1{}:terms()[2]}, {G = A.l1{}:terms()[3]}},
           A.l1{}, 1e-15, "anisotropy from terms() = the preset")
T.assert_equal(froth.anisotropy{{G = {1, 1, 1}}, r = 2}:r(), 2, "anisotropy r")

-- Errors of the constructors and methods name the problem.
local function bad(text, f, ...) T.check_error(text, f, ...) end
local fa = froth.anisotropy
bad("anisotropy: term 1: G is not symmetric", fa, {{G = {{1, 2, 0}, {0, 1, 0}, {0, 0, 1}}}})
bad("anisotropy: term 2: G is not positive definite (smallest eigenvalue -1)", fa,
    {{G = {1, 1, 1}}, {G = {{1, 2, 0}, {2, 1, 0}, {0, 0, 1}}}})
bad("anisotropy: term 1: G is not positive definite", fa, {{G = {1, 0, 1}}})
bad("G has a non-finite entry", fa, {{G = {1, 0 / 0, 1}}})
bad("anisotropy: eps must be a finite number > 0 (got 0)", fa, {{eps = 0, theta = {0, 0, 0}}})
bad("anisotropy: eps must be a finite number > 0 (got -1)", fa, {{eps = -1}})
bad("anisotropy: r must be a finite number >= 1 (got 0.5)", fa, {{G = {1, 1, 1}}, r = 0.5})
bad("anisotropy: r must be a finite number >= 1", fa, {{G = {1, 1, 1}}, r = math.huge})
bad("anisotropy: unknown option 'q' (terms and r only)", fa, {{G = {1, 1, 1}}, q = 1})
bad("anisotropy: term 1: unknown option 'foo'", fa, {{G = {1, 1, 1}, foo = 1}})
bad("anisotropy: term 1: option 'G' excludes eps and theta", fa, {{G = {1, 1, 1}, eps = 0.1}})
bad("anisotropy: term 1: option 'eps' must be a number", fa, {{eps = "a"}})
bad("anisotropy: term 1: option 'eps' is required", fa, {{theta = {0, 0, 0}}})
bad("anisotropy: term 1: G must be a 3x3 table", fa, {{G = {1, 1}}})
bad("anisotropy: term 1: G must be a 3x3 table", fa, {{G = "x"}})
bad("anisotropy: term 1: G: entry 2 must be a number", fa, {{G = {1, "a", 1}}})
bad("anisotropy: term 1: G: row 2 must be a table of 3 numbers", fa,
    {{G = {{1, 0, 0}, {0, 1}, {0, 0, 1}}}})
bad("anisotropy: expected a vector {x, y, z}", fa, {{eps = 0.1, theta = {0, "x", 0}}})
bad("anisotropy: needs at least one term", fa, {})
bad("anisotropy: term 1 must be a table {G = ...} or {eps = ..., theta = ...}", fa, {5})
bad("table expected, got number", fa, 5)
bad("anisotropy: sigma must be a finite number > 0 (got 0)", A.isotropic, 0)
bad("anisotropy: sigma must be a finite number > 0 (got -1)", A.isotropic, -1)
bad("G is not positive definite", A.ellipsoidal, {1, 0, 1})
bad("G is not symmetric", A.ellipsoidal, {{1, 1, 0}, {0, 1, 0}, {0, 0, 1}})
bad("ellipsoidal: G must be a 3x3 table", A.ellipsoidal, nil)
bad("anisotropy: eps must be a finite number > 0 (got 0)", A.l1, {eps = 0})
bad("anisotropy: r must be a finite number >= 1 (got 0.9)", A.l1, {eps = 0.1, r = 0.9})
bad("l1: unknown option 'epsilon'", A.l1, {epsilon = 0.1})
bad("hexagonal: unknown option 'r'", A.hexagonal, {r = 2})
bad("fig3_left: unknown option 'r'", A.fig3_left, {r = 2})
bad("anisotropy: eps must be a finite number > 0 (got -1)", A.fig3_right, {eps = -1})
bad("fig3_right: expected an option table {...}, got number", A.fig3_right, 5)
local g1 = A.l1{}
bad("anisotropy: expected a vector {x, y, z}", g1.gamma, g1, {1, 2})
bad("number expected, got no value", g1.gamma, g1, 1, 2)
bad("anisotropy: gamma' needs a non-zero vector", g1.gamma_prime, g1, {0, 0, 0})
bad("froth.Anisotropy expected, got table", g1.gamma, {}, {1, 0, 0})

-- Energy: sigma_i sum_facets gamma_i(nu) |facet|, on two glued tetrahedra (no gmsh needed).
local V = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}}
local S = {{{1, 2, 4}, {2, 3, 4}, {3, 1, 4}}, {{2, 1, 5}, {3, 2, 5}, {1, 3, 5}},
           {facets = {{1, 3, 2}}, sigma = 1.5}}
local tets = froth.cluster{vertices = V, surfaces = S, bodies = {{1, 3}, {2, 3}}}
local E_iso = tets:energy()
local function facet_energy(g, tri)
  local a, b, c = V[tri[1]], V[tri[2]], V[tri[3]]
  local n = cross({b[1] - a[1], b[2] - a[2], b[3] - a[3]}, {c[1] - a[1], c[2] - a[2], c[3] - a[3]})
  return g:gamma(scale(0.5, n)) -- gamma(nu) |facet| = gamma(area vector), gamma homogeneous
end
local gl1, gel = A.l1{eps = 0.1, r = 3}, A.ellipsoidal{1, 4, 9}
tets:set_anisotropy(1, gl1)
tets:set_anisotropy(3, gel)
local E = 0
for _, tri in ipairs(S[1]) do E = E + facet_energy(gl1, tri) end
E = E + tets:area(2)                                 -- surface 2 stays isotropic
E = E + 1.5 * facet_energy(gel, S[3].facets[1])      -- sigma multiplies gamma
T.assert_near(tets:energy(), E, 1e-14 * E, "energy = sum sigma_i gamma_i(nu)|facet|")
T.assert_near(tets:area(), 2 * (1 + h3) + 0.5, 1e-14, "the area is unchanged by gamma")
T.assert_true(tets:anisotropy(1) ~= nil and tets:anisotropy(2) == nil, "anisotropy(id): gamma or nil")
T.assert_equal(tets:anisotropy(1):gamma{1, 2, 3}, gl1:gamma{1, 2, 3}, "anisotropy(id) is the gamma set")
T.assert_equal(tets:anisotropy(3):r(), 1, "anisotropy(3)")
local clone = tets:clone()
T.assert_equal(clone:energy(), tets:energy(), "a clone keeps the anisotropies")
T.assert_equal(tostring(clone:anisotropy(1)), tostring(gl1), "a clone's anisotropy(1)")
clone:set_anisotropy(1, nil)
T.assert_equal(clone:anisotropy(1), nil, "set_anisotropy(id, nil) restores the isotropic energy")
T.assert_true(tets:anisotropy(1) ~= nil, "the original keeps its gamma after the clone changed")
tets:set_anisotropy("all", A.isotropic(2))
T.assert_near(tets:energy(), 2 * E_iso, 1e-14, "isotropic(2) on all surfaces doubles the energy")
T.assert_equal(tets:set_anisotropy("all"), nil, "set_anisotropy returns nothing")
T.assert_near(tets:energy(), E_iso, 1e-15, "set_anisotropy('all') without gamma: isotropic again")

-- Mobility settings and their errors (the cluster keeps its previous setting).
T.assert_equal(tets:mobility(1), 1, "default mobility 1")
tets:set_mobility(2, 0.5)
T.assert_equal(tets:mobility(2), 0.5, "constant mobility")
tets:set_mobility("all", "gamma")
T.assert_equal(tets:mobility(3), "gamma", "mobility 'gamma'")
tets:set_mobility(1, function(nx, ny, nz) return 1 + nz * nz end)
T.assert_equal(tets:mobility(1), "function", "mobility function")
T.assert_equal(tets:mobility(2), "gamma", "set_mobility(1, ...) leaves surface 2")
bad("mobility: beta must be a finite number > 0 (got 0)", tets.set_mobility, tets, 2, 0)
bad("mobility: beta must be a finite number > 0 (got -1)", tets.set_mobility, tets, 2, -1)
bad("mobility: beta must be a finite number > 0 (got nan)", tets.set_mobility, tets, 2, 0 / 0)
bad("mobility: beta must be a finite number > 0 (got inf)", tets.set_mobility, tets, 2, math.huge)
bad('set_mobility: beta must be a positive number, "gamma" or a function (nx, ny, nz) -> beta, got string',
    tets.set_mobility, tets, 2, "gama")
bad("set_mobility: beta must be a positive number", tets.set_mobility, tets, 2, {})
bad("set_mobility: beta must be a positive number", tets.set_mobility, tets, 2, nil)
T.assert_equal(tets:mobility(2), "gamma", "a failed set_mobility changes nothing")
bad("surface 4 does not exist (the cluster has surfaces 1..3)", tets.set_mobility, tets, 4, 1)
bad("surface 0 does not exist", tets.set_anisotropy, tets, 0, gl1)
bad("surface 4 does not exist", tets.anisotropy, tets, 4)
bad("surface 4 does not exist", tets.mobility, tets, 4)
bad('expected a surface id or "all", got string', tets.set_anisotropy, tets, "some", gl1)
bad('expected a surface id or "all", got number', tets.set_mobility, tets, 1.5, 1)
bad("set_anisotropy: expected a froth.Anisotropy (from froth.anisotropy or froth.anisotropies), got number",
    tets.set_anisotropy, tets, 1, 5)
bad("set_anisotropy: expected a froth.Anisotropy", tets.set_anisotropy, tets, 1, {})
bad("set_anisotropy: expected a froth.Anisotropy", tets.set_anisotropy, tets, 1, tets)
T.assert_equal(tets:anisotropy(1), nil, "a failed set_anisotropy changes nothing")

if not froth.has("gmsh") then return T.summary() end -- the steps below need a meshed cluster

-- Steps. The half-ball double bubble at h = 0.5: 186 vertices, a few ms per step.
local db = froth.double_bubble{h = 0.5}
local maxdiff = T.max_difference
local function with(gamma, beta)
  local c = db:clone()
  if gamma then c:set_anisotropy("all", gamma) end
  if beta then c:set_mobility("all", beta) end
  return c
end

-- A constant mobility beta scales the velocity: for both schemes a step of tau with beta equals
-- a step of beta tau with beta = 1 ((3.7a)/(3.8a) divide by tau and multiply by beta). With
-- beta = "gamma" and gamma = isotropic(2) the velocity is beta gamma-curvature = 2 * 2 kappa.
for _, flow in ipairs{"mcf", "sd"} do
  local ref = with(); ref:step{flow = flow, tau = 2e-3, exact_volumes = false}
  local moved = maxdiff(ref, db)
  T.assert_true(moved > 1e-3, flow .. ": the reference step moves the mesh", moved)
  local b2 = with(nil, 2); b2:step{flow = flow, tau = 1e-3, exact_volumes = false}
  T.assert_true(maxdiff(b2, ref) <= 1e-9 * moved, flow .. ": beta = 2 doubles the velocity",
                maxdiff(b2, ref))
  local bf = with(nil, function() return 2 end); bf:step{flow = flow, tau = 1e-3, exact_volumes = false}
  T.assert_true(maxdiff(bf, ref) <= 1e-9 * moved, flow .. ": a function returning 2 = beta 2",
                maxdiff(bf, ref))
  local bg = with(A.isotropic(2), "gamma"); bg:step{flow = flow, tau = 0.5e-3, exact_volumes = false}
  T.assert_true(maxdiff(bg, ref) <= 1e-9 * moved, flow .. ": beta = gamma = 2|nu| with gamma 2|nu|",
                maxdiff(bg, ref))
  local i1 = with(A.isotropic(1)); i1:step{flow = flow, tau = 2e-3, exact_volumes = false}
  T.assert_true(maxdiff(i1, ref) <= 1e-9 * moved, flow .. ": isotropic(1) = no anisotropy",
                maxdiff(i1, ref))
  local half = with(); half:step{flow = flow, tau = 1e-3, exact_volumes = false}
  T.assert_true(maxdiff(half, ref) > 1e-2 * moved, flow .. ": (and half the step is different)")
end

-- The mobility function sees unit normals; it is called for the step.
local calls, worst_unit = 0, 0
local fm = with(nil, function(nx, ny, nz)
  calls = calls + 1
  worst_unit = math.max(worst_unit, math.abs(sqrt(nx * nx + ny * ny + nz * nz) - 1))
  return 1 + 0.5 * nz * nz
end)
local rf = fm:step{flow = "sd", tau = 1e-3, exact_volumes = false}
T.assert_true(calls > 0 and worst_unit < 1e-12, "the mobility function gets unit normals",
              calls .. " calls, |nu| - 1 up to " .. worst_unit)
T.assert_true(rf.energy <= rf.energy_before, "sd with a mobility function decreases the energy")

-- r = 1: no fixed-point iteration, the energy never increases.
local c1 = with(A.l1{eps = 0.1})
for _, flow in ipairs{"sd", "mcf", "sd"} do
  local r = c1:step{flow = flow, tau = 1e-3, exact_volumes = false}
  T.assert_equal(r.fixed_point_iterations, 0, flow .. " r = 1: fixed_point_iterations = 0")
  T.assert_equal(r.fixed_point_change, 0, flow .. " r = 1: fixed_point_change = 0")
  T.assert_equal(r.substeps, 1, flow .. " r = 1: one substep")
  T.assert_true(r.energy <= r.energy_before, flow .. " r = 1: the energy does not increase",
                r.energy .. " > " .. r.energy_before)
  T.assert_near(r.energy, c1:energy(), 0, "the step's energy is the anisotropic energy")
end
local plain = db:clone():step{flow = "sd", tau = 1e-3, exact_volumes = false}
T.assert_equal(plain.fixed_point_iterations, 0, "isotropic: fixed_point_iterations = 0")

-- r = 3: Newton's method for (3.9) converges to the tolerance in a few solves.
local c3 = with(A.l1{eps = 0.1, r = 3})
for _, flow in ipairs{"sd", "mcf"} do
  local r = c3:step{flow = flow, tau = 1e-3, exact_volumes = false}
  T.assert_true(r.fixed_point_iterations >= 2 and r.fixed_point_iterations <= 60,
                flow .. " r = 3: fixed_point_iterations in 2..60", r.fixed_point_iterations)
  T.assert_true(r.fixed_point_change > 0 and r.fixed_point_change <= 1e-8,
                flow .. " r = 3: fixed_point_change <= tol = 1e-8", r.fixed_point_change)
  T.assert_true(r.substeps >= 1, flow .. " r = 3: substeps >= 1", r.substeps)
  T.assert_true(r.energy <= r.energy_before, flow .. " r = 3: the energy does not increase")
end
local loose = with(A.l1{eps = 0.1, r = 3}):step{flow = "sd", tau = 1e-3, exact_volumes = false, fixed_point = {tol = 1e-4}, exact_volumes = false}
local tight = with(A.l1{eps = 0.1, r = 3}):step{flow = "sd", tau = 1e-3, exact_volumes = false, fixed_point = {tol = 1e-11}, exact_volumes = false}
T.assert_true(loose.fixed_point_change <= 1e-4 and tight.fixed_point_change <= 1e-11 and
              loose.fixed_point_iterations < tight.fixed_point_iterations,
              "fixed_point.tol: a tighter tolerance takes more solves",
              loose.fixed_point_iterations .. " vs " .. tight.fixed_point_iterations)

-- Too few solves allowed: the step is split into halves (substeps), which need fewer solves each;
-- a full step here needs more than 10.
local need = with(A.l1{eps = 0.1, r = 3}):step{flow = "sd", tau = 1e-3, exact_volumes = false}.fixed_point_iterations
local cs = with(A.l1{eps = 0.1, r = 3})
local ok, rs = pcall(cs.step, cs, {flow = "sd", tau = 1e-3, exact_volumes = false,
                                   fixed_point = {max_iterations = need - 1, max_halvings = 6}})
T.assert_true(ok, "a step with halvings converges", tostring(rs))
if ok then
  T.assert_true(rs.substeps >= 2, "the step was split", rs.substeps)
  T.assert_true(rs.fixed_point_iterations > need - 1, "iterations summed over the substeps",
                rs.fixed_point_iterations)
  T.assert_equal(rs.tau, 1e-3, "the report's tau is the whole step")
  T.assert_near(cs:time(), 1e-3, 1e-18, "the split step advances the time by tau")
  T.assert_true(rs.energy <= rs.energy_before, "split step: the energy does not increase")
end

-- No convergence: an error naming the iteration, and the cluster unchanged; evolve stops.
local cn = with(A.l1{eps = 0.1, r = 3})
local before = cn:clone()
bad("step: Newton's method for the r > 1 system (3.9) did not converge in 2 solves", cn.step, cn,
    {flow = "sd", tau = 1e-3, exact_volumes = false, fixed_point = {max_iterations = 2, max_halvings = 0}})
bad("after 2 halvings of the step); the cluster is unchanged", cn.step, cn,
    {flow = "sd", tau = 1e-3, exact_volumes = false, fixed_point = {max_iterations = 2, max_halvings = 2}})
T.assert_true(cn:time() == 0 and maxdiff(cn, before) == 0, "no convergence: the cluster is unchanged")
local rn = cn:evolve{flow = "sd", tau = 1e-3, exact_volumes = false, steps = 3, progress = false,
                     fixed_point = {max_iterations = 2, max_halvings = 0}}
T.assert_equal(rn.steps, 0, "evolve: no step taken")
T.assert_true(rn.stop_reason:find("no convergence: step: Newton's method for the r > 1 system", 1, true) == 1,
              "evolve stops with 'no convergence: ...'", rn.stop_reason)
T.assert_true(cn:time() == 0 and maxdiff(cn, before) == 0, "evolve: the cluster is unchanged")
-- Options are per call: the next step uses the defaults again.
T.assert_true(cn:step{flow = "sd", tau = 1e-3, exact_volumes = false}.fixed_point_iterations >= 2, "defaults again")

-- evolve's on_step reports carry the fields.
local seen = {}
local re = with(A.l1{eps = 0.1, r = 3}):evolve{flow = "sd", tau = 1e-3, exact_volumes = false, steps = 2, progress = false,
  fixed_point = {tol = 1e-9}, on_step = function(s) seen[#seen + 1] = s end}
T.assert_true(re.steps == 2 and #seen == 2, "evolve with fixed_point takes its steps")
for _, s in ipairs(seen) do
  T.assert_true(s.fixed_point_iterations >= 2 and s.fixed_point_change <= 1e-9 and s.substeps >= 1,
                "on_step reports fixed_point_iterations/change/substeps")
end
T.assert_true(re.max_energy_increase <= 0, "r = 3 evolve: no energy increase", re.max_energy_increase)

-- fixed_point option errors (checked before anything moves).
local cf = with(A.l1{eps = 0.1, r = 3})
local fp = function(o) return {flow = "sd", tau = 1e-3, exact_volumes = false, fixed_point = o} end
bad("fixed_point: tol must be positive and finite, got 0", cf.step, cf, fp{tol = 0})
bad("fixed_point: tol must be positive and finite, got -1", cf.step, cf, fp{tol = -1})
bad("step: fixed_point: unknown option 'tols'", cf.step, cf, fp{tols = 1e-8})
bad("fixed_point: max_iterations must be at least 2, got 1", cf.step, cf, fp{max_iterations = 1})
bad("step: fixed_point: option 'max_iterations' must be an integer", cf.step, cf,
    fp{max_iterations = 2.5})
bad("fixed_point: max_halvings must be in 0..20, got 21", cf.step, cf, fp{max_halvings = 21})
bad("fixed_point: max_halvings must be in 0..20, got -1", cf.step, cf, fp{max_halvings = -1})
bad("step: option 'fixed_point' must be a table {tol, max_iterations, max_halvings}", cf.step, cf,
    {flow = "sd", tau = 1e-3, exact_volumes = false, fixed_point = 5})
local ev = function(o) return {flow = "sd", tau = 1e-3, exact_volumes = false, steps = 1, fixed_point = o} end
bad("fixed_point: tol must be positive and finite, got 0", cf.evolve, cf, ev{tol = 0})
bad("evolve: fixed_point: unknown option 'foo'", cf.evolve, cf, ev{foo = 1})
bad("evolve: option 'fixed_point' must be a table", cf.evolve, cf,
    {flow = "sd", tau = 1e-3, exact_volumes = false, steps = 1, fixed_point = true})
T.assert_true(cf:time() == 0 and maxdiff(cf, with()) == 0, "bad fixed_point options change nothing")

-- A failing mobility function: the step raises an error and the cluster is unchanged.
local cm = db:clone()
local mref = cm:clone()
cm:set_mobility(2, function() return -1 end)
bad("surface 2: the mobility function is -1 at the normal", cm.step, cm, {flow = "mcf", tau = 1e-3})
cm:set_mobility(2, function() return 0 / 0 end)
bad("surface 2: the mobility function is nan", cm.step, cm, {flow = "sd", tau = 1e-3})
cm:set_mobility(2, function() error("no beta here") end)
bad("no beta here", cm.step, cm, {flow = "sd", tau = 1e-3})
bad("mobility: beta(", cm.step, cm, {flow = "mcf", tau = 1e-3})
cm:set_mobility(2, function() return "fast" end)
bad("returned string where a number was expected", cm.step, cm, {flow = "sd", tau = 1e-3})
T.assert_true(cm:time() == 0 and maxdiff(cm, mref) == 0, "failed mobility: the cluster is unchanged")
cm:set_mobility(2, function() return 0 end)
bad("surface 2: the mobility function is 0", cm.evolve, cm,
    {flow = "sd", tau = 1e-3, exact_volumes = false, steps = 2, progress = false})
T.assert_true(cm:time() == 0 and maxdiff(cm, mref) == 0, "evolve: the cluster is unchanged")

-- A clone keeps anisotropy and mobility: it steps exactly like its original.
local orig = with(A.ellipsoidal{1, 2, 4}, 0.5)
local copy = orig:clone()
T.assert_equal(copy:mobility(1), 0.5, "a clone keeps the mobility")
T.assert_equal(copy:energy(), orig:energy(), "a clone keeps the anisotropic energy")
orig:step{flow = "sd", tau = 1e-3, exact_volumes = false}
copy:step{flow = "sd", tau = 1e-3, exact_volumes = false}
T.assert_equal(maxdiff(orig, copy), 0, "a clone steps like its original")

-- The anisotropic force balance (2.3) at triple lines: report.angles.force_imbalance =
-- |sum_j Pi_T gamma_j'(nu_j)| / sum_j |Pi_T gamma_j'(nu_j)|. Exact values on the initial double
-- bubble (two half balls: at the equator the caps leave along +-z, the disk radially inwards):
-- 1/3 for isotropic films (|mu_3| / 3), and with the disk's gamma = sqrt(p.Gp), G = diag(1, 1, 4),
-- whose gamma'(z) = 2 z: 2 / (2 + 1 + 1) = 1/2. The caps' normals are radial, where that G acts
-- as the identity: 1/3 again.
local fb = froth.double_bubble{h = 0.1}
T.assert_near(fb:report().angles.force_imbalance, 1 / 3, 0.005, "force_imbalance 1/3 at 90/90/180")
for i, expected in ipairs({1 / 3, 1 / 3, 1 / 2}) do
  local d = fb:clone()
  d:set_anisotropy(i, A.ellipsoidal{1, 1, 4})
  T.assert_near(d:report().angles.force_imbalance, expected, 0.005,
                ("force_imbalance with diag(1, 1, 4) on surface %d"):format(i))
end
-- Under SD with l1 (eps = 0.1) on one cap the junction moves to the anisotropic balance (2.3),
-- far from the isotropic Young angles: the imbalance falls from 0.31 to 0.04 by t = 0.3
-- (measured), while the angles stay 50 degrees off 120.
local fl = froth.double_bubble{h = 0.15}
fl:set_anisotropy(1, A.l1{eps = 0.1})
local before = fl:report().angles.force_imbalance
fl:evolve{flow = "sd", tau = 1e-3, exact_volumes = false, tau_start = 1e-6, T = 0.3, progress = false}
local after = fl:report().angles
T.assert_true(before > 0.3 and after.force_imbalance < 0.06,
              "l1 cap: the force imbalance (2.3) falls below 0.06",
              before .. " -> " .. after.force_imbalance)
T.assert_true(after.young_error > 30, "l1 cap: the isotropic Young angles do not hold",
              tostring(after.young_error))
T.summary()
