// The only translation unit that includes CGAL (it adds -frounding-math to what it compiles).
#include "checks/self_intersection.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/box_intersection_d.h>
#include <CGAL/intersections.h>

#include <algorithm>

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

} // namespace

std::vector<FacetCrossing> find_self_intersections(const Cluster& c, int max_pairs) {
    const auto& X = c.positions();
    std::vector<SoupFacet> soup;
    soup.reserve(c.n_facets());
    for (int i = 0; i < c.n_surfaces(); ++i) {
        const auto& tris = c.surface(i).triangles;
        for (int f = 0; f < static_cast<int>(tris.size()); ++f) {
            const Tri& t = tris[f];
            auto point = [&](int v) { return Point(X[v][0], X[v][1], X[v][2]); };
            soup.push_back({{i, f}, t, Triangle(point(t[0]), point(t[1]), point(t[2]))});
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
