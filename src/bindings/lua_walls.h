#pragma once
/// froth.Wall: the external boundaries of (3.10)/(3.11) as Lua values (froth.plane, froth.slab,
/// froth.sphere_wall, froth.cylinder_wall, froth.wall).

#include "mesh/walls.h"

#include <lua.hpp>

#include <vector>

namespace froth::lua {

inline constexpr const char* kWallType = "froth.Wall";

/// Creates the froth.Wall metatable (once per state).
void register_wall_type(lua_State* L);
/// Adds the wall constructors to the table on top of the stack.
void add_wall_constructors(lua_State* L);
/// Pushes a froth.Wall.
void push_wall(lua_State* L, WallPtr wall);
/// Reads a wall or an array of walls at idx (nil: none); errors name `who` ("cluster: walls").
std::vector<WallPtr> read_walls(lua_State* L, int idx, const char* who);

} // namespace froth::lua
