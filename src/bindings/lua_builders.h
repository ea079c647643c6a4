#pragma once
/// froth.cluster, froth.double_bubble, froth.sphere, froth.read, froth.has.

struct lua_State;

namespace froth::lua {

/// Adds the constructor functions to the table on the top of the stack.
void add_builders(lua_State* L);

} // namespace froth::lua
