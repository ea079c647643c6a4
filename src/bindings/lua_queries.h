#pragma once
/// froth.Cluster methods that list and edit elements: vertices, facets, edges, set_vertex, and
/// the fixed vertices: fix, unfix, fixed.

#include <vector>

struct lua_State;

namespace froth::lua {

/// The vertex ids (0-based) at stack index idx: one id, an array of ids, or an array of vertex
/// records with an `id` field (what c:vertices{where} returns). Raises a Lua error naming `op`
/// and the entry for anything else; ids are range-checked by the engine.
std::vector<int> read_vertex_ids(lua_State* L, int idx, const char* op);

/// Adds the query methods to the table on top of the stack (the Cluster's __index).
void add_query_methods(lua_State* L);

} // namespace froth::lua
