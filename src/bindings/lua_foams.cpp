// froth.voronoi_foam{sites = {{x, y, z}, ...}, period = {a, b, c}, h = ...}: a periodic
// cluster whose body k is the Voronoi cell of site k (foams/foam.h).
#include "bindings/lua_foams.h"

#include "bindings/lua_cluster.h"
#include "bindings/luax.h"
#include "foams/foam.h"

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

int l_voronoi_foam(lua_State* L) {
    Options o(L, 1, "voronoi_foam");
    if (o.push("sites") == LUA_TNIL) o.error("sites", "is required");
    const auto sites = read_vec3_list(L, -1, "voronoi_foam", "sites");
    lua_pop(L, 1);
    if (o.push("period") == LUA_TNIL) o.error("period", "is required");
    const Eigen::Matrix3d P = read_period(L, -1, "voronoi_foam");
    lua_pop(L, 1);
    const double h = o.number("h");
    o.finish();
    return guarded(L, [&] {
        FoamMesh mesh = voronoi_foam(sites, P, h);
        push_cluster(L, std::move(mesh.spec));
        return 1;
    });
}

const luaL_Reg functions[] = {
    {"voronoi_foam", l_voronoi_foam},
    {nullptr, nullptr},
};

} // namespace

void add_foam_functions(lua_State* L) { luaL_setfuncs(L, functions, 0); }

} // namespace froth::lua
