#include "bindings/froth_lua.h"

#include "bindings/lua_anisotropy.h"
#include "bindings/lua_builders.h"
#include "bindings/lua_cluster.h"
#include "bindings/lua_state.h"
#include "bindings/lua_walls.h"
#include "bindings/lua_foams.h"
#include "bindings/lua_wulff.h"

#include "bindings/paths.h"

#include <lua.hpp>

#include <unistd.h>

#include <cstdlib>
#include <string>

namespace froth::lua {

const char* version() { return FROTH_VERSION; }

namespace {

/// Puts froth's own Lua modules first on package.path: the first of bindings/paths.h's
/// candidates that holds them (an installed prefix before the source tree), or, if none does,
/// the first candidate (so that the error for a missing module names where froth looked).
void add_lua_path(lua_State* L) {
    const std::vector<std::string> dirs = lua_dir_candidates();
    std::string dir = dirs.front();
    for (const std::string& d : dirs)
        if (::access((d + "/froth/test.lua").c_str(), R_OK) == 0) {
            dir = d;
            break;
        }
    lua_getglobal(L, "package");
    lua_getfield(L, -1, "path");
    const std::string path = dir + "/?.lua;" + dir + "/?/init.lua;" + lua_tostring(L, -1);
    lua_pop(L, 1);
    lua_pushstring(L, path.c_str());
    lua_setfield(L, -2, "path");
    lua_pop(L, 1);
}

/// froth._manual: the lua_api.md that help() reads (froth.help), nil if none was found;
/// froth._manual_searched: where froth looked.
void set_manual(lua_State* L) {
    std::string searched;
    for (const std::string& path : manual_candidates()) {
        searched += (searched.empty() ? "" : ", ") + path;
        if (::access(path.c_str(), R_OK) == 0) {
            lua_pushstring(L, path.c_str());
            lua_setfield(L, -2, "_manual");
            break;
        }
    }
    lua_pushstring(L, searched.c_str());
    lua_setfield(L, -2, "_manual_searched");
}

/// help(topic): lua/froth/help.lua, loaded on first use.
void define_help(lua_State* L) {
    constexpr const char* kHelp =
        "help = function(...) return require('froth.help').help(...) end";
    if (luaL_dostring(L, kHelp) != LUA_OK) lua_error(L);
}

} // namespace

void open_froth(lua_State* L) {
    register_cluster_type(L);
    register_wall_type(L);
    register_anisotropy_type(L);
    add_lua_path(L);
    lua_newtable(L);
    add_builders(L);
    add_wall_constructors(L);
    add_wulff_functions(L);
    add_foam_functions(L);
    add_anisotropy_constructors(L);
    add_state_functions(L);
    lua_pushstring(L, FROTH_VERSION);
    lua_setfield(L, -2, "version");
    set_manual(L);
    lua_pushvalue(L, -1);
    lua_setglobal(L, "froth");
    luaL_getsubtable(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE);
    lua_insert(L, -2);
    lua_setfield(L, -2, "froth");
    lua_pop(L, 1);
    define_help(L);
}

} // namespace froth::lua
