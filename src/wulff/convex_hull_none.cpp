// Built instead of convex_hull_cgal.cpp when froth has no CGAL: Wulff shapes are unavailable
// (Frank diagrams and the Cahn–Hoffmann check need no hull and still work).
#include "wulff/convex_hull.h"

#include "core/errors.h"

#include <string>

namespace froth {

std::vector<Tri> convex_hull_triangles(const std::vector<Vec3>&, const char* who) {
    throw Error(std::string(who) +
                ": froth was built without CGAL, which computes the Wulff shape's convex hull "
                "(install libcgal-dev and configure with -DFROTH_WITH_CGAL=ON)");
}

int exact_orientation(const Vec3&, const Vec3&, const Vec3&, const Vec3&) {
    throw Error("exact_orientation: froth was built without CGAL");
}

bool convex_hull_available() {
    return false;
}

} // namespace froth
