// Meshing a periodic Voronoi diagram into a cluster (foam.h).
#include "foams/foam.h"

#include "core/errors.h"
#include "core/format.h"

#include <algorithm>
#include <cmath>

namespace froth {
namespace {

constexpr int kMaxSplits = 4096;

/// The fan of a convex polygon from its centroid, each fan triangle (c, p_i, p_i+1) split
/// into n^2 by the lattice c + (p_i - c) i/n + (p_i+1 - c) j/n, appended to spec as points
/// and triangles (points repeat along shared lines; identify_periodic_images merges them).
void add_split_fan(const std::vector<Vec3>& polygon, int n, ClusterSpec& spec,
                   ClusterSpec::Surface& surface) {
    Vec3 center = Vec3::Zero();
    for (const Vec3& p : polygon) center += p;
    center /= static_cast<double>(polygon.size());
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

} // namespace

FoamMesh voronoi_foam(const std::vector<Vec3>& sites, const Eigen::Matrix3d& L, double h) {
    if (!(std::isfinite(h) && h > 0)) throw InvalidInput("foam: h must be positive, got " + fmt(h));
    const std::vector<VoronoiFace> faces = periodic_voronoi(sites, L);
    double longest = 0; // of the fans' spokes and rims
    for (const VoronoiFace& f : faces) {
        Vec3 center = Vec3::Zero();
        for (const Vec3& p : f.polygon) center += p;
        center /= static_cast<double>(f.polygon.size());
        for (std::size_t k = 0; k < f.polygon.size(); ++k)
            longest = std::max({longest, (f.polygon[k] - center).norm(),
                                (f.polygon[(k + 1) % f.polygon.size()] - f.polygon[k]).norm()});
    }
    const double splits = std::ceil(longest / h);
    if (!(splits <= kMaxSplits))
        throw InvalidInput("foam: h = " + fmt(h) + " would split each fan triangle " + fmt(splits) +
                           " times (at most " + std::to_string(kMaxSplits) + "); take a larger h");
    FoamMesh out;
    out.splits = std::max(1, static_cast<int>(splits));
    out.spec.bodies.resize(sites.size());
    for (const VoronoiFace& f : faces) {
        ClusterSpec::Surface surface;
        add_split_fan(f.polygon, out.splits, out.spec, surface);
        const int id = static_cast<int>(out.spec.surfaces.size());
        out.spec.surfaces.push_back(std::move(surface));
        out.spec.bodies[f.a].push_back(id);
        out.spec.bodies[f.b].push_back(id); // twice when a cell meets its own image
    }
    identify_periodic_images(out.spec, L);
    return out;
}

} // namespace froth
