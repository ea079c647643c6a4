// Cluster constructors: froth.cluster{...} from plain Lua tables, and (with gmsh) the meshed
// builders froth.double_bubble, froth.sphere and froth.read.
#include "bindings/lua_builders.h"

#include "bindings/lua_cluster.h"
#include "bindings/luax.h"

#ifdef FROTH_HAVE_GMSH
#include "builders/gmsh_builder.h"
#endif

#include <climits>
#include <string>

namespace froth::lua {
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
                                  "the orientation itself)", path.c_str(), k);
                ids.push_back(s);
            }
            spec.bodies.push_back(std::move(ids));
            lua_pop(L, 1);
        }
    }
    lua_pop(L, 1);
    o.finish();
    return guarded(L, [&] {
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
        push_cluster(L, build_double_bubble(d));
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
    o.finish();
    return guarded(L, [&] {
        push_cluster(L, build_sphere(s));
        return 1;
    });
}

int l_read(lua_State* L) {
    const std::string path = luaL_checkstring(L, 1);
    return guarded(L, [&] {
        push_cluster(L, read_msh(path));
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
#ifdef FROTH_HAVE_GMSH
    {"double_bubble", l_double_bubble},
    {"sphere", l_sphere},
    {"read", l_read},
#endif
    {"has", l_has},
    {nullptr, nullptr},
};

} // namespace

void add_builders(lua_State* L) { luaL_setfuncs(L, functions, 0); }

} // namespace froth::lua
