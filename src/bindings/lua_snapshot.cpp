// c:snapshot: a shaded PNG of the cluster (render/snapshot.h).
#include "bindings/lua_snapshot.h"

#include "bindings/lua_cluster.h"
#include "bindings/luax.h"

#include <lua.hpp>

namespace froth::lua {

SnapshotOptions read_snapshot_options(lua_State* L, int idx, const char* op) {
    SnapshotOptions s;
    Options o(L, idx, op, true);
    s.view = vector_option(L, o, "view", s.view);
    s.color = o.string("color", s.color.c_str());
    const int t = o.push("size");
    if (t != LUA_TNIL) {
        if (t != LUA_TTABLE || luaL_len(L, -1) != 2) o.error("size", "must be {width, height}");
        for (int k = 1; k <= 2; ++k) {
            int ok = 0;
            lua_rawgeti(L, -1, k);
            const lua_Integer v = lua_tointegerx(L, -1, &ok);
            lua_pop(L, 1);
            if (!ok || v < 16 || v > 8192)
                o.error("size", "must be {width, height}, integers in 16..8192");
            (k == 1 ? s.width : s.height) = static_cast<int>(v);
        }
    }
    lua_pop(L, 1);
    o.finish();
    return s;
}

namespace {

/// c:snapshot(path[, options]) -> {coverage, surfaces}.
int l_snapshot(lua_State* L) {
    const Cluster& c = check_cluster(L, 1).cluster;
    const std::string path = luaL_checkstring(L, 2);
    const SnapshotOptions o = read_snapshot_options(L, 3, "snapshot");
    return guarded(L, [&] {
        const SnapshotStats s = write_snapshot(c, path, o);
        lua_createtable(L, 0, 2);
        set_number(L, "coverage", s.coverage);
        set_integer(L, "surfaces", s.surfaces);
        return 1;
    });
}

const luaL_Reg methods[] = {{"snapshot", l_snapshot}, {nullptr, nullptr}};

} // namespace

void add_snapshot_methods(lua_State* L) {
    luaL_setfuncs(L, methods, 0);
}

} // namespace froth::lua
