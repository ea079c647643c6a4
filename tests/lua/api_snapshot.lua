-- c:snapshot and evolve{snapshots}: PNG pictures (render/snapshot.h; the pixel statistics are
-- checked in tests/unit/snapshot_test.cpp). Here: the files, their size fields, what the
-- returned statistics say of different clusters and views, the frame series, the errors.
local T = require("froth.test")
local dir = (os.getenv("FROTH_TEST_TMP") or "/tmp") .. "/froth_api_snapshot_" .. tostring(os.time())
  .. "_" .. tostring(math.random(1e9))

local function png_size(path)
  local f = assert(io.open(path, "rb"))
  local head = f:read(24)
  f:close()
  T.assert_equal(head:sub(1, 8), "\137PNG\r\n\26\n", path .. " is a PNG")
  return string.unpack(">I4", head, 17), string.unpack(">I4", head, 21)
end

local cells = froth.box_cells{x = {0, 1, 2, 3}, y = {0, 1}, z = {0, 1}, cell = function(i) return i end}
cells:refine()
local s = cells:snapshot(dir .. "/cells.png", {size = {320, 200}})
local w, h = png_size(dir .. "/cells.png")
T.assert_equal(w, 320, "the width asked for")
T.assert_equal(h, 200, "the height asked for")
T.assert_true(s.coverage > 0.1 and s.coverage < 0.9, "the cells cover part of the picture", tostring(s.coverage))
T.assert_true(s.surfaces >= 3, "the outer films of the three cells show their colours", tostring(s.surfaces))
-- Looking down the row of cells from its end shows less of it than from the side.
local along = cells:snapshot(dir .. "/along.png", {size = {320, 200}, view = {1, 0, 0}})
local side = cells:snapshot(dir .. "/side.png", {size = {320, 200}, view = {0, 1, 0}})
T.assert_true(along.coverage < side.coverage, "the end view covers less than the side view",
              along.coverage .. " vs " .. side.coverage)
T.assert_true(along.surfaces < side.surfaces, "and shows fewer films", along.surfaces .. " vs " .. side.surfaces)
local hc = cells:snapshot(dir .. "/curvature.png", {color = "mean_curvature"})
T.assert_equal(hc.surfaces, 0, "mean_curvature colours by curvature, not by surface")
T.assert_equal(select(1, png_size(dir .. "/curvature.png")), 800, "the default size is 800 x 600")

-- evolve{snapshots}: the start, every `every` steps and the end.
local run = froth.box_cells{x = {0, 1}, y = {0, 1}, z = {0, 1}, cell = function() return 1 end}
run:refine()
run:evolve{flow = "sd", tau = 1e-3, steps = 5, every = 2, snapshots = dir .. "/frames/f",
           snapshot = {size = {64, 48}}}
for k = 0, 3 do
  local fw, fh = png_size(("%s/frames/f_%06d.png"):format(dir, k))
  T.assert_true(fw == 64 and fh == 48, "frame " .. k .. " at the snapshot size")
end
T.assert_true(io.open(dir .. "/frames/f_000004.png") == nil, "frames 0, 2, 4 and the end 5: four")

T.check_error("snapshot: option 'size' must be {width, height}, integers in 16..8192", cells.snapshot, cells, dir .. "/x.png", {size = {8, 8}})
T.check_error("snapshot: option 'view' must be {x, y, z}", cells.snapshot, cells, dir .. "/x.png", {view = 1})
T.check_error("snapshot: view must be a finite non-zero direction", cells.snapshot, cells, dir .. "/x.png", {view = {0, 0, 0}})
T.check_error("snapshot: color must be \"surface\" or \"mean_curvature\", got 'area'", cells.snapshot, cells, dir .. "/x.png", {color = "area"})
T.check_error("snapshot: unknown option 'colour'", cells.snapshot, cells, dir .. "/x.png", {colour = "surface"})
T.check_error("snapshot: cannot create directory", cells.snapshot, cells, "/proc/froth_none/x.png")
T.check_error("evolve: snapshot: unknown option 'sise'", run.evolve, run,
              {flow = "sd", tau = 1e-3, steps = 1, snapshots = dir .. "/g", snapshot = {sise = {1, 1}}})
os.execute("rm -rf '" .. dir .. "'")
T.summary()
