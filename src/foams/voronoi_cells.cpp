// Cell volumes and centroids of a periodic Voronoi diagram, and Lloyd's relaxation on them
// (voronoi.h). Needs no CGAL: it reads the faces periodic_voronoi returns.
#include "foams/voronoi.h"

#include "core/errors.h"
#include "core/interrupt.h"

#include <Eigen/Geometry>

#include <string>

namespace froth {
namespace {

struct Moments {
    double volume = 0;
    Vec3 first = Vec3::Zero();
    Vec3 apex = Vec3::Zero();
    bool has_apex = false;
};

/// Adds the signed fan of `polygon` + `shift` (hub its corner mean, apex the cell's) to the
/// cell's volume and first moment; `sign` is +1 where the polygon's normal points out of it.
/// Any apex gives the exact volume of a closed cell; a corner of the cell keeps the fans'
/// round-off at the cell's own size.
void add_face(const std::vector<Vec3>& polygon, const Vec3& shift, double sign, Moments& cell) {
    if (!cell.has_apex) cell.apex = polygon.front() + shift, cell.has_apex = true;
    const Vec3& o = cell.apex;
    Vec3 hub = Vec3::Zero();
    for (const Vec3& p : polygon) hub += p;
    hub = hub / static_cast<double>(polygon.size()) + shift;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Vec3 p = polygon[i] + shift, q = polygon[(i + 1) % polygon.size()] + shift;
        const double v = sign * (hub - o).dot((p - o).cross(q - o)) / 6;
        cell.volume += v;
        cell.first += v * (o + hub + p + q) / 4;
    }
}

} // namespace

VoronoiCells voronoi_cells(const std::vector<VoronoiFace>& faces, int n, const Eigen::Matrix3d& L) {
    std::vector<Moments> cells(n);
    for (const VoronoiFace& f : faces) {
        // Face (a, b, k) lies at a's central copy with its normal out of a, and at b's copy
        // shifted by L k: b sees it shifted back, the normal into b.
        add_face(f.polygon, Vec3::Zero(), 1.0, cells[f.a]);
        add_face(f.polygon, -(L * f.offset.cast<double>()), -1.0, cells[f.b]);
    }
    VoronoiCells out;
    for (int s = 0; s < n; ++s) {
        if (!(cells[s].volume > 0))
            throw InvalidInput("foam: the Voronoi cell of site " + std::to_string(s + 1) + " is empty");
        out.volumes.push_back(cells[s].volume);
        out.centroids.push_back(cells[s].first / cells[s].volume);
    }
    return out;
}

std::vector<Vec3> lloyd_relax(std::vector<Vec3> sites, const Eigen::Matrix3d& L, int iterations) {
    if (iterations < 0)
        throw InvalidInput("foam: lloyd must be a count >= 0, got " + std::to_string(iterations));
    // thousands of steps on many sites take minutes: Ctrl-C ends them between steps
    const EngineLoopScope loop;
    for (int it = 0; it < iterations; ++it) {
        if (consume_interrupt())
            throw Interrupted("foam: interrupted (Ctrl-C) after " + std::to_string(it) + " of " +
                              std::to_string(iterations) + " Lloyd steps; nothing was built");
        sites = voronoi_cells(periodic_voronoi(sites, L), static_cast<int>(sites.size()), L).centroids;
    }
    return sites;
}

} // namespace froth
