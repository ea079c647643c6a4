-- froth.evolver_fe: Surface Evolver datafiles (.fe) read by froth.read (issue 14, item 2).
-- The subset read: `vertices` (coordinates, `fixed`), `edges` (end points, `fixed`), `faces`
-- (oriented edge loops; `tension`/`density` per face), `bodies` (signed faces, `volume`),
-- `PARAMETER name = value`, `#define name value`, comments (`//`, `/* */`), and expressions in
-- numbers (pi, e, sin, cos, tan, sqrt, exp, log, abs, atan, asin, acos, ^); everything after
-- `read` is Evolver's command section and is not run. As Evolver does, a face of more than
-- three edges gets a vertex at its centroid and a triangle per edge (so the counts and areas
-- after reading are Evolver's). froth's surfaces are the faces joined across edges of exactly
-- two faces (a film between triple lines), each oriented consistently; bodies are closed by
-- films, and an edge between two fixed vertices on a film's border is a wire. Anything else
-- (constraints, boundaries, quantities, torus models, gravity, ...) is one error naming the
-- keyword and the line, never a wrong cluster.
local M = {}

local unsupported = {
  constraint = "constraints (walls given as level sets)",
  boundary = "parametric boundaries (wires with parameters)",
  quantity = "named quantities", method_instance = "method instances",
  torus = "the torus model", torus_filled = "the torus model", periods = "the torus model",
  symmetry_group = "symmetry groups", gravity_constant = "gravity", gravity = "gravity",
  string = "the string model", lagrange_order = "Lagrange elements",
  space_dimension = "other space dimensions", simplex_representation = "the simplex model",
  quadratic = "the quadratic model", volconst = "volconst", content = "constraint contents",
  energy = "constraint energies",
}

local function fail(path, line, fmt, ...)
  error(("read: %s:%d: " .. fmt):format(path, line, ...), 0)
end

--- The file's text without comments, as a list of {line number, tokens}.
local function tokenize(path, text)
  text = text:gsub("/%*.-%*/", function(c) return (c:gsub("[^\n]", " ")) end)
  local lines = {}
  local n = 0
  for raw in (text .. "\n"):gmatch("(.-)\r?\n") do
    n = n + 1
    local code = raw:gsub("//.*", "")
    local tokens = {}
    for token in code:gmatch("%S+") do tokens[#tokens + 1] = token end
    if #tokens > 0 then lines[#lines + 1] = {n = n, tokens = tokens} end
  end
  if text:find("/%*") then fail(path, n, "a comment /* is not closed") end
  return lines
end

--- Evaluates a number or expression token with the parameters and Lua's math.
local function evaluator(path, params)
  local env = {pi = math.pi, e = math.exp(1), sin = math.sin, cos = math.cos, tan = math.tan,
               sqrt = math.sqrt, exp = math.exp, log = math.log, abs = math.abs,
               atan = math.atan, asin = math.asin, acos = math.acos}
  setmetatable(env, {__index = function(_, k) return params[k:lower()] end})
  return function(token, line)
    local v = tonumber(token)
    if v then return v end
    if not token:match("^[%w%.%+%-%*/%^%(%)_]+$") then
      fail(path, line, "'%s' is not a number or an expression", token)
    end
    local f = load("return " .. token, "=expression", "t", env)
    local ok, value = pcall(f or error)
    if not (f and ok and type(value) == "number" and value == value and math.abs(value) < math.huge) then
      fail(path, line, "'%s' is not a number or an expression of known parameters", token)
    end
    return value
  end
end

local sections = {vertices = true, edges = true, faces = true, facets = true, bodies = true}
-- Model declarations that say what froth does anyway.
local ignored = {soapfilm = true, linear = true}
local singular = {vertices = "vertex", edges = "edge", faces = "face", bodies = "body"}
local attribute_list = {vertices = "fixed", edges = "fixed, color", faces = "tension, density, color",
                        bodies = "volume"}
-- The attributes each section may carry (colors are display only and ignored).
local allowed = {
  vertices = {fixed = true},
  edges = {fixed = true, color = true},
  faces = {tension = true, density = true, color = true, frontcolor = true, backcolor = true},
  bodies = {volume = true},
}

--- PARAMETER name = value or #define name value: stores the value in params.
local function read_definition(path, n, t, params, eval)
  local name, value
  if t[1]:lower() == "parameter" then
    name, value = table.concat(t, " ", 2):match("^([%a_][%w_]*)%s*=%s*(.-)%s*$")
    if not name then fail(path, n, "PARAMETER needs 'name = value'") end
    value = value:gsub("%s+", "")
  else
    name, value = t[2], t[3]
    if not (name and value) then fail(path, n, "#define needs a name and a value") end
  end
  params[name:lower()] = eval(value, n)
end

--- The attributes of an element line from token i on: {fixed, tension, volume}.
local function read_attributes(path, n, t, i, section, eval)
  local attrs = {}
  while t[i] do
    local a = t[i]:lower()
    if not allowed[section][a] then
      fail(path, n, "the attribute '%s' of %s %s is outside the .fe subset froth reads (%s)",
           t[i], section == "edges" and "an" or "a", singular[section], attribute_list[section])
    end
    if a == "fixed" then
      attrs.fixed = true
    elseif a == "tension" or a == "density" or a == "volume" then
      if not t[i + 1] then fail(path, n, "'%s' needs a value", t[i]) end
      attrs[a == "density" and "tension" or a] = eval(t[i + 1], n)
      i = i + 1
    else
      i = i + 1 -- a color: display only
    end
    i = i + 1
  end
  return attrs
end

--- One element line of a section: its id and record.
local function read_element(path, n, t, section, params, eval)
  local id = math.tointeger(tonumber(t[1]))
  if not id or id < 1 then fail(path, n, "expected an element id, got '%s'", t[1]) end
  -- Numbers (or expressions) first, then attributes: a bare word that is not a parameter or a
  -- constant starts the attributes.
  local i, numbers = 2, {}
  while t[i] do
    local word = t[i]:match("^[%a_][%w_]*$")
    if word and params[word:lower()] == nil and word ~= "pi" and word ~= "e" then break end
    numbers[#numbers + 1] = t[i]
    i = i + 1
  end
  local attrs = read_attributes(path, n, t, i, section, eval)
  if section == "vertices" then
    if #numbers ~= 3 then fail(path, n, "vertex %d needs 3 coordinates, got %d", id, #numbers) end
    return id, {x = {eval(numbers[1], n), eval(numbers[2], n), eval(numbers[3], n)},
                fixed = attrs.fixed, line = n}
  end
  local ids = {}
  for k, x in ipairs(numbers) do
    ids[k] = math.tointeger(eval(x, n))
    if not ids[k] or ids[k] == 0 or (section == "edges" and ids[k] < 0) then
      fail(path, n, "'%s' is not a%s %s id", x, section == "edges" and "" or " signed",
           section == "edges" and "vertex" or section == "faces" and "edge" or "face")
    end
  end
  if section == "edges" then
    if #ids ~= 2 then fail(path, n, "edge %d needs 2 vertices, got %d", id, #ids) end
    return id, {ids[1], ids[2], fixed = attrs.fixed, line = n}
  elseif section == "faces" then
    if #ids < 3 then fail(path, n, "face %d needs at least 3 edges", id) end
    return id, {loop = ids, tension = attrs.tension or 1, line = n}
  end
  return id, {faces = ids, volume = attrs.volume, line = n}
end

--- Parses the datafile: {vertices = {{x, fixed}}, edges = {{a, b, fixed}}, faces = {{loop,
--- tension, line}}, bodies = {{faces, volume, line}}}, each keyed by its Evolver id.
local function parse(path, lines)
  local params = {}
  local eval = evaluator(path, params)
  local data = {vertices = {}, edges = {}, faces = {}, bodies = {}}
  local section
  for _, l in ipairs(lines) do
    local t, n = l.tokens, l.n
    local key = t[1]:lower()
    if key == "read" then break end
    if key == "parameter" or key == "#define" then
      read_definition(path, n, t, params, eval)
      section = nil
    elseif sections[key] then
      section = key == "facets" and "faces" or key
    elseif ignored[key] and #t == 1 then
      section = nil
    elseif unsupported[key] ~= nil or (section == nil and not tonumber(key)) then
      fail(path, n, "'%s' (%s) is outside the .fe subset froth reads (vertices, edges, faces, "
           .. "bodies, fixed, tension, volume, PARAMETER, #define)", t[1], unsupported[key] or "unknown keyword")
    else
      local id, record = read_element(path, n, t, section, params, eval)
      if data[section][id] then fail(path, n, "%s %d is defined twice", singular[section], id) end
      data[section][id] = record
    end
  end
  return data
end

--- The vertex loop of a face from its signed edges, checked to be closed.
local function face_vertices(path, data, fid, face)
  local loop = {}
  for k, se in ipairs(face.loop) do
    local e = data.edges[math.abs(se)]
    if not e then fail(path, face.line, "face %d uses edge %d, which is not defined", fid, math.abs(se)) end
    local a, b = e[1], e[2]
    if se < 0 then a, b = b, a end
    if k > 1 and loop[#loop] ~= a then
      fail(path, face.line, "face %d: edge %d does not start where edge %d ends", fid, se, face.loop[k - 1])
    end
    if k == 1 then loop[1] = a end
    loop[#loop + 1] = b
  end
  if loop[#loop] ~= loop[1] then fail(path, face.line, "face %d: its edge loop is not closed", fid) end
  loop[#loop] = nil
  return loop
end

--- Groups the faces into surfaces (joined across edges of exactly two faces) and orients
--- each group consistently; returns {faces (ids), flip (per face)} per surface.
local function surfaces_of(path, loops, order, line_of)
  local uses = {} -- undirected edge key -> list of {face, direction}
  for _, f in ipairs(order) do
    local loop = loops[f]
    for k = 1, #loop do
      local a, b = loop[k], loop[k % #loop + 1]
      local key = math.min(a, b) .. "-" .. math.max(a, b)
      uses[key] = uses[key] or {}
      table.insert(uses[key], {face = f, dir = a < b and 1 or -1})
    end
  end
  local group, flip, groups = {}, {}, {}
  for _, f0 in ipairs(order) do
    if not group[f0] then
      local g = {faces = {}}
      groups[#groups + 1] = g
      group[f0], flip[f0] = #groups, false
      local queue = {f0}
      while #queue > 0 do
        local f = table.remove(queue)
        g.faces[#g.faces + 1] = f
        local loop = loops[f]
        for k = 1, #loop do
          local a, b = loop[k], loop[k % #loop + 1]
          local u = uses[math.min(a, b) .. "-" .. math.max(a, b)]
          if #u == 2 then
            local mine, other = u[1], u[2]
            if mine.face ~= f then mine, other = other, mine end
            -- Opposite traversals after the flips: same surface, consistent orientation.
            local want = (mine.dir == other.dir) ~= flip[f]
            if group[other.face] == nil then
              group[other.face], flip[other.face] = #groups, want
              queue[#queue + 1] = other.face
            elseif flip[other.face] ~= want then
              fail(path, line_of[f], "the faces around face %d cannot be oriented consistently "
                   .. "(a non-orientable film)", f)
            end
          end
        end
      end
    end
  end
  return groups, group, flip
end

--- froth's bodies from the datafile's: the films (face groups) of their faces, each whole;
--- returns the bodies' surface lists and their target volumes (nil: keep the volume).
local function bodies_of(path, data, groups, group)
  local bodies, volumes = {}, {}
  local bids = {}
  for id in pairs(data.bodies) do bids[#bids + 1] = id end
  table.sort(bids)
  for _, id in ipairs(bids) do
    local b, set, list = data.bodies[id], {}, {}
    for _, sf in ipairs(b.faces) do
      local g = group[math.abs(sf)]
      if not g then fail(path, b.line, "body %d uses face %d, which is not defined", id, math.abs(sf)) end
      if not set[g] then set[g] = 0; list[#list + 1] = g end
      set[g] = set[g] + 1
    end
    for _, g in ipairs(list) do
      if set[g] ~= #groups[g].faces then
        fail(path, b.line, "body %d uses %d of the %d faces of one film (faces joined across "
             .. "edges of two faces); froth's bodies are bounded by whole films", id, set[g], #groups[g].faces)
      end
    end
    table.sort(list)
    bodies[#bodies + 1] = list
    volumes[#bodies] = b.volume
  end
  return bodies, volumes
end

--- The cluster of an Evolver datafile's text (froth.read reads the file, with its limits, and
--- calls this; path names the file in messages). opts must be empty: an .fe file says its
--- fixed vertices itself, and walls would come from constraints, which this subset refuses.
function M.from_text(text, path, opts)
  local froth = require("froth")
  if opts ~= nil then
    if type(opts) ~= "table" then error("read: expected an option table {...}, got " .. type(opts), 0) end
    for k in pairs(opts) do
      error(("read: option '%s' is not used for an .fe file (the datafile itself says which "
             .. "vertices are fixed; its constraints are not read)"):format(tostring(k)), 0)
    end
  end
  local data = parse(path, tokenize(path, text))
  -- Vertices in id order; ids may have gaps (Evolver allows it).
  local vid, V, fixed = {}, {}, {}
  local vids = {}
  for id in pairs(data.vertices) do vids[#vids + 1] = id end
  table.sort(vids)
  if #vids == 0 then error("read: " .. path .. ": no vertices", 0) end
  for _, id in ipairs(vids) do
    V[#V + 1] = data.vertices[id].x
    vid[id] = #V
    if data.vertices[id].fixed then fixed[#fixed + 1] = #V end
  end
  for id, e in pairs(data.edges) do
    for _, v in ipairs{e[1], e[2]} do
      if not vid[v] then fail(path, e.line, "edge %d uses vertex %s, which is not defined", id, tostring(v)) end
      -- froth fixes vertices, not edges: a fixed edge must have fixed ends (a wire).
      if e.fixed and not data.vertices[v].fixed then
        fail(path, e.line, "edge %d is fixed but its vertex %d is not (froth holds vertices; fix "
             .. "both ends of a fixed edge)", id, v)
      end
    end
  end
  local order, loops = {}, {}
  for id in pairs(data.faces) do order[#order + 1] = id end
  table.sort(order)
  if #order == 0 then error("read: " .. path .. ": no faces", 0) end
  for _, id in ipairs(order) do loops[id] = face_vertices(path, data, id, data.faces[id]) end
  local line_of = {}
  for id, face in pairs(data.faces) do line_of[id] = face.line end
  local groups, group, flip = surfaces_of(path, loops, order, line_of)
  -- Triangles: a face of more than 3 vertices gets its centroid as a new vertex (Evolver's).
  local surfaces = {}
  for gi, g in ipairs(groups) do
    local tension = data.faces[g.faces[1]].tension
    local tris = {}
    for _, fid in ipairs(g.faces) do
      if data.faces[fid].tension ~= tension then
        fail(path, data.faces[fid].line, "face %d has tension %g but joins faces of tension %g "
             .. "across an edge of two faces (one film must have one tension)", fid,
             data.faces[fid].tension, tension)
      end
      local loop = {}
      for k, v in ipairs(loops[fid]) do loop[k] = vid[v] end
      if flip[fid] then
        local r = {}
        for k = #loop, 1, -1 do r[#r + 1] = loop[k] end
        loop = r
      end
      if #loop == 3 then
        tris[#tris + 1] = loop
      else
        local c = {0, 0, 0}
        for _, v in ipairs(loop) do for d = 1, 3 do c[d] = c[d] + V[v][d] / #loop end end
        V[#V + 1] = c
        for k = 1, #loop do tris[#tris + 1] = {#V, loop[k], loop[k % #loop + 1]} end
      end
    end
    surfaces[gi] = {facets = tris, sigma = tension}
  end
  local bodies, volumes = bodies_of(path, data, groups, group)
  local c = froth.cluster{vertices = V, surfaces = surfaces, bodies = bodies,
                          fixed = #fixed > 0 and fixed or nil}
  for b, v in pairs(volumes) do c:set_volume(b, v) end
  return c
end

return M
