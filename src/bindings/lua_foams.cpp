// froth.voronoi_foam{sites = {{x, y, z}, ...}, period = {a, b, c}, h = ..., lloyd = 0}: a
// periodic cluster whose body k is the Voronoi cell of site k, after `lloyd` relaxation steps
// (foams/foam.h, foams/voronoi.h); froth.voronoi_cells{sites, period, lloyd}: the relaxed
// sites and their cells' volumes and centroids.
#include "bindings/lua_foams.h"

#include "bindings/lua_cluster.h"
#include "bindings/luax.h"
#include "foams/foam.h"

#ifdef FROTH_HAVE_GMSH
#include "bindings/gmsh_plugin.h"
#endif

#include <string>

namespace froth::lua {

std::vector<Eigen::Vector3d> read_vec3_list(lua_State* L, int idx, const char* op, const char* name) {
    idx = lua_absindex(L, idx);
    if (!lua_istable(L, idx)) luaL_error(L, "%s: %s must be an array of {x, y, z}", op, name);
    std::vector<Eigen::Vector3d> out(luaL_len(L, idx));
    for (int i = 1; i <= static_cast<int>(out.size()); ++i) {
        lua_rawgeti(L, idx, i);
        if (!lua_istable(L, -1) || luaL_len(L, -1) != 3)
            luaL_error(L, "%s: %s[%d] must be {x, y, z}", op, name, i);
        for (int d = 0; d < 3; ++d) {
            lua_rawgeti(L, -1, d + 1);
            int ok = 0;
            out[i - 1][d] = lua_tonumberx(L, -1, &ok);
            if (!ok || lua_type(L, -1) != LUA_TNUMBER)
                luaL_error(L, "%s: %s[%d][%d] must be a number", op, name, i, d + 1);
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
    return out;
}

Eigen::Matrix3d read_period(lua_State* L, int idx, const char* op) {
    const auto v = read_vec3_list(L, idx, op, "period");
    if (v.size() != 3) luaL_error(L, "%s: period must be three vectors {a, b, c}", op);
    Eigen::Matrix3d P;
    for (int k = 0; k < 3; ++k) P.col(k) = v[k];
    return P;
}

namespace {

/// The options sites, period and lloyd that froth.voronoi_foam and froth.voronoi_cells share.
struct Diagram {
    std::vector<Vec3> sites;
    Eigen::Matrix3d period;
    int lloyd = 0;
};

Diagram read_diagram(lua_State* L, Options& o, const char* op) {
    Diagram d;
    if (o.push("sites") == LUA_TNIL) o.error("sites", "is required");
    d.sites = read_vec3_list(L, -1, op, "sites");
    lua_pop(L, 1);
    if (o.push("period") == LUA_TNIL) o.error("period", "is required");
    d.period = read_period(L, -1, op);
    lua_pop(L, 1);
    const long long lloyd = o.integer("lloyd", 0);
    if (lloyd < 0 || lloyd > 10000) o.error("lloyd", "must be a count of steps from 0 to 10000");
    d.lloyd = static_cast<int>(lloyd);
    return d;
}

void push_vec3_list(lua_State* L, const std::vector<Vec3>& points) {
    lua_createtable(L, static_cast<int>(points.size()), 0);
    for (std::size_t i = 0; i < points.size(); ++i) {
        push_numbers(L, points[i]);
        lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
    }
}

/// mesher = "fan" (the split fans, foams/foam.h) or "gmsh" (graded, builders/gmsh_builder.h).
PolygonMesher read_mesher(lua_State* L, Options& o) {
    const std::string name = o.string("mesher", "fan");
    if (name == "fan") return {};
    if (name != "gmsh") o.error("mesher", "must be \"fan\" or \"gmsh\"");
#ifdef FROTH_HAVE_GMSH
    (void)L;
    return [](const std::vector<std::vector<Vec3>>& boundaries, double h) {
        return gmsh_builders().planar_polygons({boundaries, h});
    };
#else
    luaL_error(L, "voronoi_foam: mesher \"gmsh\" needs froth built with gmsh (froth.has(\"gmsh\") is false)");
    return {};
#endif
}

int l_voronoi_foam(lua_State* L) {
    Options o(L, 1, "voronoi_foam");
    const Diagram d = read_diagram(L, o, "voronoi_foam");
    const double h = o.number("h");
    const PolygonMesher mesher = read_mesher(L, o);
    o.finish();
    return guarded(L, [&] {
        FoamMesh mesh = voronoi_foam(lloyd_relax(d.sites, d.period, d.lloyd), d.period, h, mesher);
        push_cluster(L, std::move(mesh.spec));
        return 1;
    });
}

int l_voronoi_cells(lua_State* L) {
    Options o(L, 1, "voronoi_cells");
    const Diagram d = read_diagram(L, o, "voronoi_cells");
    o.finish();
    return guarded(L, [&] {
        const std::vector<Vec3> sites = lloyd_relax(d.sites, d.period, d.lloyd);
        const std::vector<VoronoiFace> faces = periodic_voronoi(sites, d.period);
        const VoronoiCells cells = voronoi_cells(faces, static_cast<int>(sites.size()), d.period);
        lua_createtable(L, 0, 4);
        push_vec3_list(L, sites);
        lua_setfield(L, -2, "sites");
        push_numbers(L, cells.volumes);
        lua_setfield(L, -2, "volumes");
        push_vec3_list(L, cells.centroids);
        lua_setfield(L, -2, "centroids");
        set_integer(L, "faces", static_cast<long long>(faces.size()));
        return 1;
    });
}

const luaL_Reg functions[] = {
    {"voronoi_foam", l_voronoi_foam},
    {"voronoi_cells", l_voronoi_cells},
    {nullptr, nullptr},
};

} // namespace

void add_foam_functions(lua_State* L) { luaL_setfuncs(L, functions, 0); }

} // namespace froth::lua
