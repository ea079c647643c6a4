// Cluster constructors: froth.cluster{...} from plain Lua tables, froth.read of MSH files, and
// (with gmsh) the meshed builders froth.double_bubble, froth.sphere and froth.fragment, plus the named
// clusters of lua/froth/clusters.lua (froth.torus_bubble, ...) built on froth.fragment.
#include "bindings/lua_builders.h"

#include "bindings/lua_foams.h"

#include "bindings/lua_cluster.h"
#include "bindings/lua_queries.h"
#include "bindings/lua_walls.h"
#include "core/errors.h"
#include "io/msh_reader.h"
#include "io/text_file.h"
#include "core/format.h"
#include "wulff/sphere_sampling.h"
#include "bindings/luax.h"

#ifdef FROTH_HAVE_GMSH
#include "bindings/gmsh_plugin.h"
#endif

#include <climits>
#include <cmath>
#include <map>
#include <optional>
#include <string>

namespace froth::lua {
std::function<Vec3(double)> curve_function(lua_State* L, int idx, const std::string& name) {
    auto f = std::make_shared<LuaFunction>(L, idx, "curve '" + name + "'", "x");
    return [f](double p) {
        const std::vector<double> x = f->call(p, 0, 0, 3); // function(p) ignores the rest
        return Vec3(x[0], x[1], x[2]);
    };
}

namespace {

/// Reads t[key] as a Lua array (errors name the path, e.g. "surfaces[2].facets[5]").
void check_array(lua_State* L, int idx, const std::string& path) {
    if (!lua_istable(L, idx))
        luaL_error(L, "cluster: %s must be a table, got %s", path.c_str(), luaL_typename(L, idx));
}

double number_at(lua_State* L, int table, int i, const std::string& path) {
    lua_rawgeti(L, table, i);
    int ok = 0;
    const double v = lua_tonumberx(L, -1, &ok);
    if (!ok || lua_type(L, -1) != LUA_TNUMBER)
        luaL_error(L, "cluster: %s[%d] must be a number", path.c_str(), i);
    lua_pop(L, 1);
    return v;
}

int id_at(lua_State* L, int table, int i, const std::string& path) {
    lua_rawgeti(L, table, i);
    int ok = 0;
    const lua_Integer v = lua_tointegerx(L, -1, &ok);
    if (!ok || lua_type(L, -1) != LUA_TNUMBER)
        luaL_error(L, "cluster: %s[%d] must be an integer id", path.c_str(), i);
    if (v < INT_MIN + 1 || v > INT_MAX) // ids beyond int would wrap around silently
        luaL_error(L, "cluster: %s[%d] = %I is out of range", path.c_str(), i,
                   static_cast<LUAI_UACINT>(v));
    lua_pop(L, 1);
    return static_cast<int>(v - 1);
}

std::vector<Vec3> read_vertices(lua_State* L, int idx) {
    check_array(L, idx, "vertices");
    std::vector<Vec3> X(luaL_len(L, idx));
    for (int v = 1; v <= static_cast<int>(X.size()); ++v) {
        lua_rawgeti(L, idx, v);
        const std::string path = "vertices[" + std::to_string(v) + "]";
        check_array(L, -1, path);
        if (luaL_len(L, -1) != 3) luaL_error(L, "cluster: %s must have 3 coordinates", path.c_str());
        for (int d = 0; d < 3; ++d) X[v - 1][d] = number_at(L, lua_gettop(L), d + 1, path);
        lua_pop(L, 1);
    }
    return X;
}

/// A surface is {facets = {{1,2,3}, ...}, sigma = 1} or just the list of facets.
ClusterSpec::Surface read_surface(lua_State* L, int idx, int i) {
    const std::string path = "surfaces[" + std::to_string(i) + "]";
    check_array(L, idx, path);
    ClusterSpec::Surface s;
    int facets = idx;
    std::string facets_path = path;
    if (lua_getfield(L, idx, "facets") != LUA_TNIL) {
        facets = lua_gettop(L);
        facets_path += ".facets";
        check_array(L, facets, facets_path);
        if (lua_getfield(L, idx, "sigma") != LUA_TNIL) {
            if (lua_type(L, -1) != LUA_TNUMBER)
                luaL_error(L, "cluster: %s.sigma must be a number", path.c_str());
            s.sigma = lua_tonumber(L, -1);
        }
        lua_pop(L, 1);
    }
    for (int f = 1; f <= luaL_len(L, facets); ++f) {
        lua_rawgeti(L, facets, f);
        const std::string fpath = facets_path + "[" + std::to_string(f) + "]";
        check_array(L, -1, fpath);
        if (luaL_len(L, -1) != 3) luaL_error(L, "cluster: %s must have 3 vertex ids", fpath.c_str());
        const int t = lua_gettop(L);
        s.triangles.push_back({id_at(L, t, 1, fpath), id_at(L, t, 2, fpath), id_at(L, t, 3, fpath)});
        lua_pop(L, 1);
    }
    lua_settop(L, idx);
    return s;
}

/// curves = {{x = function(p) return x, y, z end, name, vertices = {ids}, parameters = {p}}}:
/// wire curves and the fixed vertices on them (mesh/curves.h).
void read_curves(lua_State* L, int idx, ClusterSpec& spec) {
    check_array(L, idx, "curves");
    for (int k = 1; k <= luaL_len(L, idx); ++k) {
        lua_rawgeti(L, idx, k);
        const int t = lua_gettop(L);
        const std::string path = "curves[" + std::to_string(k) + "]", op = "cluster: " + path;
        check_array(L, t, path);
        Options co(L, t, op.c_str());
        const std::string name = co.string("name", ("curve " + std::to_string(k)).c_str());
        if (co.push("x") != LUA_TFUNCTION) co.error("x", "must be a function p -> x, y, z");
        const auto x = curve_function(L, lua_gettop(L), name);
        lua_pop(L, 1);
        if (co.push("vertices") == LUA_TNIL) co.error("vertices", "is required");
        const std::vector<int> ids = read_vertex_ids(L, -1, (op + ".vertices").c_str());
        lua_pop(L, 1);
        if (co.push("parameters") != LUA_TTABLE || luaL_len(L, -1) != static_cast<lua_Integer>(ids.size()))
            co.error("parameters", "must be an array of one number per vertex");
        for (std::size_t i = 0; i < ids.size(); ++i)
            spec.curve_points.push_back({ids[i], k - 1, number_at(L, lua_gettop(L), static_cast<int>(i) + 1,
                                                                  path + ".parameters")});
        lua_pop(L, 1);
        co.finish();
        spec.curves.push_back(std::make_shared<const Curve>(x, name));
        lua_settop(L, idx);
    }
}

/// bodies[b].volconst: Evolver's volume convention for the body (ClusterSpec::volconst).
std::optional<double> read_volconst(lua_State* L, int body, const std::string& path) {
    std::optional<double> v;
    if (lua_getfield(L, body, "volconst") != LUA_TNIL) {
        if (lua_type(L, -1) != LUA_TNUMBER)
            luaL_error(L, "cluster: %s.volconst must be a number, got %s", path.c_str(),
                       luaL_typename(L, -1));
        v = lua_tonumber(L, -1);
    }
    lua_pop(L, 1);
    return v;
}

int l_cluster(lua_State* L) {
    Options o(L, 1, "cluster");
    ClusterSpec spec;
    o.push("vertices");
    spec.vertices = read_vertices(L, lua_gettop(L));
    lua_pop(L, 1);
    o.push("surfaces");
    check_array(L, -1, "surfaces");
    const int surfaces = lua_gettop(L);
    for (int i = 1; i <= luaL_len(L, surfaces); ++i) {
        lua_rawgeti(L, surfaces, i);
        spec.surfaces.push_back(read_surface(L, lua_gettop(L), i));
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    if (o.push("bodies") != LUA_TNIL) {
        const int bodies = lua_gettop(L);
        check_array(L, bodies, "bodies");
        for (int b = 1; b <= luaL_len(L, bodies); ++b) {
            lua_rawgeti(L, bodies, b);
            const std::string path = "bodies[" + std::to_string(b) + "]";
            check_array(L, -1, path);
            std::vector<int> ids;
            for (int k = 1; k <= luaL_len(L, -1); ++k) {
                const int s = id_at(L, lua_gettop(L), k, path);
                if (s < 0)
                    luaL_error(L, "cluster: %s[%d] must be a positive surface id (froth finds "
                                  "the orientation itself; in a periodic cluster a film with "
                                  "the body on both sides is named twice)", path.c_str(), k);
                ids.push_back(s);
            }
            spec.bodies.push_back(std::move(ids));
            spec.volconst.push_back(read_volconst(L, lua_gettop(L), path));
            lua_pop(L, 1);
        }
    }
    lua_pop(L, 1);
    o.push("walls");
    spec.walls = read_walls(L, -1, "cluster: walls");
    lua_pop(L, 1);
    if (o.push("fixed") != LUA_TNIL) spec.fixed = read_vertex_ids(L, -1, "cluster: fixed");
    lua_pop(L, 1);
    if (o.push("curves") != LUA_TNIL) read_curves(L, lua_gettop(L), spec);
    lua_pop(L, 1);
    std::optional<Eigen::Matrix3d> period;
    if (o.push("period") != LUA_TNIL) period = read_period(L, -1, "cluster");
    lua_pop(L, 1);
    o.finish();
    return guarded(L, [&] {
        // Unwrapped vertices: lattice images become one vertex, corners get their offsets.
        if (period) identify_periodic_images(spec, *period);
        push_cluster(L, std::move(spec));
        return 1;
    });
}

/// froth.read(path[, {walls}]): an MSH file (io/msh_reader.h; no gmsh needed), or a Surface
/// Evolver datafile (*.fe: lua/froth/evolver_fe.lua).
int l_read(lua_State* L) {
    const std::string path = luaL_checkstring(L, 1);
    if (path.size() > 3 && path.compare(path.size() - 3, 3, ".fe") == 0) {
        // Read here with the file limits of every reader (regular files only, at most 64 MiB:
        // Evolver's datafiles are small), parsed in Lua.
        std::string text;
        guarded(L, [&] {
            text = io::read_text_file(path, std::uintmax_t{64} << 20, "read");
            return 0;
        });
        lua_settop(L, 2);
        lua_getglobal(L, "require");
        lua_pushstring(L, "froth.evolver_fe");
        lua_call(L, 1, 1);
        lua_getfield(L, -1, "from_text");
        lua_pushlstring(L, text.data(), text.size());
        lua_pushvalue(L, 1);
        lua_pushvalue(L, 2);
        lua_call(L, 3, 1);
        return 1;
    }
    Options o(L, 2, "read", true);
    o.push("walls");
    std::vector<WallPtr> walls = read_walls(L, -1, "read: walls");
    lua_pop(L, 1);
    std::vector<int> fixed;
    if (o.push("fixed") != LUA_TNIL) fixed = read_vertex_ids(L, -1, "read: fixed");
    lua_pop(L, 1);
    o.finish();
    return guarded(L, [&] {
        ClusterSpec spec = read_msh(path);
        spec.walls = std::move(walls);
        spec.fixed = std::move(fixed);
        push_cluster(L, std::move(spec));
        return 1;
    });
}

#ifdef FROTH_HAVE_GMSH
std::array<double, 3> read_sigmas(lua_State* L, Options& o, const char* op) {
    std::array<double, 3> sigma{1, 1, 1};
    const int t = o.push("sigma");
    if (t == LUA_TNUMBER) {
        sigma.fill(lua_tonumber(L, -1));
    } else if (t == LUA_TTABLE) {
        if (luaL_len(L, -1) != 3) luaL_error(L, "%s: option 'sigma' must have 3 values", op);
        for (int i = 0; i < 3; ++i) {
            lua_rawgeti(L, -1, i + 1);
            if (lua_type(L, -1) != LUA_TNUMBER)
                luaL_error(L, "%s: sigma[%d] must be a number", op, i + 1);
            sigma[i] = lua_tonumber(L, -1);
            lua_pop(L, 1);
        }
    } else if (t != LUA_TNIL) {
        luaL_error(L, "%s: option 'sigma' must be a number or a table of 3 numbers", op);
    }
    lua_pop(L, 1);
    return sigma;
}

int l_double_bubble(lua_State* L) {
    Options o(L, 1, "double_bubble", true);
    DoubleBubbleOptions d;
    d.h = o.number("h", d.h);
    d.split = o.number("split", d.split);
    d.sigma = read_sigmas(L, o, "double_bubble");
    o.finish();
    return guarded(L, [&] {
        push_cluster(L, gmsh_builders().double_bubble(d));
        return 1;
    });
}

int l_sphere(lua_State* L) {
    Options o(L, 1, "sphere", true);
    SphereOptions s;
    s.R = o.number("R", s.R);
    s.h = o.number("h", s.h);
    if (o.push("center") == LUA_TTABLE) {
        for (int d = 0; d < 3; ++d) {
            lua_rawgeti(L, -1, d + 1);
            if (lua_type(L, -1) != LUA_TNUMBER) luaL_error(L, "sphere: center must be {x, y, z}");
            s.center[d] = lua_tonumber(L, -1);
            lua_pop(L, 1);
        }
    } else if (!lua_isnil(L, -1)) {
        luaL_error(L, "sphere: center must be {x, y, z}");
    }
    lua_pop(L, 1);
    if (o.has("levels") && o.has("h")) o.error("levels", "and option 'h' exclude each other");
    const long long levels = o.integer("levels", -1);
    constexpr int kMaxSphereLevels = 9; // 2,621,442 vertices
    if (o.has("levels") && (levels < 0 || levels > kMaxSphereLevels))
        o.error("levels", ("must be in 0.." + std::to_string(kMaxSphereLevels)).c_str());
    o.finish();
    return guarded(L, [&] {
        if (levels < 0) {
            push_cluster(L, gmsh_builders().sphere(s));
            return 1;
        }
        // The icosphere: symmetric, every vertex on the sphere, and no gmsh.
        if (!(std::isfinite(s.R) && s.R > 0))
            throw InvalidInput("sphere: R must be positive, got " + fmt(s.R));
        if (!s.center.allFinite()) throw InvalidInput("sphere: center must be finite");
        TriangleSurface ico = icosphere(static_cast<int>(levels));
        ClusterSpec spec;
        for (const Vec3& x : ico.vertices) spec.vertices.push_back(s.center + s.R * x);
        spec.surfaces.push_back({std::move(ico.triangles), 1.0, {}});
        spec.bodies = {{0}};
        push_cluster(L, std::move(spec));
        return 1;
    });
}

// ---- froth.fragment -------------------------------------------------------------------------

/// Reads option key as {x, y, z}; absent: fallback.
Vec3 vec3_option(lua_State* L, Options& o, const char* key, const Vec3& fallback,
                 const std::string& who) {
    Vec3 v = fallback;
    const int t = o.push(key);
    if (t == LUA_TTABLE && luaL_len(L, -1) == 3) {
        for (int d = 0; d < 3; ++d) {
            if (lua_rawgeti(L, -1, d + 1) != LUA_TNUMBER)
                luaL_error(L, "%s: %s must be {x, y, z}", who.c_str(), key);
            v[d] = lua_tonumber(L, -1);
            lua_pop(L, 1);
        }
    } else if (t != LUA_TNIL) {
        luaL_error(L, "%s: %s must be {x, y, z}", who.c_str(), key);
    }
    lua_pop(L, 1);
    return v;
}

Vec3 required_vec3(lua_State* L, Options& o, const char* key, const std::string& who) {
    if (!o.has(key)) o.error(key, "is required");
    return vec3_option(L, o, key, Vec3::Zero(), who);
}

/// rotate = {axis = {x, y, z}, angle = radians}
void read_rotate(lua_State* L, Options& o, Solid& s, const std::string& who) {
    const int t = o.push("rotate");
    if (t == LUA_TTABLE) {
        const std::string rwho = who + ": rotate";
        Options r(L, lua_gettop(L), rwho.c_str());
        s.rotate_axis = vec3_option(L, r, "axis", Vec3::UnitZ(), rwho);
        s.rotate_angle = r.number("angle");
        r.finish();
    } else if (t != LUA_TNIL) {
        luaL_error(L, "%s: rotate must be a table {axis = {x, y, z}, angle = radians}",
                   who.c_str());
    }
    lua_pop(L, 1);
}

/// scale = number (uniform) or {sx, sy, sz}
void read_scale(lua_State* L, Options& o, Solid& s, const std::string& who) {
    const int t = o.push("scale");
    const bool vector = t == LUA_TTABLE && luaL_len(L, -1) == 3;
    if (t == LUA_TNUMBER) s.scale = Vec3::Constant(lua_tonumber(L, -1));
    lua_pop(L, 1);
    if (vector) s.scale = vec3_option(L, o, "scale", Vec3::Ones(), who);
    if (t != LUA_TNIL && t != LUA_TNUMBER && !vector)
        luaL_error(L, "%s: scale must be a number or {sx, sy, sz}", who.c_str());
}

/// latitude = {lo, hi} (radians; the range is checked by build_fragment)
void read_latitude(lua_State* L, Options& o, Solid& s, const std::string& who) {
    const int t = o.push("latitude");
    if (t != LUA_TNIL) {
        if (t != LUA_TTABLE || luaL_len(L, -1) != 2)
            luaL_error(L, "%s: latitude must be {lo, hi} (radians)", who.c_str());
        double v[2];
        for (int i = 0; i < 2; ++i) {
            if (lua_rawgeti(L, -1, i + 1) != LUA_TNUMBER)
                luaL_error(L, "%s: latitude must be {lo, hi} (radians)", who.c_str());
            v[i] = lua_tonumber(L, -1);
            lua_pop(L, 1);
        }
        s.latitude_lo = v[0];
        s.latitude_hi = v[1];
    }
    lua_pop(L, 1);
}

void read_kind_fields(lua_State* L, Options& o, Solid& s, const std::string& who) {
    switch (s.kind) {
    case SolidKind::ball:
        s.center = vec3_option(L, o, "center", Vec3::Zero(), who);
        s.r = o.number("r");
        s.angle = o.number("angle", s.angle);
        read_latitude(L, o, s, who);
        break;
    case SolidKind::box:
        s.min = required_vec3(L, o, "min", who);
        if (o.has("max") == o.has("size"))
            luaL_error(L, "%s: give exactly one of max and size", who.c_str());
        s.size = o.has("max") ? Vec3(vec3_option(L, o, "max", Vec3::Zero(), who) - s.min)
                              : vec3_option(L, o, "size", Vec3::Ones(), who);
        break;
    case SolidKind::cylinder:
        s.base = vec3_option(L, o, "base", Vec3::Zero(), who);
        s.axis = required_vec3(L, o, "axis", who);
        s.r = o.number("r");
        break;
    case SolidKind::torus:
        s.center = vec3_option(L, o, "center", Vec3::Zero(), who);
        s.R = o.number("R");
        s.r = o.number("r");
        s.axis = vec3_option(L, o, "axis", Vec3::UnitZ(), who);
        break;
    }
}

SolidKind solid_kind(lua_State* L, int idx, int k) {
    if (lua_rawgeti(L, idx, 1) != LUA_TSTRING)
        luaL_error(L,
                   "fragment: solids[%d] must start with its kind: \"ball\", \"box\", "
                   "\"cylinder\" or \"torus\"",
                   k);
    const std::string name = lua_tostring(L, -1);
    lua_pop(L, 1);
    for (SolidKind kind : {SolidKind::ball, SolidKind::box, SolidKind::cylinder, SolidKind::torus})
        if (name == solid_kind_name(kind)) return kind;
    luaL_error(L,
               "fragment: solids[%d]: unknown solid kind '%s' (known: ball, box, cylinder, "
               "torus)",
               k, name.c_str());
    return SolidKind::ball; // not reached
}

/// solids[k] = {"ball", center = {...}, r = 1, translate = ..., h = ...}
Solid read_solid(lua_State* L, int idx, int k) {
    if (!lua_istable(L, idx))
        luaL_error(L, "fragment: solids[%d] must be a table such as {\"ball\", r = 1}, got %s", k,
                   luaL_typename(L, idx));
    Solid s;
    s.kind = solid_kind(L, idx, k);
    const std::string who =
        "fragment: solids[" + std::to_string(k) + "] (" + solid_kind_name(s.kind) + ")";
    lua_newtable(L); // the keys without the kind at [1], so that Options sees only names
    const int copy = lua_gettop(L);
    lua_pushnil(L);
    while (lua_next(L, idx)) {
        if (lua_isinteger(L, -2) && lua_tointeger(L, -2) == 1) {
            lua_pop(L, 1);
            continue;
        }
        lua_pushvalue(L, -2);
        lua_insert(L, -2);
        lua_rawset(L, copy);
    }
    Options o(L, copy, who.c_str());
    read_kind_fields(L, o, s, who);
    s.translate = vec3_option(L, o, "translate", Vec3::Zero(), who);
    read_rotate(L, o, s, who);
    read_scale(L, o, s, who);
    if (o.has("h")) s.h = o.number("h");
    if (o.has("body")) s.body = o.integer("body"); // build_fragment checks the range
    o.finish();
    lua_pop(L, 1);
    return s;
}

/// sigma = number, or a table {[id] = sigma, ...} (an array lists them all).
void read_fragment_sigma(lua_State* L, Options& o, FragmentOptions& f) {
    const int t = o.push("sigma");
    if (t == LUA_TNUMBER) {
        f.sigma = lua_tonumber(L, -1);
    } else if (t == LUA_TTABLE) {
        lua_pushnil(L);
        while (lua_next(L, -2)) {
            if (!lua_isinteger(L, -2) || lua_tointeger(L, -2) < 1 || lua_tointeger(L, -2) > INT_MAX)
                luaL_error(L, "fragment: sigma keys must be surface ids 1, 2, ...");
            const int id = static_cast<int>(lua_tointeger(L, -2));
            if (lua_type(L, -1) != LUA_TNUMBER)
                luaL_error(L, "fragment: sigma[%d] must be a number", id);
            f.sigma_of[id - 1] = lua_tonumber(L, -1);
            lua_pop(L, 1);
        }
    } else if (t != LUA_TNIL) {
        luaL_error(L, "fragment: option 'sigma' must be a number or a table {[surface] = sigma}");
    }
    lua_pop(L, 1);
}

/// Calls fn(x, y, z) -> x, y, z on every vertex (outside any gmsh session).
void apply_transform(lua_State* L, int fn, std::vector<Vec3>& X) {
    for (Vec3& x : X) {
        lua_pushvalue(L, fn);
        for (int d = 0; d < 3; ++d)
            lua_pushnumber(L, x[d]);
        lua_call(L, 3, 3);
        for (int d = 0; d < 3; ++d) {
            if (lua_type(L, d - 3) != LUA_TNUMBER)
                luaL_error(L, "fragment: transform must return 3 numbers x, y, z");
            x[d] = lua_tonumber(L, d - 3);
        }
        lua_pop(L, 3);
    }
}

/// fragment{sigma = {[id] = s}} with walls: ids of the films that remain.
void apply_sigma_after_lids(ClusterSpec& spec, const std::map<int, double>& sigma_of) {
    for (auto [id, sigma] : sigma_of) {
        if (id >= static_cast<int>(spec.surfaces.size()))
            throw InvalidInput("fragment: sigma names surface " + std::to_string(id + 1) +
                               ", but there are " + std::to_string(spec.surfaces.size()) +
                               " films once the lids on the walls are dropped");
        spec.surfaces[id].sigma = sigma;
    }
}

int l_fragment(lua_State* L) {
    Options o(L, 1, "fragment");
    FragmentOptions f;
    if (o.push("solids") != LUA_TTABLE)
        luaL_error(L, "fragment: option 'solids' must be a table of solids, got %s",
                   luaL_typename(L, -1));
    const int solids = lua_gettop(L);
    for (int k = 1; k <= luaL_len(L, solids); ++k) {
        lua_rawgeti(L, solids, k);
        f.solids.push_back(read_solid(L, lua_gettop(L), k));
        lua_pop(L, 1);
    }
    lua_pop(L, 1);
    if (o.has("h")) f.h = o.number("h");
    if (o.has("vertices")) {
        if (o.has("h")) luaL_error(L, "fragment: give h or vertices, not both");
        const long long n = o.integer("vertices");
        if (n < 100 || n > static_cast<long long>(f.max_vertices))
            luaL_error(L, "fragment: vertices must be in [100, %d], got %I",
                       static_cast<int>(f.max_vertices), static_cast<LUAI_UACINT>(n));
        f.default_vertices = static_cast<std::size_t>(n);
    }
    read_fragment_sigma(L, o, f);
    const int t = o.push("transform");
    if (t != LUA_TNIL && t != LUA_TFUNCTION)
        luaL_error(L, "fragment: option 'transform' must be a function (x, y, z) -> x, y, z");
    lua_pop(L, 1);
    o.push("walls");
    std::vector<WallPtr> walls = read_walls(L, -1, "fragment: walls");
    lua_pop(L, 1);
    o.finish();
    // With walls, sigma ids count the films left once the lids are gone: apply them after.
    std::map<int, double> sigma_of;
    if (!walls.empty()) std::swap(sigma_of, f.sigma_of);
    ClusterSpec spec;
    guarded(L, [&] {
        spec = gmsh_builders().fragment(f);
        return 0;
    });
    if (lua_getfield(L, 1, "transform") == LUA_TFUNCTION)
        apply_transform(L, lua_gettop(L), spec.vertices);
    return guarded(L, [&] {
        if (!walls.empty()) {
            spec.walls = std::move(walls);
            drop_wall_lids(spec);
            apply_sigma_after_lids(spec, sigma_of);
        }
        push_cluster(L, std::move(spec));
        return 1;
    });
}
#endif

int l_has(lua_State* L) {
    const std::string feature = luaL_checkstring(L, 1);
#ifdef FROTH_HAVE_GMSH
    const bool gmsh = true;
#else
    const bool gmsh = false;
#endif
#ifdef FROTH_HAVE_CGAL
    const bool cgal = true;
#else
    const bool cgal = false;
#endif
    if (feature != "gmsh" && feature != "cgal")
        luaL_error(L, "has: unknown feature '%s' (known: \"gmsh\", \"cgal\")", feature.c_str());
    lua_pushboolean(L, feature == "gmsh" ? gmsh : cgal);
    return 1;
}

const luaL_Reg functions[] = {
    {"cluster", l_cluster},
    {"read", l_read},
#ifdef FROTH_HAVE_GMSH
    {"double_bubble", l_double_bubble},
    {"sphere", l_sphere},
    {"fragment", l_fragment},
#endif
    {"has", l_has},
    {nullptr, nullptr},
};

// The named clusters (froth.torus_bubble, ..., froth.cube_on_plane, ...) are Lua,
// lua/froth/clusters.lua and lua/froth/wall_clusters.lua, on top of froth.fragment; they are
// copied into the froth table so that no script has to require them. A missing module is an
// error at startup rather than a silently missing builder.
void add_named_clusters(lua_State* L, int froth, const char* module) {
    lua_getglobal(L, "require");
    lua_pushstring(L, module);
    lua_call(L, 1, 1);
    if (!lua_istable(L, -1)) luaL_error(L, "%s must return a table of builders", module);
    lua_pushnil(L);
    while (lua_next(L, -2)) {
        if (lua_type(L, -2) == LUA_TSTRING && lua_isfunction(L, -1)) {
            lua_pushvalue(L, -2);
            lua_insert(L, -2);
            lua_rawset(L, froth);
        } else {
            lua_pop(L, 1);
        }
    }
    lua_pop(L, 1);
}

} // namespace

void add_builders(lua_State* L) {
    luaL_setfuncs(L, functions, 0);
    for (const char* module : {"froth.structured_clusters", "froth.foams"}) // no gmsh needed
        add_named_clusters(L, lua_gettop(L), module);
#ifdef FROTH_HAVE_GMSH
    for (const char* module : {"froth.clusters", "froth.wall_clusters"})
        add_named_clusters(L, lua_gettop(L), module);
#endif
}

} // namespace froth::lua
