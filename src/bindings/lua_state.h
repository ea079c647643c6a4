#pragma once
/// State files from Lua: c:save(path) and froth.load(path[, {walls, mobilities}])
/// (io/state_file.h; docs/lua_api.md "Saving and resuming").

struct lua_State;

namespace froth::lua {

/// Adds c:save to the table on top of the stack (the Cluster's __index).
void add_state_methods(lua_State* L);
/// Adds froth.load to the table on top of the stack (the froth table).
void add_state_functions(lua_State* L);

} // namespace froth::lua
