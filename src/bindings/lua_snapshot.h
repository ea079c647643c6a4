#pragma once
/// Pictures from Lua: c:snapshot(path, {view, color, size}) and the snapshot options of
/// evolve (render/snapshot.h).

#include "render/snapshot.h"

struct lua_State;

namespace froth::lua {

/// {view = {x, y, z}, color = "surface" | "mean_curvature", size = {w, h}} at stack index idx
/// (nil: the defaults); `op` prefixes the option errors.
SnapshotOptions read_snapshot_options(lua_State* L, int idx, const char* op);
/// Adds c:snapshot to the table on top of the stack (the Cluster's __index).
void add_snapshot_methods(lua_State* L);

} // namespace froth::lua
