#pragma once
/// froth.Anisotropy: the surface energy densities of (1.15)/(1.17) as Lua values
/// (froth.anisotropy{...} and the presets in froth.anisotropies), with gamma, gamma' and gamma*
/// callable from Lua.

#include "anisotropy/anisotropy.h"

#include <lua.hpp>

#include <memory>

namespace froth::lua {

inline constexpr const char* kAnisotropyType = "froth.Anisotropy";

/// Creates the froth.Anisotropy metatable (once per state).
void register_anisotropy_type(lua_State* L);
/// Adds froth.anisotropy and the presets to the table on top of the stack.
void add_anisotropy_constructors(lua_State* L);
/// Pushes a froth.Anisotropy.
void push_anisotropy(lua_State* L, std::shared_ptr<const Anisotropy> gamma);
/// The anisotropy at idx; raises a Lua error naming `who` unless it is a froth.Anisotropy.
std::shared_ptr<const Anisotropy> check_anisotropy(lua_State* L, int idx, const char* who);

} // namespace froth::lua
