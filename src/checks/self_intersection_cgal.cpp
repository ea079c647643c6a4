// The only translation unit that includes CGAL (it adds -frounding-math to what it compiles).
#include "checks/self_intersection.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace froth {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Triangle = Kernel::Triangle_3;

struct SoupFacet {
    FacetRef ref;
    Tri corners;
    Triangle triangle;
};
using Box = CGAL::Box_intersection_d::Box_with_handle_d<double, 3, const SoupFacet*>;

bool share_a_vertex(const Tri& p, const Tri& q) {
    for (int v : p)
        if (std::find(q.begin(), q.end(), v) != q.end()) return true;
    return false;
}

/// True if a corner of x lies in the region (through the period's nearest image).
bool in_region(const Cluster& c, const std::array<Vec3, 3>& x, const Region& r) {
    for (const Vec3& p : x) {
        Vec3 d = p - r.centre;
        if (c.periodic()) {
            const Vec3 k = c.period().inverse() * d;
            d -= c.period() * Vec3(std::round(k.x()), std::round(k.y()), std::round(k.z()));
        }
        if (d.norm() <= r.radius) return true;
    }
    return false;
}

} // namespace

std::vector<FacetCrossing> find_self_intersections(const Cluster& c, int max_pairs,
                                                   const Region* region) {
    const auto& X = c.positions();
    std::vector<SoupFacet> soup;
    soup.reserve(c.n_facets());
    for (int i = 0; i < c.n_surfaces(); ++i) {
        const auto& tris = c.surface(i).triangles;
        for (int f = 0; f < static_cast<int>(tris.size()); ++f) {
            // Each facet where its corners put it: in a periodic cluster only facets that meet
            // in the same copy of the box are found (a crossing through the box's faces is not).
            const auto x = c.surface(i).corners(X, f);
            if (region && !in_region(c, x, *region)) continue;
            auto point = [&](int a) { return Point(x[a][0], x[a][1], x[a][2]); };
            soup.push_back({{i, f}, tris[f], Triangle(point(0), point(1), point(2))});
        }
    }
    std::vector<Box> boxes;
    boxes.reserve(soup.size());
    for (const SoupFacet& s : soup) boxes.emplace_back(s.triangle.bbox(), &s);
    std::vector<FacetCrossing> found;
    // Facets sharing a vertex touch by construction; only disjoint ones may not meet.
    auto report = [&](const Box& a, const Box& b) {
        if (static_cast<int>(found.size()) >= max_pairs) return;
        const SoupFacet& p = *a.handle();
        const SoupFacet& q = *b.handle();
        if (share_a_vertex(p.corners, q.corners)) return;
        if (p.triangle.is_degenerate() || q.triangle.is_degenerate()) return;
        if (CGAL::do_intersect(p.triangle, q.triangle)) found.push_back({p.ref, q.ref});
    };
    CGAL::box_self_intersection_d(boxes.begin(), boxes.end(), report);
    return found;
}

bool self_intersection_available() { return true; }

} // namespace froth
