#include "bindings/froth_lua.h"

#include <lua.hpp>

namespace froth::lua {

const char* version() { return FROTH_VERSION; }

void open_froth(lua_State* L) {
    lua_newtable(L);
    lua_pushstring(L, FROTH_VERSION);
    lua_setfield(L, -2, "version");
    lua_pushvalue(L, -1);
    lua_setglobal(L, "froth");
    luaL_getsubtable(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE);
    lua_insert(L, -2);
    lua_setfield(L, -2, "froth");
    lua_pop(L, 1);
}

} // namespace froth::lua
