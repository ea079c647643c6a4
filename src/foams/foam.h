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

/// Meshes flat convex polygons given by all their boundary points in order (corners and the
/// cuts of their edges), keeping every boundary segment as an edge: one surface per polygon
/// (triangles in either orientation), interior edges up to h. The bindings pass gmsh's
/// (builders/gmsh_builder.h: build_planar_polygons); the foams module sees no gmsh.
using PolygonMesher = std::function<ClusterSpec(const std::vector<std::vector<Vec3>>& boundaries, double h)>;

/// Each face's boundary for a PolygonMesher: its corners with its edges cut in between, the
/// pieces graded from half a corner's shortest edge up to about h (edge_cuts.cpp), every edge
/// cut alike for all its films and into at least 2 pieces.
/// \throw InvalidInput when an edge would need more than 4096 pieces.
std::vector<std::vector<Vec3>> graded_boundaries(const std::vector<VoronoiFace>& faces, const Eigen::Matrix3d& L,
                                                 double h);

/// The periodic cluster of the Voronoi foam of `sites` in the box L (columns: period
/// vectors), films meshed with edges of about h: without a mesher by the split fans above
/// (at most 4096 splits per fan triangle), with one by it from graded_boundaries.
/// \throw InvalidInput for h not positive or too small for that, what periodic_voronoi and
/// the mesher throw, GeometryError when the mesher returns the wrong number of surfaces.
FoamMesh voronoi_foam(const std::vector<Vec3>& sites, const Eigen::Matrix3d& L, double h,
                      const PolygonMesher& mesher = {});

} // namespace froth
