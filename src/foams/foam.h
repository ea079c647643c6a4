#pragma once
/// Foams: clusters of many cells in a periodic box. A Voronoi foam's cells are the Voronoi
/// cells of its sites (foams/voronoi.h), each flat face a film meshed by a fan from its
/// centroid whose triangles are split n times (n from h, the same for every face, so that
/// faces sharing an edge split it alike); the films are then one periodic cluster
/// (mesh/cluster.h, identify_periodic_images), body k the cell of site k. Kelvin's foam is the
/// Voronoi foam of the BCC lattice and Weaire-Phelan's of the A15 lattice (lua/froth/foams.lua).

#include "foams/voronoi.h"
#include "mesh/cluster.h"

namespace froth {

struct FoamMesh {
    ClusterSpec spec;
    int splits = 0; ///< n: each fan triangle is split into n^2
};

/// The periodic cluster of the Voronoi foam of `sites` in the box L (columns: period
/// vectors), films meshed with edges of about h (at most 4096 splits per fan triangle).
/// \throw InvalidInput for h not positive or too small for that, what periodic_voronoi throws.
FoamMesh voronoi_foam(const std::vector<Vec3>& sites, const Eigen::Matrix3d& L, double h);

} // namespace froth
