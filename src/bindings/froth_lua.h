#pragma once
/// Entry point of the Lua bindings: the only part of froth that knows about Lua.

struct lua_State;

namespace froth::lua {

/// Makes `froth` available in L: sets package.loaded.froth and the global `froth`, and puts
/// froth's own Lua modules (lua/froth/*.lua) on package.path. Standard libraries must already
/// be open.
void open_froth(lua_State* L);

/// The froth version string ("0.1.0").
const char* version();

} // namespace froth::lua
