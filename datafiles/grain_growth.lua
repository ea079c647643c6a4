-- datafiles/grain_growth.lua — ideal grain growth: mean curvature flow of a periodic network of
-- grains (the Voronoi cells of n random sites, relaxed by Lloyd's algorithm, each grain keeping
-- its own volume as the flow changes it: no volume constraint), every film of tension and
-- mobility 1, with the topological transitions that let it coarsen (inverse T1s of shrinking
-- triangular films, T1s of shrinking triple lines, collapses of two-sided and disc films, pinches
-- of films whose waist closes between two of their lines, pops of vanishing grains;
-- docs/lua_api.md "Topological transitions").
--
-- After every step without a transition or mesh upkeep it checks each grain against the
-- MacPherson-Srolovitz law (Nature 446, 2007), in froth's units (normal velocity kappa, the sum
-- of the principal curvatures):
--
--     dV/dt = -2 pi (L - (1/6) sum of the grain's triple-line lengths),
--
-- L the grain's mean width in their normalisation (c:grain_measures: twice the classical mean
-- breadth, from the exterior angles at the mesh's edges), dV/dt the volume change of the step
-- over tau, the right-hand side the mean of its values before and after the step. The residual
-- of a grain is |dV/dt - law| / (2 pi L): each term of the law is of the size 2 pi L, so this is
-- the fraction of the curvature integral the flow misses (time and curvature discretisation,
-- and how far the lines' angles are from 120 degrees). Prints the transitions as they come, a
-- line per `every` steps, and the residuals' median and 90th percentile at the end.
--
-- Sample runs:  froth datafiles/grain_growth.lua                    (200 grains, T = 0.05)
--               froth datafiles/grain_growth.lua n=27 seed=2 lloyd=5 T=0.5
--               FROTH_SMOKE=1 froth datafiles/grain_growth.lua     (ctest: 27 grains, 5 steps)
--               froth datafiles/grain_growth.lua T=2 save=g.froth  (the last state, for froth.load)
--               froth datafiles/grain_growth.lua T=2 save=g.froth checkpoint=50
--                                               (also every 50 steps to g_checkpoint.froth, to
--                                               resume after a crash or replay a stop)
--               froth datafiles/grain_growth.lua resume=g.froth T=1  (go on from a saved state;
--                                               the transitions' memory is in it, so the run
--                                               continues as the saving run would have)
local script = require("froth.script")
local measure = require("froth.measure")
local opts = script.options({n = 200, seed = 1, lloyd = 20, h = 0.4, tau = 2e-3, T = 0.05,
                             every = 5, output = "out", save = "", checkpoint = 0, resume = ""},
                            arg)
if opts.smoke then opts.n, opts.seed, opts.lloyd, opts.T = 27, 2, 5, 5 * opts.tau end
if math.type(opts.checkpoint) ~= "integer" or opts.checkpoint < 0 then
  error(("grain_growth: checkpoint must be a number of steps (0: none), got '%s'"):format(opts.checkpoint))
end
if opts.checkpoint > 0 and opts.save == "" then
  error("grain_growth: checkpoint = N saves beside the file given as save = ...")
end

-- a file of its own, so that the state before a stop stays beside the final one
local checkpoint_path = opts.save:gsub("%.froth$", "") .. "_checkpoint.froth"

local c
if opts.resume ~= "" then
  c = froth.load(opts.resume)
  print(("resumed from %s at t = %.4f"):format(opts.resume, c:time()))
else
  c = froth.foam{n = opts.n, seed = opts.seed, lloyd = opts.lloyd, h = opts.h,
                 equal_volumes = false}
end
local info = c:info()
print(("%d grains%s: %d films, %d triple lines, %d quadruple points; %d vertices")
      :format(info.bodies, opts.resume ~= "" and "" or
              (" (seed %d, %d Lloyd steps)"):format(opts.seed, opts.lloyd),
              info.surfaces, #c:triple_lines(), #c:quadruple_points(), info.vertices))

local residuals, counts, clean_steps, deferred, retried = {}, {}, 0, 0, 0
local steps, stop = 0, "T reached"
local t_end = c:time() + opts.T
local clock = os.clock()
while c:time() < t_end - 1e-12 do
  local before, t_before = c:grain_measures(), c:time()
  -- the last step ends on T (after a retried step the steps are shorter than tau for a while,
  -- so the steps need not add up to it)
  local r = c:evolve{flow = "mcf", tau = math.min(opts.tau, t_end - c:time()), steps = 1,
                     progress = false}
  steps = steps + 1
  for _, e in ipairs(r.events) do
    counts[e.kind] = (counts[e.kind] or 0) + 1
    print(("  t = %.4f  %s: %s"):format(e.t, e.kind, e.where))
  end
  deferred, retried = deferred + r.deferred, retried + r.rejected_steps
  if r.stop_reason ~= "steps done" then stop = r.stop_reason; break end
  local upkeep = r.split_edges + r.collapsed_edges + r.flipped_edges
  if #r.events == 0 and upkeep == 0 then
    clean_steps = clean_steps + 1
    -- the step's own length: after a retried step evolve's steps are shorter than tau
    local dt = c:time() - t_before
    for _, x in ipairs(measure.macpherson_srolovitz(before, c:grain_measures(), dt)) do
      residuals[#residuals + 1] = x
    end
  end
  if opts.checkpoint > 0 and steps % opts.checkpoint == 0 then c:save(checkpoint_path) end
  if steps % opts.every == 0 then
    local made = 0
    for _, n in pairs(counts) do made = made + n end
    print(("step %4d  t = %.4f  energy %.6f  grains %d  transitions so far %d")
          :format(steps, c:time(), c:energy(), c:info().bodies, made))
  end
end
local seconds = os.clock() - clock

local made = {}
for kind, n in pairs(counts) do made[#made + 1] = ("%d %s"):format(n, kind) end
table.sort(made)
print(("%d steps to t = %.4f in %.1f s: %s; %d grains left"):format(steps, c:time(), seconds,
      #made > 0 and table.concat(made, ", ") or "no transitions", c:info().bodies))
print("stop: " .. stop)
print(("%d steps went on past a sliver the upkeep left (deferred); steps retried shorter: %d")
      :format(deferred, retried))
table.sort(residuals)
if #residuals > 0 then
  local function quantile(q) return residuals[math.max(1, math.ceil(q * #residuals))] end
  print(("MacPherson-Srolovitz over %d grain steps (%d steps without transitions or upkeep):")
        :format(#residuals, clean_steps))
  print(("  |dV/dt - law| / (2 pi L): median %.3g, 90th percentile %.3g, largest %.3g")
        :format(quantile(0.5), quantile(0.9), residuals[#residuals]))
end
local path = opts.output .. "/grain_growth.vtu"
c:write(path)
print("wrote " .. path)
if opts.save ~= "" then -- the last state, to load and go on from (froth.load)
  c:save(opts.save)
  print("saved " .. opts.save)
end
