#pragma once
/// Wulff shapes and Frank diagrams of an anisotropy gamma of the class (1.15) (seed: Barrett,
/// Garcke and Nürnberg 2009, after (1.16)):
///
///   Wulff shape     W = { q : q . p <= gamma(p) for all p } = { q : gamma*(q) <= 1 }   (1.16)
///   Frank diagram   F = { p : gamma(p) <= 1 }
///
/// W and F are polar to each other. W minimises the energy E = int gamma(nu) among bodies of its
/// volume, and E(r W) = 3 r^2 |W|. For smooth gamma the Cahn–Hoffmann map p -> gamma'(p) maps
/// the unit sphere onto the boundary of W, with normal p at gamma'(p).

#include "anisotropy/anisotropy.h"
#include "mesh/cluster.h"

#include <optional>
#include <vector>

namespace froth {

struct WulffOptions {
    /// The plane directions p_k: the icosphere of this level (10 * 4^k + 2 directions; 0..7)...
    int subdivisions = 4;
    /// ...or, when set, this many Fibonacci-sphere directions instead (20..200000).
    std::optional<int> directions;
    /// Also the directions where a nearly crystalline gamma has facets (facet_directions() of
    /// sphere_sampling.h), so that those facets appear flat with their exact support value.
    bool facet_directions = true;
    /// The result is scale * W_h (finite, > 0): its energy is 3 scale^2 |W_h|.
    double scale = 1.0;
};

/// The Wulff shape, discretised as the polytope W_h = { q : q . p_k <= gamma(p_k) for all k }
/// (W_h contains W and converges to it as the directions p_k fill the sphere), scaled by
/// options.scale. Computed exactly for the given doubles: the faces of W_h are polar to the
/// vertices of the convex hull of the Frank diagram points p_k / gamma(p_k) (CGAL, exact
/// predicates), its vertices to the hull's facets. Each polygonal face lies in its plane
/// q . p_k = gamma(p_k) and is triangulated by a fan from its centroid (triangles as they are);
/// vertices closer than 1e-9 times the polytope's radius are merged first, so no facet is
/// degenerate. One closed outward-oriented surface (sigma 1) and one body.
/// \throw InvalidInput naming the option for subdivisions, directions or scale out of range;
///        froth::Error when froth was built without CGAL.
ClusterSpec wulff_shape(const Anisotropy& gamma, const WulffOptions& options = {});

/// The Frank diagram: the icosphere of the given level (0..7) with each vertex p moved to
/// p / gamma(p) on the boundary of F. F is convex and star-shaped about 0, so the surface is
/// closed, outward oriented and has no degenerate facet. One surface (sigma 1), one body.
/// \throw InvalidInput for subdivisions out of range.
ClusterSpec frank_diagram(const Anisotropy& gamma, int subdivisions = 4);

/// How well a convex polytope containing 0 (a closed triangulated surface: vertices X,
/// triangles of any orientation) matches scale * W, via the Cahn–Hoffmann map. For sample
/// directions p the point x = scale gamma'(p) lies on the boundary of scale * W, which W_h
/// contains; the distance of x to the boundary of the polytope is min_t (h_t - nu_t . x) over
/// the facet planes nu_t . q = h_t. The samples are `samples` Fibonacci points turned by a fixed
/// generic rotation, so that they miss the plane directions of wulff_shape (at a plane
/// direction p_k the point gamma'(p_k) lies on the face of W_h exactly, distance 0). All values
/// are divided by scale.
struct CahnHoffmannCheck {
    /// max_p |min_t (h_t - nu_t . x)|: how far the polytope is from scale * W at its
    /// Cahn–Hoffmann points (O(h^2) for smooth gamma and direction spacing h).
    double max_distance = 0.0;
    /// max_p max(0, -min_t (h_t - nu_t . x)): how far a point gamma'(p) lies outside the
    /// polytope; 0 up to round-off for any polytope containing W, such as W_h.
    double max_outside = 0.0;
    /// max_t |h_t - scale gamma(nu_t)| over triangles t: 0 up to round-off when every facet
    /// lies on a plane q . nu = gamma(nu), as for W_h. The round-off grows as a triangle's size
    /// shrinks (its normal comes from its corners): ~1e-11 at the rounded corners of l1(1e-3).
    double max_support_error = 0.0;
    /// |sum_t gamma(nu_t) |t| - 3 |polytope| / scale| / (3 |polytope| / scale): the relative
    /// defect of E = 3 r^2 |W|, since 3 |polytope| = sum_t h_t |t|. Each h_t >= scale
    /// gamma(nu_t) when the polytope contains scale * W, so this is the area-weighted mean
    /// support error: 0 up to round-off for W_h.
    double energy_defect = 0.0;
    int samples = 0; ///< the number of directions p
};

/// \throw InvalidInput for scale not finite and > 0, samples out of 1..200000, no triangles,
///        or a triangle naming a vertex that does not exist.
CahnHoffmannCheck cahn_hoffmann_check(const Anisotropy& gamma, const std::vector<Vec3>& X,
                                      const std::vector<Tri>& triangles, double scale = 1.0,
                                      int samples = 1000);

/// False when froth was built without CGAL (then wulff_shape throws).
bool wulff_shape_available();

} // namespace froth
