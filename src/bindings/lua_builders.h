#pragma once
/// froth.cluster, froth.double_bubble, froth.sphere, froth.read, froth.has.

#include "core/types.h"

#include <functional>
#include <string>

struct lua_State;

namespace froth::lua {

/// x(p) of the Lua function p -> x, y, z at stack index idx (a wire curve's; froth.cluster's
/// curves, froth.load's). `name` names the curve in the function's errors.
std::function<Vec3(double)> curve_function(lua_State* L, int idx, const std::string& name);

/// Adds the constructor functions to the table on the top of the stack.
void add_builders(lua_State* L);

} // namespace froth::lua
