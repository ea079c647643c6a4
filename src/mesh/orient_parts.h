#pragma once
/// Consistent orientation of a surface assembled from parts (CAD entities, mesh-file blocks):
/// shared by the gmsh builders and the MSH reader.

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace froth {

using NodeTri = std::array<std::size_t, 3>; ///< a triangle as node tags of a mesh file

/// Flips whole parts so that triangles of different parts sharing an edge traverse it in
/// opposite directions; triangles within one part are taken as consistent already. Parts that
/// share no manifold edge keep their own orientation.
/// \throw TopologyError "<what> cannot be oriented consistently" if that is impossible.
void orient_parts(std::vector<std::vector<NodeTri>>& parts, const std::string& what);

} // namespace froth
