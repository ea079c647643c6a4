// Meshing a periodic Voronoi diagram into a cluster (foam.h).
#include "foams/foam.h"

#include "core/errors.h"
#include "core/format.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace froth {
namespace {

constexpr int kMaxSplits = 4096;

Vec3 corner_mean(const std::vector<Vec3>& polygon) {
    Vec3 sum = Vec3::Zero();
    for (const Vec3& p : polygon) sum += p;
    return sum / static_cast<double>(polygon.size());
}

/// The fan of a convex polygon from its centroid, each fan triangle (c, p_i, p_i+1) split
/// into n^2 by the lattice c + (p_i - c) i/n + (p_i+1 - c) j/n, appended to spec as points
/// and triangles (points repeat along shared lines; identify_periodic_images merges them).
void add_split_fan(const std::vector<Vec3>& polygon, int n, ClusterSpec& spec,
                   ClusterSpec::Surface& surface) {
    const Vec3 center = corner_mean(polygon);
    for (std::size_t k = 0; k < polygon.size(); ++k) {
        const Vec3 u = polygon[k] - center, w = polygon[(k + 1) % polygon.size()] - center;
        const int base = static_cast<int>(spec.vertices.size());
        std::vector<int> row_start; // point (i, j) is base + row_start[i] + j, i + j <= n
        for (int i = 0; i <= n; ++i) {
            row_start.push_back(static_cast<int>(spec.vertices.size()) - base);
            for (int j = 0; i + j <= n; ++j)
                spec.vertices.push_back(center + u * (static_cast<double>(i) / n) +
                                        w * (static_cast<double>(j) / n));
        }
        const auto at = [&](int i, int j) { return base + row_start[i] + j; };
        for (int i = 0; i < n; ++i)
            for (int j = 0; i + j < n; ++j) {
                surface.triangles.push_back({at(i, j), at(i + 1, j), at(i, j + 1)});
                if (i + j + 1 < n) surface.triangles.push_back({at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
            }
    }
}

Vec3 newell_normal(const std::vector<Vec3>& polygon) {
    Vec3 normal = Vec3::Zero();
    for (std::size_t i = 0; i < polygon.size(); ++i)
        normal += polygon[i].cross(polygon[(i + 1) % polygon.size()]);
    return normal;
}

/// The faces meshed by `mesher` on their graded boundaries, each triangle turned to its
/// face's normal (from a to b: the orientation the fan gives); the mesher's vertices are the
/// spec's, merged across faces by identify_periodic_images afterwards.
ClusterSpec mesh_faces(const std::vector<VoronoiFace>& faces, const Eigen::Matrix3d& L, double h,
                       const PolygonMesher& mesher) {
    ClusterSpec spec = mesher(graded_boundaries(faces, L, h), h);
    if (spec.surfaces.size() != faces.size())
        throw GeometryError("foam: the mesher returned " + std::to_string(spec.surfaces.size()) +
                            " surfaces for " + std::to_string(faces.size()) + " Voronoi faces");
    for (std::size_t f = 0; f < faces.size(); ++f) {
        const Vec3 normal = newell_normal(faces[f].polygon);
        for (auto& t : spec.surfaces[f].triangles) {
            const Vec3 &a = spec.vertices[t[0]], &b = spec.vertices[t[1]], &c = spec.vertices[t[2]];
            if ((b - a).cross(c - a).dot(normal) < 0) std::swap(t[1], t[2]);
        }
    }
    spec.bodies.clear();
    return spec;
}

/// The longest spoke or rim of the faces' fans, which sets the fan's split count.
double longest_fan_edge(const std::vector<VoronoiFace>& faces) {
    double longest = 0;
    for (const VoronoiFace& f : faces) {
        const Vec3 center = corner_mean(f.polygon);
        for (std::size_t k = 0; k < f.polygon.size(); ++k)
            longest = std::max({longest, (f.polygon[k] - center).norm(),
                                (f.polygon[(k + 1) % f.polygon.size()] - f.polygon[k]).norm()});
    }
    return longest;
}

} // namespace

FoamMesh voronoi_foam(const std::vector<Vec3>& sites, const Eigen::Matrix3d& L, double h,
                      const PolygonMesher& mesher) {
    if (!(std::isfinite(h) && h > 0)) throw InvalidInput("foam: h must be positive, got " + fmt(h));
    const std::vector<VoronoiFace> faces = periodic_voronoi(sites, L);
    FoamMesh out;
    if (mesher) {
        out.spec = mesh_faces(faces, L, h, mesher);
    } else {
        const double splits = std::ceil(longest_fan_edge(faces) / h);
        if (!(splits <= kMaxSplits))
            throw InvalidInput("foam: h = " + fmt(h) + " would split each fan triangle " + fmt(splits) +
                               " times (at most " + std::to_string(kMaxSplits) + "); take a larger h");
        out.splits = std::max(1, static_cast<int>(splits));
        for (const VoronoiFace& f : faces) {
            out.spec.surfaces.emplace_back();
            add_split_fan(f.polygon, out.splits, out.spec, out.spec.surfaces.back());
        }
    }
    out.spec.bodies.resize(sites.size()); // surface f is face f
    for (std::size_t f = 0; f < faces.size(); ++f) {
        out.spec.bodies[faces[f].a].push_back(static_cast<int>(f));
        out.spec.bodies[faces[f].b].push_back(static_cast<int>(f)); // twice: a cell meets its image
    }
    identify_periodic_images(out.spec, L);
    return out;
}

} // namespace froth
