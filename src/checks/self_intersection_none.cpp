// Built instead of self_intersection_cgal.cpp when CGAL is not available.
#include "checks/self_intersection.h"

namespace froth {

std::vector<FacetCrossing> find_self_intersections(const Cluster&, int, const Region*) {
    return {};
}

bool self_intersection_available() { return false; }

} // namespace froth
