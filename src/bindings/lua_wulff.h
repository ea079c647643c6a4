#pragma once
/// froth.wulff_shape, froth.frank_diagram and froth.cahn_hoffmann_check: the Wulff shape and
/// the Frank diagram of a froth.Anisotropy as froth.Cluster values (engine: wulff/wulff.h).

#include <lua.hpp>

namespace froth::lua {

/// Adds froth.wulff_shape, froth.frank_diagram and froth.cahn_hoffmann_check to the table on
/// top of the stack.
void add_wulff_functions(lua_State* L);

} // namespace froth::lua
