// The double bubble, the sphere and flat polygons (the session and extraction:
// gmsh_session.cpp).
#include "builders/gmsh_builder.h"

#include "builders/gmsh_session.h"
#include "core/errors.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <numbers>
#include <unordered_map>
#include <utility>

namespace froth {
using namespace gmsh_detail;
namespace {

// Groups the surface entities of the double bubble by their adjacent volumes: a seam can split
// one film into several entities, and the key (lower, upper or both) is what defines a film.
std::vector<FilmPlan> double_bubble_films(int lower, int upper, const DoubleBubbleOptions& o) {
    std::vector<FilmPlan> films(3);
    for (int i = 0; i < 3; ++i)
        films[i].sigma = o.sigma[i];
    for (int s : entity_tags(2)) {
        const std::vector<int> up = adjacent(2, s, true);
        if (up == std::vector<int>{lower})
            films[0].entities.push_back(s);
        else if (up == std::vector<int>{upper})
            films[1].entities.push_back(s);
        else if (up == std::vector<int>{std::min(lower, upper), std::max(lower, upper)})
            films[2].entities.push_back(s);
    }
    for (int i = 0; i < 3; ++i)
        if (films[i].entities.empty())
            throw GeometryError("double_bubble: gmsh produced no surface " + std::to_string(i + 1));
    return films;
}

} // namespace

ClusterSpec build_double_bubble(const DoubleBubbleOptions& o) {
    const std::string op = "double_bubble";
    check_h(op, o.h, 0.005, 0.5, 5 * std::numbers::pi);
    if (!(std::isfinite(o.split) && std::abs(o.split) <= 0.9))
        throw InvalidInput(op + ": split must be in [-0.9, 0.9], got " + num(o.split));
    for (int i = 0; i < 3; ++i)
        if (!(std::isfinite(o.sigma[i]) && o.sigma[i] > 0))
            throw InvalidInput(op + ": sigma[" + std::to_string(i + 1) +
                               "] must be positive, got " + num(o.sigma[i]));
    return in_session<GeometryError>(op + ": gmsh failed: ", [&] {
        namespace occ = gmsh::model::occ;
        gmsh::model::add(op);
        const int ball = occ::addSphere(0, 0, 0, 1);
        const int box = occ::addBox(-2, -2, -2, 4, 4, 2 + o.split); // the half-space z < split
        gmsh::vectorpair pieces, outside;
        std::vector<gmsh::vectorpair> map;
        occ::fragment({{3, ball}}, {{3, box}}, pieces, map);
        int lower = -1, upper = -1;
        for (auto [dim, tag] : pieces) {
            if (dim != 3) continue;
            double x0, y0, z0, x1, y1, z1;
            occ::getBoundingBox(3, tag, x0, y0, z0, x1, y1, z1);
            if (x1 - x0 > 3)
                outside.push_back({3, tag}); // the rest of the 4-wide box
            else
                (z0 + z1 < 2 * o.split ? lower : upper) = tag;
        }
        if (lower < 0 || upper < 0) throw GeometryError(op + ": the fragment lacks a bubble");
        occ::remove(outside, /*recursive=*/true); // keeps the cap it shares with the lower bubble
        occ::synchronize();
        mesh_surfaces(o.h);
        return extract(double_bubble_films(lower, upper, o), {{0, 2}, {1, 2}}, op);
    });
}

ClusterSpec build_sphere(const SphereOptions& o) {
    const std::string op = "sphere";
    if (!(std::isfinite(o.R) && o.R > 0))
        throw InvalidInput(op + ": R must be positive, got " + num(o.R));
    if (!o.center.allFinite()) throw InvalidInput(op + ": center must be finite");
    check_h(op, o.h, 0.0035 * o.R, o.R, 4 * std::numbers::pi * o.R * o.R); // about 1.2M vertices
    return in_session<GeometryError>(op + ": gmsh failed: ", [&] {
        // Mesh the unit sphere at the origin and map it: OCC's Frontal-Delaunay fails on some
        // offset spheres (R = 2 at (1,-2,3)) and gmsh silently falls back to MeshAdapt, 10x
        // slower. The unit sphere meshes at every h tried, and scaling keeps the shape.
        gmsh::model::add(op);
        gmsh::model::occ::addSphere(0, 0, 0, 1);
        gmsh::model::occ::synchronize();
        mesh_surfaces(o.h / o.R);
        FilmPlan film;
        film.entities = entity_tags(2); // the sphere face (its seam does not split it)
        ClusterSpec spec = extract({film}, {{0}}, op);
        for (Vec3& x : spec.vertices)
            x = o.center + o.R * x;
        return spec;
    });
}

namespace {

void check_polygons(const PlanarPolygonsOptions& o, const std::string& op) {
    if (!(std::isfinite(o.h) && o.h > 0)) throw InvalidInput(op + ": h must be positive, got " + num(o.h));
    for (std::size_t f = 0; f < o.boundaries.size(); ++f)
        if (o.boundaries[f].size() < 3)
            throw InvalidInput(op + ": polygon " + std::to_string(f + 1) + " has fewer than 3 points");
}

/// Adds a polygon as a geo plane surface of one line per boundary segment, each transfinite
/// with no inner node (so gmsh keeps the segments), each point sized by its shorter segment
/// (so the triangles grade from the segments up to h); returns the surface's tag.
int add_polygon(const std::vector<Vec3>& boundary, double h) {
    namespace geo = gmsh::model::geo;
    const std::size_t n = boundary.size();
    std::vector<int> points, lines;
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3& x = boundary[i];
        const double size = std::min({h, (boundary[(i + 1) % n] - x).norm(), (boundary[(i + n - 1) % n] - x).norm()});
        points.push_back(geo::addPoint(x[0], x[1], x[2], size));
    }
    for (std::size_t i = 0; i < n; ++i) {
        lines.push_back(geo::addLine(points[i], points[(i + 1) % n]));
        geo::mesh::setTransfiniteCurve(lines.back(), 2);
    }
    return geo::addPlaneSurface({geo::addCurveLoop(lines)});
}

} // namespace

ClusterSpec build_planar_polygons(const PlanarPolygonsOptions& o) {
    const std::string op = "foam mesher";
    check_polygons(o, op);
    return in_session<GeometryError>(op + ": gmsh failed: ", [&] {
        gmsh::model::add("polygons");
        std::vector<FilmPlan> films(o.boundaries.size());
        for (std::size_t f = 0; f < o.boundaries.size(); ++f)
            films[f].entities = {add_polygon(o.boundaries[f], o.h)};
        gmsh::model::geo::synchronize();
        mesh_surfaces(o.h);
        return extract(films, {}, op);
    });
}

} // namespace froth
