// The only translation unit of the wulff module that includes CGAL (it adds -frounding-math to
// what it compiles). convex_hull_3 into an indexed triangle set keeps the compile time low
// (no Surface_mesh, no halfspace_intersection_3).
#include "wulff/convex_hull.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_3.h>

#include <array>
#include <map>

namespace froth {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;

Point point(const Vec3& x) {
    return Point(x[0], x[1], x[2]);
}

} // namespace

std::vector<Tri> convex_hull_triangles(const std::vector<Vec3>& points, const char*) {
    // CGAL keeps repeated input points as separate hull vertices (degenerate triangles), so
    // each point goes in once; the hull copies coordinates exactly, which maps them back.
    std::vector<Point> in;
    std::map<std::array<double, 3>, int> id;
    for (int i = 0; i < static_cast<int>(points.size()); ++i)
        if (id.try_emplace({points[i][0], points[i][1], points[i][2]}, i).second)
            in.push_back(point(points[i]));
    std::vector<Point> hull_points;
    std::vector<std::array<int, 3>> hull_faces;
    CGAL::convex_hull_3(in.begin(), in.end(), hull_points, hull_faces);
    std::vector<int> to_input(hull_points.size());
    for (std::size_t v = 0; v < hull_points.size(); ++v)
        to_input[v] = id.at({hull_points[v].x(), hull_points[v].y(), hull_points[v].z()});
    std::vector<Tri> out;
    out.reserve(hull_faces.size());
    for (const auto& f : hull_faces)
        out.push_back({to_input[f[0]], to_input[f[1]], to_input[f[2]]});
    return out;
}

int exact_orientation(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    return static_cast<int>(CGAL::orientation(point(a), point(b), point(c), point(d)));
}

bool convex_hull_available() {
    return true;
}

} // namespace froth
