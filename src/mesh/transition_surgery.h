#pragma once
/// What the topological transitions (transitions.h) share: the steps of rebuilding a cluster
/// after mesh surgery. Internal to src/mesh.

#include "mesh/cluster.h"

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace froth::surgery {

/// Drops the vertices of V that no facet of spec uses: spec.vertices becomes the used ones in
/// order and the triangles are renumbered. Returns the map from V's ids to the new ones (-1:
/// dropped).
std::vector<int> keep_used_vertices(ClusterSpec& spec, const std::vector<Vec3>& V);

/// c's walls, wall attachments, fixed vertices, curves and curve points into spec, the vertex
/// ids through `map` (from c's ids; -1 for a vertex that is gone, which the callers refuse
/// before: such an entry makes the cluster invalid).
void copy_vertex_lists(const Cluster& c, const std::function<int(int)>& map, ClusterSpec& spec);

/// The cluster of spec; what its constructor throws becomes a TopologyError "<what>: the
/// cluster after <surgery> is not valid: ...".
Cluster rebuild(ClusterSpec spec, const std::string& what, const std::string& surgery);

/// In one surface, the facets at a point P given by their link edges x -> y (the corners after
/// P in the facet's order) must form one fan: a path or a cycle. Two fans would pinch the film
/// at P. \throw TopologyError "<what>: ... surface N ..."
void check_one_fan(const std::vector<std::pair<int, int>>& link, int surface,
                   const std::string& what);

/// True if the facet with corners y still faces the way of its old area vector and has not
/// (nearly) lost its area: surgery that moves corners must not turn or flatten a facet.
bool keeps_its_side(const Vec3& old_area, const std::array<Vec3, 3>& y);

/// Integer lattice offsets d with u = X + L d (all zero without a period).
Offset lattice_offset(const Cluster& c, const Vec3& unwrapped, const Vec3& stored);

} // namespace froth::surgery
