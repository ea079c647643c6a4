-- froth side of the statics benchmark (statics.sh): one static equilibrium at fixed volumes by
-- c:minimize{tol}, from boxes meshed by gmsh at size h; prints one line per (h, tol) with the
-- vertices, minimize's iterations and seconds, the area and its relative error against the
-- reference, and the volume error. The problems (the same boxes as the Evolver datafiles):
--   db11    two unit cubes side by side (two_cubes.fe), volumes (1, 1): the standard double
--           bubble, area 3 (9 pi)^(1/3) = 9.1394216780693
--   db12    the same cubes with c:set_volume(2, 2), volumes (1, 2): the standard double bubble
--           of (1, 2), area 11.8542931280002 (double_bubble_exact.lua)
--   triple  the unit cubes [0,1]^3, [1,2]x[0,1]x[0,1] and the slab [0,2]x[0,1]x[1,1.5] on them
--           (three_cells.fe), volumes (1, 1, 1): the standard triple bubble; no closed form,
--           reference 13.1281682 = Evolver's levels 5 and 6 extrapolated (statics.sh)
--   froth bench/evolver/statics_froth.lua problem=db11 h=0.1 tol=1e-2 [levels=2]
-- start=boxes cut=N pre=P: the boxes of Evolver's datafiles without gmsh (froth.box_cells, h
-- ignored), refined P times before the first minimize.
-- levels = L > 0 runs Evolver's coarse-to-fine schedule: minimize on the gmsh mesh, then L times
-- c:refine() and c:minimize{tol, tau_start = 1e4} (near an equilibrium the ramp of small first
-- steps is not needed: the first step is already the Dirichlet limit).
-- h and tol may be comma lists (h=0.1,0.08 tol=1e-1,1e-2): every pair runs in this process,
-- each from a fresh mesh (the search that chose statics.sh's h and tol). statics.sh times one
-- pair per process, so the process's seconds include startup and meshing.
local opts = require("froth.script").options({problem = "db11", h = 0.1, tol = 1e-2,
                                              max_iterations = 1000, ref = 0,
                                              levels = 0, start = "gmsh", cut = 1, pre = 2}, arg)
local function box(x, y, z, sx, sy, sz) return {"box", min = {x, y, z}, size = {sx, sy, sz}} end
local problems = {
  db11 = {ref = 3 * (9 * math.pi) ^ (1 / 3), solids = {box(0, 0, 0, 1, 1, 1), box(1, 0, 0, 1, 1, 1)}},
  db12 = {ref = 11.8542931280002, solids = {box(0, 0, 0, 1, 1, 1), box(1, 0, 0, 1, 1, 1)},
          volumes = {[2] = 2}},
  triple = {ref = 13.1281682, solids = {box(0, 0, 0, 1, 1, 1), box(1, 0, 0, 1, 1, 1),
                                          box(0, 0, 1, 2, 1, 0.5)}},
}
-- start = "boxes": the same boxes as Evolver's datafiles, built by froth.box_cells without gmsh
-- (every lattice interval cut into `cut` parts, like make_cells_fe.py's n; every rectangle into
-- 4 triangles at its centre), refined `pre` times before the first minimize.
local function boxes(problem, cut)
  local function axis(points)
    local t = {points[1]}
    for n = 2, #points do
      for m = 1, cut do t[#t + 1] = points[n - 1] + (points[n] - points[n - 1]) * m / cut end
    end
    return t
  end
  local z = problem == "triple" and {0, 1, 1.5} or {0, 1}
  return froth.box_cells{x = axis{0, 1, 2}, y = axis{0, 1}, z = axis(z), cell = function(i, _, k)
    local cube = i <= cut and 1 or 2
    if problem == "triple" and k > cut then return 3 end
    return cube
  end}
end

local p = problems[opts.problem]
if not p then error("statics_froth.lua: problem must be db11, db12 or triple, got " .. opts.problem) end
local ref = opts.ref ~= 0 and opts.ref or p.ref

local function list(v)
  local t = {}
  for x in tostring(v):gmatch("[^,]+") do t[#t + 1] = assert(tonumber(x), "bad number " .. x) end
  return t
end

print("FROTH problem  h      tol     vertices  iterations  minimize_s  area             error       volume_error  stop")
for _, h in ipairs(list(opts.h)) do
  for _, tol in ipairs(list(opts.tol)) do
    local c
    if opts.start == "boxes" then
      c = boxes(opts.problem, math.floor(opts.cut))
      for _ = 1, opts.pre do c:refine() end
    else
      c = froth.fragment{solids = p.solids, h = h}
    end
    for b, v in pairs(p.volumes or {}) do c:set_volume(b, v) end
    local r = c:minimize{tol = tol, max_iterations = opts.max_iterations}
    local iterations, seconds = r.iterations, r.wall_s
    for _ = 1, opts.levels do
      c:refine()
      r = c:minimize{tol = tol, max_iterations = opts.max_iterations, tau_start = 1e4}
      iterations, seconds = iterations + r.iterations, seconds + r.wall_s
    end
    r.iterations, r.wall_s = iterations, seconds
    print(("FROTH %-7s %-6g %-7g %8d  %10d  %10.3f  %.13f  %10.3e  %12.2e  %s"):format(opts.problem,
          h, tol, c:info().vertices, r.iterations, r.wall_s, r.energy, (r.energy - ref) / ref,
          r.volume_error, r.stop_reason))
  end
end
