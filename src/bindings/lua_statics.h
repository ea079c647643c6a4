#pragma once
/// froth.Cluster methods for statics: c:minimize, c:pressures, c:body_report, c:set_volume,
/// c:target_volumes, c:refine (the engine's flows/minimize.h and refine in mesh/cluster.h).

struct lua_State;

namespace froth::lua {

/// Adds the methods to the table at the top of the stack (the Cluster metatable's __index).
void add_statics_methods(lua_State* L);

} // namespace froth::lua
