#pragma once
/// The polytope { q : q . d_k <= 1 for all k } from its polar, the convex hull of the points d_k
/// (for the Wulff shape, d_k = p_k / gamma(p_k) are points of the Frank diagram).

#include "wulff/sphere_sampling.h"

#include <vector>

namespace froth {

/// The polytope P = { q : q . d_k <= 1 } for points d_k that surround 0 (0 inside their hull),
/// as a closed, outward-oriented triangulated surface. Polarity: each facet of conv{d_k} is a
/// vertex w of P with w . d = 1 on the facet; each hull corner d_k is a face of P, the polygon
/// of the vertices of the hull facets around d_k in the hull's cyclic order, in the plane
/// q . d_k = 1. Hull triangles form one facet when they are coplanar exactly (CGAL's exact
/// predicate) or within coplanar_tol * max |d_k| (round-off twins, which would give vertices of
/// P a few ulps apart); no other merging is done. Faces are fanned from their centroid.
/// \throw GeometryError if the hull is not consistently oriented about 0 (the d_k do not
/// surround 0, or degenerate input), or if a face folds over or a facet has no area because
/// its vertices are not resolved in double precision (gamma too close to crystalline).
TriangleSurface polar_polytope(const std::vector<Vec3>& d, double coplanar_tol, const char* who);

} // namespace froth
