#pragma once
/// Direction sets on the unit sphere for the Wulff shapes and Frank diagrams of wulff.h: the
/// subdivided icosahedron (a closed triangulated unit sphere), Fibonacci points, and the
/// directions where a nearly crystalline anisotropy (1.17) has the facets of its Wulff shape.

#include "anisotropy/anisotropy.h"
#include "mesh/cluster.h"

#include <vector>

namespace froth {

/// A closed triangulated surface: triangles counterclockwise seen from outside.
struct TriangleSurface {
    std::vector<Vec3> vertices;
    std::vector<Tri> triangles;
};

/// The icosahedron, its edges bisected `subdivisions` times and projected to the unit sphere:
/// 10 * 4^k + 2 vertices, 20 * 4^k triangles. It contains +-e_x, +-e_y, +-e_z for k >= 1 (they
/// are edge midpoints of the icosahedron with vertices (0, +-1, +-phi) and its cyclic shifts).
/// The callers bound subdivisions and name the option (the Wulff shapes: kMaxSubdivisions;
/// froth.sphere{levels}: 9, 2621442 vertices).
TriangleSurface icosphere(int subdivisions);

/// The largest subdivision level accepted (163842 vertices).
inline constexpr int kMaxSubdivisions = 7;

/// Directions at which the Wulff shape of a nearly crystalline gamma has (almost flat) facets.
/// A term of (1.15) is needle-like when the largest eigenvalue of G_l is at least 25 times the
/// middle one (for (1.17), G_l = eps^2 I + (1 - eps^2) a_l a_l^T, eps <= 0.2); let a_l be its
/// eigenvector. Returned (both signs, unit, without repeats): the a_l; the normals a_i x a_j,
/// facets of the zonotope sum_l [-a_l, a_l], which is the Wulff shape of the r = 1 limit
/// sum_l |a_l . p|; and the p with a_i . p = +-1, a_j . p = +-1, a_k . p = +-1, corners of the
/// Frank diagram of the r -> infinity limit max_l |a_l . p|, hence facet normals of its Wulff
/// shape (the hull of the +-a_l). Empty when no term is needle-like (isotropic, ellipsoidal).
std::vector<Vec3> facet_directions(const Anisotropy& gamma);

} // namespace froth
