#pragma once
/// Self-intersection of a cluster: pairs of facets that cross without sharing a vertex. The
/// parametric method cannot pass a topology change; a crossing means it was attempted.
/// CGAL's box intersection finds candidate pairs, exact predicates decide (the only CGAL code).

#include "mesh/cluster.h"

#include <vector>

namespace froth {

/// One facet, as (surface, index within the surface), both 0-based.
struct FacetRef {
    int surface, facet;
};

struct FacetCrossing {
    FacetRef a, b;
};

/// A ball: only the facets with a corner in it are tested (in a periodic cluster the distance
/// to the nearest image of the centre counts).
struct Region {
    Vec3 centre;
    double radius;
};

/// Up to max_pairs crossing facet pairs (empty: none); with `region`, among its facets only.
std::vector<FacetCrossing> find_self_intersections(const Cluster& c, int max_pairs = 1,
                                                   const Region* region = nullptr);

/// False when froth was built without CGAL (then find_self_intersections finds nothing).
bool self_intersection_available();

} // namespace froth
