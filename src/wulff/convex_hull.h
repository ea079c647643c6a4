#pragma once
/// The convex hull behind wulff_shape, by CGAL with exact predicates. The only CGAL code of the
/// wulff module is convex_hull_cgal.cpp; without CGAL, convex_hull_none.cpp throws.

#include "mesh/cluster.h"

#include <vector>

namespace froth {

/// The triangles of the convex hull of `points` as indices into `points` (CGAL's convex_hull_3
/// with exact predicates on the given doubles). Points that are no hull vertex appear in no
/// triangle; a hull facet with more than three vertices comes triangulated. The orientation of
/// the triangles is not specified (wulff.cpp orients them). Throws froth::Error saying so when
/// froth was built without CGAL; `who` prefixes that message.
std::vector<Tri> convex_hull_triangles(const std::vector<Vec3>& points, const char* who);

/// The sign (+1, 0, -1) of det(b - a, c - a, d - a), exact for the given doubles (CGAL's
/// filtered orientation predicate): 0 exactly when the four points are coplanar.
int exact_orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d);

/// False when froth was built without CGAL.
bool convex_hull_available();

} // namespace froth
