// The only translation unit of the foams module that includes CGAL (it adds -frounding-math to
// what it compiles). The periodic diagram is read off the Delaunay triangulation of the sites
// and their 26 neighbouring copies: each Delaunay edge from a site of the central copy is dual
// to a Voronoi face, whose corners are the circumcenters of the tetrahedra around the edge in
// the order the edge's cell circulator gives. Exact predicates decide the combinatorics, so
// which cells meet is never a matter of round-off; only the corners are constructed in doubles.
#include "foams/voronoi.h"

#include "core/errors.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <Eigen/Geometry>
#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <tuple>
#include <utility>

namespace froth {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<int, Kernel>;
using Tds = CGAL::Triangulation_data_structure_3<Vb>;
using Delaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;

constexpr int kCopies = 27;
constexpr int kCentral = 13; // the copy with offset (0, 0, 0)

Eigen::Vector3i copy_offset(int copy) { return {copy / 9 - 1, copy / 3 % 3 - 1, copy % 3 - 1}; }

Vec3 vec(const Point& p) { return {p.x(), p.y(), p.z()}; }

bool positive(const Eigen::Vector3i& k) {
    return std::tie(k[0], k[1], k[2]) > std::tuple<int, int, int>(0, 0, 0);
}

} // namespace

std::vector<VoronoiFace> periodic_voronoi(const std::vector<Vec3>& sites, const Eigen::Matrix3d& L) {
    const int n = static_cast<int>(sites.size());
    if (n < 1) throw InvalidInput("foam: no sites");
    const double scale = L.colwise().norm().prod();
    if (!L.allFinite() || !(std::abs(L.determinant()) > 1e-12 * scale))
        throw InvalidInput("foam: the period vectors must be finite and linearly independent");
    const Eigen::Matrix3d Linv = L.inverse();
    std::vector<std::pair<Point, int>> points;
    points.reserve(static_cast<std::size_t>(kCopies) * n);
    for (int s = 0; s < n; ++s) {
        if (!sites[s].allFinite())
            throw InvalidInput("foam: site " + std::to_string(s + 1) + " is not finite");
        const Vec3 u = Linv * sites[s];
        const Vec3 reduced = L * (u.array() - u.array().floor()).matrix();
        for (int c = 0; c < kCopies; ++c) {
            const Vec3 x = reduced + L * copy_offset(c).cast<double>();
            points.emplace_back(Point(x[0], x[1], x[2]), c * n + s);
        }
    }
    const Delaunay dt(points.begin(), points.end());
    if (static_cast<int>(dt.number_of_vertices()) != kCopies * n)
        throw InvalidInput("foam: two sites coincide (modulo the period)");
    std::vector<VoronoiFace> faces;
    std::set<std::tuple<int, int, int, int, int>> seen;
    for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) {
        const auto u0 = e->first->vertex(e->second), w0 = e->first->vertex(e->third);
        for (const auto& [u, w] : {std::pair{u0, w0}, std::pair{w0, u0}}) {
            if (u->info() / n != kCentral) continue;
            const int a = u->info() % n, b = w->info() % n;
            const Eigen::Vector3i k = copy_offset(w->info() / n) - copy_offset(kCentral);
            if (a > b || (a == b && !positive(k))) continue; // the face seen from b's side
            if (!seen.emplace(a, b, k[0], k[1], k[2]).second) continue;
            VoronoiFace face{a, b, k, {}};
            auto cell = dt.incident_cells(*e);
            const auto done = cell;
            do {
                if (dt.is_infinite(cell))
                    throw InvalidInput("foam: the Voronoi cell of site " + std::to_string(a + 1) +
                                       " reaches beyond the neighbouring copies of the box "
                                       "(sites too few or too unevenly spread for the period)");
                const Vec3 x = vec(CGAL::circumcenter(cell->vertex(0)->point(), cell->vertex(1)->point(),
                                                      cell->vertex(2)->point(), cell->vertex(3)->point()));
                // tetrahedra with one circumsphere (five cospherical sites) give one corner
                if (face.polygon.empty() || (x - face.polygon.back()).norm() > 1e-12 * std::cbrt(scale))
                    face.polygon.push_back(x);
            } while (++cell != done);
            if (face.polygon.size() > 1 &&
                (face.polygon.front() - face.polygon.back()).norm() <= 1e-12 * std::cbrt(scale))
                face.polygon.pop_back();
            if (face.polygon.size() < 3)
                throw InvalidInput("foam: the Voronoi face between sites " + std::to_string(a + 1) +
                                   " and " + std::to_string(b + 1) + " has fewer than three corners "
                                   "(a degenerate diagram)");
            Vec3 normal = Vec3::Zero(); // Newell's normal of the polygon
            for (std::size_t i = 0; i < face.polygon.size(); ++i)
                normal += face.polygon[i].cross(face.polygon[(i + 1) % face.polygon.size()]);
            if (normal.dot(vec(w->point()) - vec(u->point())) < 0)
                std::reverse(face.polygon.begin(), face.polygon.end());
            // CGAL's spatial sort shuffles the insertion order with its default random state:
            // start each polygon at its least corner so that a foam does not depend on it.
            std::rotate(face.polygon.begin(),
                        std::min_element(face.polygon.begin(), face.polygon.end(),
                                         [](const Vec3& x, const Vec3& y) {
                                             return std::tie(x[0], x[1], x[2]) < std::tie(y[0], y[1], y[2]);
                                         }),
                        face.polygon.end());
            faces.push_back(std::move(face));
        }
    }
    std::sort(faces.begin(), faces.end(), [](const VoronoiFace& x, const VoronoiFace& y) {
        return std::tie(x.a, x.b, x.offset[0], x.offset[1], x.offset[2]) <
               std::tie(y.a, y.b, y.offset[0], y.offset[1], y.offset[2]);
    });
    return faces;
}

bool voronoi_available() { return true; }

} // namespace froth
