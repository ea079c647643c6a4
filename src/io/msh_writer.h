#pragma once
/// write_msh: a cluster as a gmsh MSH 4.1 ASCII file that gmsh 4.8 (and froth's read_msh) read
/// back with the same surfaces and bodies.

#include <string>

namespace froth {

class Cluster;

/// Writes c as MSH 4.1 ASCII. Layout (all gmsh tags are froth ids + 1):
///  * $PhysicalNames: "surface_i" (dim 2, tag i), then "body_j" (dim 3, tag j);
///  * $Entities: surface entity i with physical tag i and no bounding curves; volume entity j
///    with physical tag j, bounded by its surfaces signed by the body's face signs;
///  * $Nodes: node v+1 lies in the block of the first surface that uses it;
///  * $Elements: one block of 3-node triangles (type 2) per surface, in the surface's order.
/// The file is written to a temporary beside path and renamed, and a missing parent directory
/// is created. \throw IoError "write: cannot open 'path' for writing: <reason>"
void write_msh(const Cluster& c, const std::string& path);

} // namespace froth
