-- datafiles/random_foam.lua — a random monodisperse foam: the Voronoi cells of n random sites
-- in a periodic cube, relaxed by Lloyd's algorithm (each step moves every site to its cell's
-- centroid), meshed by gmsh with films graded towards the diagram's short edges (split fans
-- without gmsh), the cells set to equal volumes, and minimized at those volumes. Prints the
-- diagram, the mesh, and the cost (a cell's area, films counted for both cells, over V^(2/3))
-- before and after; writes out/random_foam.vtu (the cells unwrapped). minimize stops where a
-- short triple line collapses ("topology: ..."), the cost fallen from 5.384 to 5.365 at the
-- defaults (docs/benchmarks.md, "Foams"); with transitions=1 it makes the T1s and inverse T1s
-- there and goes on for some rounds (docs/lua_api.md, c:minimize); hessian=1 adds Newton's steps
-- near the equilibrium (the 64 cells with transitions then converge), settle=1e-7 ends a run
-- whose energy has stopped moving.
--
-- Sample runs:  froth datafiles/random_foam.lua                 (64 cells, 50 Lloyd steps: 5 s)
--               froth datafiles/random_foam.lua n=16 lloyd=0 mesher=fan
--               froth datafiles/random_foam.lua lloyd=20 transitions=1
--               froth datafiles/random_foam.lua transitions=1 hessian=1 max_iterations=3000
--               FROTH_SMOKE=1 froth datafiles/random_foam.lua  (ctest: 16 cells, 5 iterations)
local script = require("froth.script")
local opts = script.options({n = 64, seed = 1, lloyd = 50, h = 0.4, mesher = "", max_iterations = 1000,
                             transitions = 0, settle = 0, hessian = 0, output = "out"}, arg)
if opts.smoke then opts.n, opts.max_iterations = 16, 5 end
local mesher = opts.mesher ~= "" and opts.mesher or nil

local c = froth.foam{n = opts.n, seed = opts.seed, lloyd = opts.lloyd, h = opts.h, mesher = mesher}
local info = c:info()
local n = info.bodies
print(("%d cells (seed %d, %d Lloyd steps): %d films, %d triple lines, %d quadruple points; %d vertices")
      :format(n, opts.seed, opts.lloyd, info.surfaces, #c:triple_lines(), #c:quadruple_points(), info.vertices))
print(("flat cells: cost %.5f"):format(2 * c:energy() / n))
local r = c:minimize{max_iterations = opts.max_iterations, transitions = opts.transitions ~= 0,
                     settle = opts.settle, hessian = opts.hessian ~= 0}
print(("minimize: %d iterations (%d Newton) in %.2f s, residual %.3g, volume error %.2g"):format(r.iterations,
      r.hessian_steps, r.wall_s, r.residual, r.volume_error))
if r.events then
  local counts, kinds = {}, {}
  for _, e in ipairs(r.events) do counts[e.kind] = (counts[e.kind] or 0) + 1 end
  for kind, k in pairs(counts) do kinds[#kinds + 1] = ("%d %s"):format(k, kind) end
  table.sort(kinds)
  print(("%d transitions in %d rounds%s%s"):format(#r.events, r.rounds, #kinds > 0 and ": " or "",
                                                   table.concat(kinds, ", ")))
end
print(("cost %.5f; stop: %s"):format(2 * r.energy / n, r.stop_reason))
local path = opts.output .. "/random_foam.vtu"
c:write(path)
print("wrote " .. path)
