#pragma once
/// Foams: clusters of many cells in a periodic box. A Voronoi foam's cells are the Voronoi
/// cells of its sites (foams/voronoi.h), each flat face a film meshed by a fan from its
/// centroid whose triangles are split n times (n from h, the same for every face, so that
/// faces sharing an edge split it alike); the films are then one periodic cluster
/// (mesh/cluster.h, identify_periodic_images), body k the cell of site k. Kelvin's foam is the
/// Voronoi foam of the BCC lattice and Weaire-Phelan's of the A15 lattice (lua/froth/foams.lua).

#include "foams/voronoi.h"
#include "mesh/cluster.h"

#include <functional>

namespace froth {

struct FoamMesh {
    ClusterSpec spec;
    int splits = 0; ///< n: each fan triangle is split into n^2 (0 with a PolygonMesher)
};

/// Meshes flat convex polygons: given every face's corners and, per edge i (corner i to
/// i + 1), the number of equal pieces to cut it into, returns one surface per polygon whose
/// boundary points are exactly the corners and the cuts (triangles in either orientation).
/// The bindings pass gmsh's (builders/gmsh_builder.h: build_planar_polygons), which grades
/// the triangles from a short edge's small pieces up to h; the foams module sees no gmsh.
using PolygonMesher = std::function<ClusterSpec(const std::vector<std::vector<Vec3>>& polygons,
                                                const std::vector<std::vector<int>>& segments, double h)>;

/// The periodic cluster of the Voronoi foam of `sites` in the box L (columns: period
/// vectors), films meshed with edges of about h: without a mesher by the split fans above
/// (at most 4096 splits per fan triangle), with one by it, each Voronoi edge cut into
/// ceil(length / h) pieces alike for all its films.
/// \throw InvalidInput for h not positive or too small for that, what periodic_voronoi and
/// the mesher throw, GeometryError when the mesher's boundary points do not close up.
FoamMesh voronoi_foam(const std::vector<Vec3>& sites, const Eigen::Matrix3d& L, double h,
                      const PolygonMesher& mesher = {});

} // namespace froth
