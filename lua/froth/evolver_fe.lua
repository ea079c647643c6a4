-- froth.evolver_fe: Surface Evolver datafiles (.fe) read by froth.read (issue 14, item 2).
-- The subset read: `vertices` (coordinates, `fixed`, `constraint N`, or a parameter with
-- `boundary N`), `edges` (end points, `fixed`, `constraint`, `boundary`), `faces` (oriented
-- edge loops; `tension`/`density` per face), `bodies` (signed faces, `volume`, a `density`
-- when `gravity_constant 0`), `constraint N` with `formula:` (an equality: a plane wall when
-- the formula is affine, else a function wall; an `energy:` integrand only if it vanishes,
-- i.e. a 90-degree contact angle), `boundary N parameters 1` with `x1: x2: x3:` in p1 (its
-- vertices must be fixed: placed on the curve at their parameter, the edges between them
-- wires), `PARAMETER name = value`, `#define name value`, comments (`//`, `/* */`), and
-- expressions (pi, e, sin, cos, tan, sqrt, exp, log, abs, atan, asin, acos, ^). Everything
-- after `read` is Evolver's command section and is not run. Faces of tension 0 that no body
-- uses are display only (Evolver's table tops) and are dropped. As Evolver does, a face of
-- more than three edges gets a vertex at its centroid and a triangle per edge (so the counts
-- and areas after reading are Evolver's). froth's surfaces are the faces joined across edges
-- of exactly two faces (a film between triple lines), each oriented consistently; bodies are
-- closed by films, walls and wires (an edge between two fixed vertices on a film's border is a
-- wire); a body's `volconst` selects Evolver's volume (z dx dy over its facets plus the
-- constant, its lids counting nothing), so its `volume` target means what it means to Evolver.
-- The torus model (TORUS, TORUS_FILLED, periods, edge wraps * + -) becomes a periodic cluster:
-- each face's corners unwrapped along its edges' wraps, a face listed twice in a body a film
-- on both sides of the cell, and with TORUS_FILLED the last body's target the rest of the box.
-- Anything else (inequality constraints, content integrands, sliding boundary vertices,
-- quantities, gravity, ...) is one error naming the keyword and the line, never a wrong
-- cluster.
local M = {}

local unsupported = {
  quantity = "named quantities", method_instance = "method instances",
  symmetry_group = "symmetry groups", gravity = "gravity",
  string = "the string model", lagrange_order = "Lagrange elements",
  space_dimension = "other space dimensions", simplex_representation = "the simplex model",
  quadratic = "the quadratic model",
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

--- The constants and functions Evolver's expressions may use; `lookup(name)` gives the rest
--- (parameters, and a formula's variables).
local function math_env(lookup)
  local env = {pi = math.pi, e = math.exp(1), sin = math.sin, cos = math.cos, tan = math.tan,
               sqrt = math.sqrt, exp = math.exp, log = math.log, abs = math.abs,
               atan = math.atan, asin = math.asin, acos = math.acos}
  return setmetatable(env, {__index = function(_, k) return lookup(k) end})
end

--- Evaluates a number or expression token with the parameters and Lua's math.
local function evaluator(path, params)
  local env = math_env(function(k) return params[k:lower()] end)
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

--- A Lua function of the named variables from an Evolver expression (x1..x3 are x, y, z; p1 is
--- a boundary's parameter), with the parameters and math of the evaluator; checked by one call.
local function compile(path, line, text, variables, params)
  if not text:match("^[%w%.%+%-%*/%^%(%)_%s]+$") then
    fail(path, line, "'%s' is not an expression froth reads", text)
  end
  -- Evolver's names are case-insensitive: parameters are stored lower-case.
  local lua = text:lower():gsub("%f[%w_]x([123])%f[^%w_]", function(d) return ({"x", "y", "z"})[tonumber(d)] end)
  local args = {}
  local env = math_env(function(k)
    if args[k] ~= nil then return args[k] end
    return params[k:lower()]
  end)
  local chunk = load("return " .. lua, "=expression", "t", env)
  if not chunk then fail(path, line, "'%s' is not an expression froth reads", text) end
  local f = function(...)
    local values = table.pack(...)
    for k, name in ipairs(variables) do args[name] = values[k] end
    local ok, v = pcall(chunk)
    if not ok or type(v) ~= "number" then
      error(("read: %s:%d: '%s' cannot be evaluated: %s"):format(path, line, text, tostring(v)), 0)
    end
    return v
  end
  local probe = {}
  for k = 1, #variables do probe[k] = 0.1 * k end
  local ok, msg = pcall(f, table.unpack(probe))
  if not ok then error(msg, 0) end
  return f
end

--- The part of an element line after "key:" (the expression, spaces included).
local function after_colon(t)
  return (table.concat(t, " "):match(":%s*(.-)%s*$"))
end

--- `constraint N [attributes]` and the lines that belong to it: formula, energy e1..e3, content.
local function read_constraint_line(path, n, t, current, params)
  local key = t[1]:lower():match("^([%a_]%w*):?") or ""
  if key == "formula" or key == "function" then
    local text = after_colon(t)
    local lhs, rhs = text:match("^(.-)=(.*)$")
    current.formula = compile(path, n, lhs and ("(" .. lhs .. ")-(" .. rhs .. ")") or text,
                              {"x", "y", "z"}, params)
    current.formula_text = text
  elseif key == "energy" or key == "content" then
    current.integrand = key
  elseif key:match("^[ec][123]$") and current.integrand then
    current[current.integrand] = current[current.integrand] or {}
    current[current.integrand][tonumber(key:sub(2))] =
      {f = compile(path, n, after_colon(t), {"x", "y", "z"}, params), text = after_colon(t)}
  else
    return false
  end
  return true
end

--- `boundary N parameters 1` and its lines x1: x2: x3: (the curve as functions of p1).
local function read_boundary_line(path, n, t, current, params)
  local d = t[1]:lower():match("^x([123]):?$") or t[1]:lower():match("^x([123]):")
  if not d then return false end
  current.x[tonumber(d)] = compile(path, n, after_colon(t), {"p1"}, params)
  return true
end

local function start_constraint(path, n, t, data)
  local id = math.tointeger(tonumber(t[2]))
  if not id then fail(path, n, "constraint needs a number") end
  for k = 3, #t do
    fail(path, n, "constraint %d is '%s': froth reads equality constraints only (walls; "
         .. "inequalities, global and convex constraints are outside the subset)", id, t[k])
  end
  if data.constraints[id] then fail(path, n, "constraint %d is defined twice", id) end
  data.constraints[id] = {line = n}
  return data.constraints[id]
end

local function start_boundary(path, n, t, data)
  local id = math.tointeger(tonumber(t[2]))
  if not id then fail(path, n, "boundary needs a number") end
  if not (t[3] and t[3]:lower() == "parameters" and t[4] == "1") or t[5] then
    fail(path, n, "boundary %d: froth reads boundaries with 'parameters 1' only (wires)", id)
  end
  if data.boundaries[id] then fail(path, n, "boundary %d is defined twice", id) end
  data.boundaries[id] = {line = n, x = {}}
  return data.boundaries[id]
end

local sections = {vertices = true, edges = true, faces = true, facets = true, bodies = true}
-- Display settings whose lines of numbers froth skips (the torus model's view transforms).
local display_sections = {view_transform_generators = true, view_transforms = true}
local wrap_symbol = {["*"] = 0, ["+"] = 1, ["-"] = -1}
-- Model declarations that say what froth does anyway.
local ignored = {soapfilm = true, linear = true}
local singular = {vertices = "vertex", edges = "edge", faces = "face", bodies = "body"}
local attribute_list = {vertices = "fixed, constraint, boundary",
                        edges = "fixed, constraint, boundary, no_refine, color",
                        faces = "tension, density, constraint, no_refine, fixed, color",
                        bodies = "volume, volconst, density"}
-- The attributes each section may carry (colors are display only and ignored; no_refine and a
-- fixed face only on display faces, which froth drops; a body's density only without gravity).
local allowed = {
  vertices = {fixed = true, constraint = true, constraints = true, boundary = true},
  edges = {fixed = true, color = true, constraint = true, constraints = true, boundary = true,
           no_refine = true},
  faces = {tension = true, density = true, color = true, frontcolor = true, backcolor = true,
           constraint = true, constraints = true, no_refine = true, fixed = true},
  bodies = {volume = true, volconst = true, density = true},
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
    if a == "fixed" or a == "no_refine" then
      attrs[a] = true
    elseif a == "tension" or a == "density" or a == "volume" or a == "volconst" then
      if not t[i + 1] then fail(path, n, "'%s' needs a value", t[i]) end
      local key = a == "density" and (section == "bodies" and "density" or "tension") or a
      attrs[key] = eval(t[i + 1], n)
      i = i + 1
    elseif a == "constraint" or a == "constraints" or a == "boundary" then
      local ids = {}
      while t[i + 1] and math.tointeger(tonumber(t[i + 1])) do
        ids[#ids + 1] = math.tointeger(tonumber(t[i + 1]))
        i = i + 1
      end
      if #ids == 0 then fail(path, n, "'%s' needs a number", t[i]) end
      if a == "boundary" and #ids ~= 1 then fail(path, n, "'boundary' takes one number") end
      attrs[a == "boundary" and "boundary" or "constraints"] = a == "boundary" and ids[1] or ids
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
    local v = {fixed = attrs.fixed, constraints = attrs.constraints, boundary = attrs.boundary,
               line = n}
    if attrs.boundary then -- the vertex is given by its parameter on the boundary curve
      if #numbers ~= 1 then fail(path, n, "vertex %d on a boundary needs 1 parameter, got %d", id, #numbers) end
      v.p = eval(numbers[1], n)
    else
      if #numbers ~= 3 then fail(path, n, "vertex %d needs 3 coordinates, got %d", id, #numbers) end
      v.x = {eval(numbers[1], n), eval(numbers[2], n), eval(numbers[3], n)}
    end
    return id, v
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
    return id, {ids[1], ids[2], fixed = attrs.fixed, no_refine = attrs.no_refine,
                boundary = attrs.boundary, line = n}
  elseif section == "faces" then
    if #ids < 3 then fail(path, n, "face %d needs at least 3 edges", id) end
    return id, {loop = ids, tension = attrs.tension or 1, no_refine = attrs.no_refine,
                fixed = attrs.fixed, constraints = attrs.constraints, line = n}
  end
  return id, {faces = ids, volume = attrs.volume, volconst = attrs.volconst, density = attrs.density, line = n}
end

--- Parses the datafile: {vertices = {{x, fixed}}, edges = {{a, b, fixed}}, faces = {{loop,
--- tension, line}}, bodies = {{faces, volume, line}}}, each keyed by its Evolver id.
local function parse(path, lines)
  local params = {}
  local eval = evaluator(path, params)
  local data = {vertices = {}, edges = {}, faces = {}, bodies = {}, constraints = {},
                boundaries = {}, gravity = 1}
  local section, current
  for _, l in ipairs(lines) do
    local t, n = l.tokens, l.n
    local key = t[1]:lower()
    if key == "read" then break end
    if section == "constraint" and read_constraint_line(path, n, t, current, params) then
      -- a line of the constraint above
    elseif section == "boundary" and read_boundary_line(path, n, t, current, params) then
      -- a coordinate of the boundary above
    elseif key == "constraint" then
      current, section = start_constraint(path, n, t, data), "constraint"
    elseif key == "boundary" then
      current, section = start_boundary(path, n, t, data), "boundary"
    elseif key == "torus" or key == "torus_filled" then
      if t[2] then fail(path, n, "%s takes no value", t[1]) end
      data.torus, section = key, nil
    elseif key == "periods" then
      data.periods, section = {}, "periods"
    elseif section == "periods" and tonumber(t[1]) then
      if #t ~= 3 or #data.periods == 3 then fail(path, n, "periods: three lines of three numbers") end
      data.periods[#data.periods + 1] = {eval(t[1], n), eval(t[2], n), eval(t[3], n)}
    elseif display_sections[key] then
      section = "display"
    elseif section == "display" and tonumber(t[1]) then
      -- a view transform: display only
    elseif key == "gravity_constant" then
      if not t[2] or t[3] then fail(path, n, "gravity_constant needs one value") end
      data.gravity, section = eval(t[2], n), nil
    elseif key == "parameter" or key == "#define" then
      read_definition(path, n, t, params, eval)
      section = nil
    elseif sections[key] then
      section = key == "facets" and "faces" or key
    elseif ignored[key] and #t == 1 then
      section = nil
    elseif unsupported[key] ~= nil or (section == nil and not tonumber(key)) then
      fail(path, n, "'%s' (%s) is outside the .fe subset froth reads (vertices, edges, faces, "
           .. "bodies, fixed, tension, volume, constraint, boundary, PARAMETER, #define)", t[1], unsupported[key] or "unknown keyword")
    elseif section == "constraint" or section == "boundary" then
      fail(path, n, "'%s' is not a line of a %s froth reads (%s)", t[1], section,
           section == "constraint" and "formula:, energy: e1: e2: e3:, content: c1: c2: c3:"
           or "x1:, x2:, x3:")
    else
      local wrap
      if section == "edges" and data.torus and t[6] and wrap_symbol[t[4]] and wrap_symbol[t[5]]
         and wrap_symbol[t[6]] then -- the torus wraps of the edge's head, per period
        wrap = {wrap_symbol[t[4]], wrap_symbol[t[5]], wrap_symbol[t[6]]}
        t = {t[1], t[2], t[3], table.unpack(t, 7)}
      end
      local id, record = read_element(path, n, t, section, params, eval)
      if section == "edges" then record.wrap = wrap or {0, 0, 0} end
      if data[section][id] then fail(path, n, "%s %d is defined twice", singular[section], id) end
      data[section][id] = record
    end
  end
  return data
end

--- The vertex loop of a face from its signed edges, checked to be closed.
local function face_vertices(path, data, fid, face)
  local loop, offsets, at = {}, {{0, 0, 0}}, {0, 0, 0}
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
    local sg = se < 0 and -1 or 1 -- the wrap leads from the edge's tail to its head
    at = {at[1] + sg * e.wrap[1], at[2] + sg * e.wrap[2], at[3] + sg * e.wrap[3]}
    offsets[#offsets + 1] = at
  end
  if loop[#loop] ~= loop[1] then fail(path, face.line, "face %d: its edge loop is not closed", fid) end
  if at[1] ~= 0 or at[2] ~= 0 or at[3] ~= 0 then
    fail(path, face.line, "face %d: its edge loop wraps around the torus (%d %d %d periods)", fid,
         at[1], at[2], at[3])
  end
  loop[#loop], offsets[#offsets] = nil, nil
  return loop, offsets
end

--- Groups the faces into surfaces (joined across edges of exactly two faces) and orients
--- each group consistently; returns {faces (ids), flip (per face)} per surface.
local function surfaces_of(path, loops, order, line_of, edge_ids)
  local uses = {} -- undirected edge key -> list of {face, direction}
  -- In a torus two edges may join the same vertices through different images: the key is then
  -- the edge's id.
  local function key_of(f, k, a, b)
    return edge_ids and ("e" .. math.abs(edge_ids[f][k])) or (math.min(a, b) .. "-" .. math.max(a, b))
  end
  for _, f in ipairs(order) do
    local loop = loops[f]
    for k = 1, #loop do
      local a, b = loop[k], loop[k % #loop + 1]
      local key = key_of(f, k, a, b)
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
          local u = uses[key_of(f, k, a, b)]
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
    local twice = {}
    for _, g in ipairs(list) do
      -- in a torus a film may bound a cell on both sides: its faces are listed twice (+ and -)
      if data.torus and set[g] == 2 * #groups[g].faces then
        set[g], twice[#twice + 1] = #groups[g].faces, g
      end
      if set[g] ~= #groups[g].faces then
        fail(path, b.line, "body %d uses %d of the %d faces of one film (faces joined across "
             .. "edges of two faces); froth's bodies are bounded by whole films", id, set[g], #groups[g].faces)
      end
    end
    for _, g in ipairs(twice) do list[#list + 1] = g end
    table.sort(list)
    list.volconst = b.volconst -- Evolver's volume convention (froth.cluster's bodies)
    bodies[#bodies + 1] = list
    volumes[#bodies] = b.volume
  end
  return bodies, volumes
end

--- The walls of the constraints: a plane when the formula is affine (tested at the origin,
--- the unit vectors and two generic points), else a function wall named "constraint N".
--- Energy integrands must vanish (froth's walls have 90-degree contact); contents are refused
--- (froth closes bodies on walls itself, with exact lid volumes).
local function walls_of(path, data, froth)
  local ids, walls, index = {}, {}, {}
  for id in pairs(data.constraints) do ids[#ids + 1] = id end
  table.sort(ids)
  local probes = {{0.3, -0.7, 0.45}, {-1.3, 0.2, 2.1}, {0.05, 1.7, -0.9}}
  for _, id in ipairs(ids) do
    local k = data.constraints[id]
    if not k.formula then fail(path, k.line, "constraint %d has no formula", id) end
    if k.content then
      fail(path, k.line, "constraint %d has a content integrand: froth closes bodies on walls "
           .. "itself (exact lid volumes), so a datafile's volume correction is not read", id)
    end
    for d, e in pairs(k.energy or {}) do
      for _, x in ipairs(probes) do
        if math.abs(e.f(x[1], x[2], x[3])) > 1e-12 then
          fail(path, k.line, "constraint %d has the energy integrand e%d: %s, which is not zero: "
               .. "froth's walls have 90-degree contact angles (a wetting energy is not modelled)",
               id, d, e.text)
        end
      end
    end
    local F = k.formula
    local b = F(0, 0, 0)
    local n = {F(1, 0, 0) - b, F(0, 1, 0) - b, F(0, 0, 1) - b}
    local affine = true
    for _, x in ipairs(probes) do
      local lin = b + n[1] * x[1] + n[2] * x[2] + n[3] * x[3]
      affine = affine and math.abs(F(x[1], x[2], x[3]) - lin) <= 1e-12 * (1 + math.abs(lin))
    end
    if affine and (n[1] ~= 0 or n[2] ~= 0 or n[3] ~= 0) then
      walls[#walls + 1] = froth.plane{normal = n, offset = -b}
    else
      walls[#walls + 1] = froth.wall{name = "constraint " .. id, F = F}
    end
    index[id] = #walls
  end
  return walls, index
end

--- Faces of tension 0 that no body uses are for display (Evolver's table tops): dropped, with
--- the edges and vertices only they use. Returns the kept face ids in order.
local function kept_faces(path, data)
  local in_body = {}
  for _, b in pairs(data.bodies) do
    for _, sf in ipairs(b.faces) do in_body[math.abs(sf)] = true end
    if b.density and b.density ~= 0 and data.gravity ~= 0 then
      fail(path, b.line, "a body has density %g with gravity_constant %g: gravity is outside "
           .. "the .fe subset froth reads (set gravity_constant 0)", b.density, data.gravity)
    end
  end
  local order = {}
  for id, f in pairs(data.faces) do
    if f.tension ~= 0 or in_body[id] then
      if f.no_refine or f.fixed then
        fail(path, f.line, "face %d is %s: froth drops only display faces (tension 0, in no "
             .. "body); a film is refined and moved whole", id, f.no_refine and "no_refine" or "fixed")
      end
      order[#order + 1] = id
    end
  end
  table.sort(order)
  if #order == 0 then error("read: " .. path .. ": no faces", 0) end
  return order
end

--- Positions of the vertices: their coordinates, or on a boundary the curve at the parameter.
--- Boundary vertices must be fixed (froth holds them; sliding along a curve is not modelled).
local function vertex_position(path, data, id, v)
  if not v.boundary then return v.x end
  local b = data.boundaries[v.boundary]
  if not b then fail(path, v.line, "vertex %d is on boundary %d, which is not defined", id, v.boundary) end
  if not (b.x[1] and b.x[2] and b.x[3]) then fail(path, b.line, "boundary %d needs x1:, x2: and x3:", v.boundary) end
  if not v.fixed then
    fail(path, v.line, "vertex %d slides along boundary %d: froth holds boundary vertices fixed "
         .. "(give it 'fixed'; sliding along a curve is not modelled yet)", id, v.boundary)
  end
  return {b.x[1](v.p), b.x[2](v.p), b.x[3](v.p)}
end

--- The boundaries as froth's wire curves, with the (fixed) vertices on each and their
--- parameters: refine then puts wire midpoints on the curve, as Evolver does.
local function curves_of(data, vids, vid)
  local curves, of = {}, {}
  for _, id in ipairs(vids) do
    local v = data.vertices[id]
    if v.boundary then
      local k = of[v.boundary]
      if not k then
        local x = data.boundaries[v.boundary].x
        curves[#curves + 1] = {name = "boundary " .. v.boundary, vertices = {}, parameters = {},
                               x = function(p) return x[1](p), x[2](p), x[3](p) end}
        k = #curves
        of[v.boundary] = k
      end
      table.insert(curves[k].vertices, vid[id])
      table.insert(curves[k].parameters, v.p)
    end
  end
  return #curves > 0 and curves or nil
end

--- The period vectors of a torus model (rows of `periods`), which froth reads without walls,
--- fixed vertices or boundaries.
local function torus_periods(path, data, walls)
  if not data.periods or #data.periods ~= 3 then
    error("read: " .. path .. ": the torus model needs `periods` (three vectors)", 0)
  end
  if #walls > 0 or next(data.boundaries) then
    error("read: " .. path .. ": constraints and boundaries in the torus model are outside the "
          .. ".fe subset froth reads", 0)
  end
  for id, v in pairs(data.vertices) do
    if v.fixed then fail(path, v.line, "vertex %d is fixed: fixed vertices in the torus model are "
                         .. "outside the .fe subset froth reads", id) end
  end
  return data.periods
end

--- The cluster of an Evolver datafile's text (froth.read reads the file, with its limits, and
--- calls this; path names the file in messages). opts must be empty: an .fe file says its
--- fixed vertices and its walls (constraints) itself.
function M.from_text(text, path, opts)
  local froth = require("froth")
  if opts ~= nil then
    if type(opts) ~= "table" then error("read: expected an option table {...}, got " .. type(opts), 0) end
    for k in pairs(opts) do
      error(("read: option '%s' is not used for an .fe file (the datafile itself says which "
             .. "vertices are fixed and where its walls are)"):format(tostring(k)), 0)
    end
  end
  local data = parse(path, tokenize(path, text))
  local walls, wall_of = walls_of(path, data, froth)
  local position = {}
  for id, v in pairs(data.vertices) do position[id] = vertex_position(path, data, id, v) end
  if next(position) == nil then error("read: " .. path .. ": no vertices", 0) end
  for id, e in pairs(data.edges) do
    for _, v in ipairs{e[1], e[2]} do
      if not data.vertices[v] then fail(path, e.line, "edge %d uses vertex %s, which is not defined", id, tostring(v)) end
      -- froth fixes vertices, not edges: a fixed edge must have fixed ends (a wire).
      if e.fixed and not data.vertices[v].fixed then
        fail(path, e.line, "edge %d is fixed but its vertex %d is not (froth holds vertices; fix "
             .. "both ends of a fixed edge)", id, v)
      end
    end
  end
  local order = kept_faces(path, data)
  local loops, offsets = {}, {}
  for _, id in ipairs(order) do loops[id], offsets[id] = face_vertices(path, data, id, data.faces[id]) end
  local L = data.torus and torus_periods(path, data, walls)
  -- Vertices in id order (ids may have gaps, as Evolver allows), those the kept faces use.
  local used, vids = {}, {}
  for _, id in ipairs(order) do for _, v in ipairs(loops[id]) do used[v] = true end end
  for id in pairs(used) do vids[#vids + 1] = id end
  table.sort(vids)
  local vid, V, fixed = {}, {}, {}
  for _, id in ipairs(vids) do
    V[#V + 1] = position[id]
    vid[id] = #V
    if data.vertices[id].fixed then fixed[#fixed + 1] = #V end
  end
  for id, e in pairs(data.edges) do
    if e.no_refine and used[e[1]] and used[e[2]] then
      fail(path, e.line, "edge %d is no_refine: froth refines every edge of a film", id)
    end
  end
  local line_of = {}
  for id, face in pairs(data.faces) do line_of[id] = face.line end
  local edge_ids
  if L then
    edge_ids = {}
    for _, id in ipairs(order) do edge_ids[id] = data.faces[id].loop end
  end
  local groups, group, flip = surfaces_of(path, loops, order, line_of, edge_ids)
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
      if L then -- each corner where the face has it (froth.cluster merges the images again)
        for k, v in ipairs(loops[fid]) do
          local x, o = position[v], offsets[fid][k]
          V[#V + 1] = {x[1] + o[1] * L[1][1] + o[2] * L[2][1] + o[3] * L[3][1],
                       x[2] + o[1] * L[1][2] + o[2] * L[2][2] + o[3] * L[3][2],
                       x[3] + o[1] * L[1][3] + o[2] * L[2][3] + o[3] * L[3][3]}
          loop[k] = #V
        end
      end
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
                          walls = #walls > 0 and walls or nil, fixed = #fixed > 0 and fixed or nil,
                          curves = curves_of(data, vids, vid), period = L}
  -- Every vertex the datafile puts on a constraint must be held by its wall: froth attaches
  -- the borders of films to walls, not vertices inside a film.
  local records = c:vertices()
  for _, id in ipairs(vids) do
    for _, k in ipairs(data.vertices[id].constraints or {}) do
      if not wall_of[k] then fail(path, data.vertices[id].line, "vertex %d is on constraint %d, which is not defined", id, k) end
      local attached = false
      for _, w in ipairs(records[vid[id]].walls) do
        attached = attached or w == wall_of[k]
      end
      if not attached and not data.vertices[id].fixed then
        fail(path, data.vertices[id].line, "vertex %d is on constraint %d but not on the free "
             .. "border of a film: froth holds only film borders on walls", id, k)
      end
    end
  end
  for b, v in pairs(volumes) do c:set_volume(b, v) end
  if L and data.torus == "torus_filled" and #bodies > 0 then
    -- Evolver's TORUS_FILLED: the last body is the rest of the box (its volume is not its own)
    local rest = math.abs(L[1][1] * (L[2][2] * L[3][3] - L[2][3] * L[3][2])
                          - L[1][2] * (L[2][1] * L[3][3] - L[2][3] * L[3][1])
                          + L[1][3] * (L[2][1] * L[3][2] - L[2][2] * L[3][1]))
    local targets = c:target_volumes()
    for b = 1, #bodies - 1 do rest = rest - targets[b] end
    if rest > 0 then c:set_volume(#bodies, rest) end
  end
  return c
end

return M
