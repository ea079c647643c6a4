#pragma once
/// froth.Cluster methods that list and edit elements: vertices, facets, edges, set_vertex.

struct lua_State;

namespace froth::lua {

/// Adds the query methods to the table on top of the stack (the Cluster's __index).
void add_query_methods(lua_State* L);

} // namespace froth::lua
