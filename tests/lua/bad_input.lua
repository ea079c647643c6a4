-- The bad-input table (issue 17): every reproducer of a crash, hang or misleading message found
-- by a hostile user, each with the message fragment it must give now, so none can come back.
-- Each case also checks that the object it was given is unchanged afterwards.
local T = require("froth.test")
local gmsh = froth.has("gmsh")
local dir = os.tmpname()
os.remove(dir)
assert(os.execute("mkdir -p " .. dir))
local function path(name) return dir .. "/" .. name end
local function write_file(name, text)
  local f = assert(io.open(path(name), "wb"))
  f:write(text)
  f:close()
  return path(name)
end
local function read_file(p)
  local f = assert(io.open(p, "rb"))
  local s = f:read("a")
  f:close()
  return s
end

local function cell() -- a small closed cell without gmsh
  return froth.box_cells{x = {0, 1}, y = {0, 1}, z = {0, 1}, cell = function() return 1 end}
end

-- 1. Userdata: the metatables are protected, and a destroyed object is an error, not freed memory.
for _, case in ipairs{
  {"froth.Cluster", cell(), function(o) return o:energy() end},
  {"froth.Wall", froth.plane{}, function(o) return o:distance(0, 0, 1) end},
  {"froth.Anisotropy", froth.anisotropy{{G = {1, 4, 9}}}, function(o) return o:gamma(0, 0, 1) end},
} do
  local name, obj, use = case[1], case[2], case[3]
  T.assert_equal(getmetatable(obj), name, name .. ": getmetatable shows the type only")
  T.check_error("attempt to call a nil value", function() getmetatable(obj).__gc(obj) end)
  local gc = debug.getmetatable(obj).__gc
  gc(obj)
  T.check_error(name .. ": the object has been destroyed (its __gc ran)", use, obj)
  gc(obj) -- twice: harmless
  T.check_error(name .. ": the object has been destroyed", use, obj)
end
do
  local c = cell()
  local w = froth.plane{}
  debug.getmetatable(w).__gc(w)
  T.check_error("froth.Wall: the object has been destroyed", froth.cluster,
                {vertices = {{0, 0, 0}}, surfaces = {}, walls = w})
  T.check_error("cannot destroy a cluster while a call on it is running", c.evolve, c,
                {flow = "mcf", tau = 1e-3, steps = 1,
                 on_step = function() debug.getmetatable(c).__gc(c) end})
  T.assert_true(c:energy() > 0, "the cluster survives a __gc from its own callback")
end

-- 2-3. Files: malformed, huge claims, not regular. Read by froth's own reader (no gmsh).
do
  local s = cell()
  s:write(path("cell.msh"))
  local text = read_file(path("cell.msh"))
  -- the reproducer of the gmsh crash: the last number of the first element line set to -1
  local at = text:find("$Elements\n", 1, true)
  local first = text:find("\n", text:find("\n", text:find("\n", at, true) + 1, true) + 1, true)
  local line_end = text:find("\n", first + 1, true) -- first .. line_end: the first element line
  local element = text:sub(first + 1, line_end - 1)
  local broken = text:sub(1, first) .. element:gsub("%d+$", "-1") .. text:sub(line_end)
  T.check_error("node tag -1 is out of range", froth.read, write_file("bad_node.msh", broken))
  local huge = text:gsub("\n(%d+) (%d+) 1 (%d+)\n2 1 0", "\n%1 2000000000 1 %3\n2 1 0", 1)
  T.check_error("number of nodes 2000000000 cannot fit in the", froth.read, write_file("huge.msh", huge))
  local absurd = text:gsub("\n(%d+) (%d+) 1 (%d+)\n2 1 0", "\n%1 1000000000000 1 %3\n2 1 0", 1)
  T.check_error("number of nodes 1000000000000 is out of range", froth.read,
                write_file("absurd.msh", absurd))
  T.check_error("read: cannot open '/dev/zero': not a regular file", froth.read, "/dev/zero")
  T.check_error("Is a directory", function() return froth.read(dir) end)
end

-- 4. Messages that used to mislead.
T.check_error("coordinates must be at most 1e100 in magnitude", froth.cluster,
              {vertices = {{0, 0, 0}, {1e300, 0, 0}, {0, 1, 0}}, surfaces = {{{1, 2, 3}}}})
do
  local c = cell()
  local e = c:energy()
  c:set_mobility("all", function() return 1e300 end)
  T.check_error("must be between 1e-100 and 1e100", c.step, c, {flow = "sd", tau = 1e-3})
  T.check_error("beta must be between 1e-100 and 1e100", c.set_mobility, c, "all", 1e300)
  T.assert_equal(c:energy(), e, "a failed step leaves the cluster unchanged")
end
T.check_error("G's entries must be between 1e-100 and 1e100", froth.anisotropy, {{G = {1e300, 1e300, 1e300}}})
T.check_error("G's entries must be between 1e-100 and 1e100", froth.anisotropy, {{G = {1e-300, 1e-300, 1e-300}}})
T.check_error("G is too close to singular (eigenvalues", froth.anisotropy, {{G = {1, 1, 1e-20}}})
T.assert_near(froth.anisotropy{{G = {1e90, 1e90, 1e90}}}:gamma(0, 0, 1), 1e45, 1e31,
              "a scaled identity is a scaled norm")
T.check_error("anisotropy: gamma of a non-finite vector", function()
  return froth.anisotropy{{G = {1, 4, 9}}}:gamma{0 / 0, 0, 0}
end)
if gmsh then
  for _, solid in ipairs{{"ball", r = 1e300}, {"ball", r = 1e-300}, {"ball", r = 1, scale = {1e300, 1, 1}}} do
    T.check_error("they must lie in [1e-5, 1e5]", froth.fragment, {solids = {solid}})
  end
  T.check_error("coordinates must be at most 1e5", froth.fragment,
                {solids = {{"ball", r = 1, center = {1e300, 0, 0}}}})
end

-- 5. Re-entrancy: callbacks may read the cluster, never change it.
do
  local c = cell()
  local seen
  T.check_error("evolve: the cluster is busy: c:evolve is running", c.evolve, c,
                {flow = "mcf", tau = 1e-3, T = 0.01, on_step = function() c:evolve{flow = "mcf", tau = 1e-3, T = 0.05} end})
  T.assert_true(c:time() < 0.0015, "the outer evolve stopped at its first step")
  local r = c:evolve{flow = "mcf", tau = 1e-3, steps = 2, on_step = function(s) seen = c:energy() end}
  T.assert_equal(seen, r.energy, "on_step may read the cluster")
  c:set_mobility("all", function() c:step{flow = "mcf", tau = 1e-3} return 1 end)
  T.check_error("step: the cluster is busy: c:step is running", c.step, c, {flow = "sd", tau = 1e-3})
  c:set_mobility("all", 1)
  for _, change in ipairs{
    function() c:set_sigma(1, 2) end, function() c:refine() end, function() c:set_volume(1, 2) end,
    function() c:minimize{} end, function() c:set_anisotropy("all", nil) end,
  } do
    T.check_error("the cluster is busy", c.evolve, c, {flow = "mcf", tau = 1e-3, steps = 1, on_step = change})
  end
  T.assert_equal(c:sigma(1), 1, "no change from a refused callback")
end
if gmsh then
  local s = froth.sphere{h = 0.3}
  local v = s:volumes()[1]
  T.check_error("body 1 would vanish (volume", s.step, s, {flow = "mcf", tau = 1e10})
  T.assert_equal(s:volumes()[1], v, "the sphere is unchanged")
  local r = s:evolve{flow = "mcf", tau = 1e10, steps = 1}
  T.assert_equal(r.event and r.event.kind, "step failed", "evolve reports the extinction as an event")
  T.check_error("break the triangle inequality", froth.double_bubble, {h = 0.3, sigma = {1, 1, 3}})
  local b = froth.double_bubble{h = 0.3}
  T.check_error("set_sigma: the tensions at triple line 1 (surfaces 1, 2, 3: sigma 1, 1, 2)", b.set_sigma, b, 3, 2)
  T.assert_equal(b:sigma(3), 1, "a refused sigma is not set")
  b:set_sigma(3, 1.99)
end
do -- the same without gmsh: two cells, three surfaces at one triple line
  local b = froth.box_cells{x = {0, 1, 2}, y = {0, 1}, z = {0, 1}, cell = function(i) return i end}
  T.check_error("break the triangle inequality", b.set_sigma, b, 3, 5)
  T.assert_equal(b:sigma(3), 1, "a refused sigma is not set")
end

-- 6. Writes and clones.
do
  local c = cell()
  write_file("c.vtu.tmp", "mine")
  c:write(path("c.vtu"))
  T.assert_equal(read_file(path("c.vtu.tmp")), "mine", "a user's .tmp file is not clobbered")
  local a = froth.box_cells{x = {0, 1, 2}, y = {0, 1}, z = {0, 1}, cell = function(i) return i end}
  for _ = 1, 3 do a:step{flow = "sd", tau = 1e-3} end
  local b = a:clone()
  for _ = 1, 5 do a:step{flow = "sd", tau = 1e-3}; b:step{flow = "sd", tau = 1e-3} end
  T.assert_true(T.same_positions(a, T.positions(b)), "clone-and-continue is bit-identical")
end

os.execute("rm -rf " .. dir)
T.summary()
