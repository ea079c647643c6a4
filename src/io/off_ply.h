#pragma once
/// Plain triangle-mesh exports of a cluster for other tools (MeshLab, Blender, CGAL).

#include <string>

namespace froth {

class Cluster;

/// Writes c as an ASCII OFF file: all cluster vertices, then the facets of all surfaces in
/// surface order (0-based vertex ids, as OFF requires). Shared vertices appear once, so the
/// result is a non-manifold mesh at triple lines. The parent directory is created if missing.
/// \throw IoError if the file cannot be written
void write_off(const Cluster& c, const std::string& path);

/// Writes c as an ASCII PLY file: vertices (double x, y, z) and faces (vertex_indices) with a
/// per-face "int surface" property holding the 1-based surface id. The parent directory is
/// created if missing.
/// \throw IoError if the file cannot be written
void write_ply(const Cluster& c, const std::string& path);

} // namespace froth
