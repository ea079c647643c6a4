#pragma once
/// The Voronoi diagram of sites in a periodic box, the cells of froth's foams. The only CGAL
/// code of the foams module is voronoi_cgal.cpp (Delaunay triangulation with exact predicates;
/// the faces are the duals of its edges); without CGAL, voronoi_none.cpp throws.

#include "core/types.h"

#include <Eigen/Core>

#include <vector>

namespace froth {

/// One face of a periodic Voronoi diagram: the film between the cell of site `a` (in the
/// central copy of the box) and the cell of site `b` translated by L * offset.
struct VoronoiFace {
    int a, b;
    Eigen::Vector3i offset;
    /// The face's corners in cyclic order, counterclockwise seen from cell b (the normal
    /// points from a to b), near site a's central copy.
    std::vector<Vec3> polygon;
};

/// Every face of the Voronoi diagram of `sites` (positions in space, reduced into the box
/// L [0, 1)^3 first) modulo the lattice L Z^3, each once. Throws InvalidInput for fewer than
/// one site, coincident sites (modulo the lattice), or a degenerate diagram (a face with
/// fewer than three distinct corners); froth::Error saying so without CGAL.
std::vector<VoronoiFace> periodic_voronoi(const std::vector<Vec3>& sites, const Eigen::Matrix3d& L);

/// The volume and centroid of each cell of a periodic Voronoi diagram (`faces` as
/// periodic_voronoi returns them for n sites in the box L), each centroid near the cell's site
/// reduced into the box: exact for the flat cells (signed fans from each face's corner mean).
/// Throws InvalidInput for a cell of no volume.
struct VoronoiCells {
    std::vector<double> volumes;
    std::vector<Vec3> centroids;
};
VoronoiCells voronoi_cells(const std::vector<VoronoiFace>& faces, int n, const Eigen::Matrix3d& L);

/// `iterations` steps of Lloyd's algorithm on the periodic diagram: every site moves to its
/// cell's centroid (towards a centroidal Voronoi tessellation, whose cells are rounder, more
/// equal in volume and have fewer short edges and small faces). Throws what periodic_voronoi
/// throws, InvalidInput for a negative count, Interrupted on Ctrl-C (polled between steps).
std::vector<Vec3> lloyd_relax(std::vector<Vec3> sites, const Eigen::Matrix3d& L, int iterations);

/// False when froth was built without CGAL.
bool voronoi_available();

} // namespace froth
