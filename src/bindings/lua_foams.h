#pragma once
/// froth.voronoi_foam: the periodic Voronoi foam of given sites (engine: foams/foam.h),
/// froth.voronoi_cells: its diagram's cells and Lloyd's relaxation (foams/voronoi.h), and
/// the reading of period vectors shared with froth.cluster. froth.foam, froth.kelvin_foam and
/// froth.weaire_phelan_foam are Lua on top of it (lua/froth/foams.lua).

#include <Eigen/Core>
#include <lua.hpp>

#include <string>
#include <vector>

namespace froth::lua {

/// The array of 3-vectors at idx ({{x, y, z}, ...}); messages name `op` and `name`.
std::vector<Eigen::Vector3d> read_vec3_list(lua_State* L, int idx, const char* op, const char* name);
/// period = {a, b, c}, three vectors: the columns of the returned matrix.
Eigen::Matrix3d read_period(lua_State* L, int idx, const char* op);

/// Adds froth.voronoi_foam and froth.voronoi_cells to the table on top of the stack.
void add_foam_functions(lua_State* L);

} // namespace froth::lua
