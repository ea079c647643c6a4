#pragma once
/// Cluster specs from gmsh (docs: ../shared/docs/dependencies.md §3): the OCC double bubble
/// and a single sphere (MSH files are read without gmsh: io/msh_reader.h). gmsh itself stays
/// private to the .cpp, so including this header needs no gmsh. gmsh is a process-wide singleton: the builders serialise on a mutex.

#include "mesh/cluster.h"

#include <array>
#include <string>
#include <vector>

namespace froth {

struct DoubleBubbleOptions {
    double h = 0.08;    ///< target edge length (Mesh.MeshSizeMax), 0.005 <= h <= 0.5
    double split = 0.0; ///< height of the flat wall, |split| <= 0.9
    std::array<double, 3> sigma{1, 1, 1}; ///< tensions of surfaces 1, 2, 3 (see below)
};

/// The unit ball cut by the plane z = split, meshed conformingly.
/// Surface 1 = lower cap (z < split), surface 2 = upper cap (z > split), surface 3 = the flat
/// wall. Body 1 = lower bubble {1, 3}, body 2 = upper bubble {2, 3}. About 3000 vertices at
/// h = 0.08. \throw InvalidInput for bad options, GeometryError if gmsh fails.
ClusterSpec build_double_bubble(const DoubleBubbleOptions& options);

struct SphereOptions {
    double R = 1.0; ///< radius, > 0
    double h = 0.1; ///< target edge length, 0.005 R <= h <= R
    Vec3 center = Vec3::Zero();
};

/// One spherical surface (sigma 1) enclosing one body.
/// \throw InvalidInput for bad options, GeometryError if gmsh fails.
ClusterSpec build_sphere(const SphereOptions& options);

struct PlanarPolygonsOptions {
    /// flat convex polygons by all their boundary points in cyclic order (corners and cuts)
    std::vector<std::vector<Vec3>> boundaries;
    double h = 0.1; ///< the largest interior edge length (Mesh.MeshSizeMax)
};
/// One surface per polygon (no bodies, no shared vertices), each meshed by gmsh's
/// Frontal-Delaunay keeping every boundary segment as an edge (polygon f's boundary points
/// are exactly the given ones), with sizes graded from the segments next to each point up to
/// h; triangles in either orientation.
/// \throw InvalidInput for a polygon of fewer than 3 points or h not positive;
/// GeometryError if gmsh fails.
ClusterSpec build_planar_polygons(const PlanarPolygonsOptions& options);

} // namespace froth
