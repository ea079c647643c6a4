// Evolver's `r`: every facet into four at its edge midpoints (refine in cluster.h).
#include "core/errors.h"
#include "mesh/cluster.h"

#include <map>

namespace froth {
namespace {

/// The walls both ends of edge (a, b) are attached to.
std::vector<int> common_walls(const Cluster& c, int a, int b) {
    std::vector<int> common;
    const std::vector<int> wa = c.vertex_walls(a), wb = c.vertex_walls(b);
    for (int w : wa)
        for (int u : wb)
            if (w == u) common.push_back(w);
    return common;
}

/// The midpoint of edge (a, b) on the walls both ends are attached to (alternating
/// projections on a corner), so a refined film still meets its walls.
Vec3 wall_midpoint(const Cluster& c, int a, int b) {
    Vec3 m = 0.5 * (c.position(a) + c.position(b));
    const std::vector<int> common = common_walls(c, a, b);
    if (common.empty()) return m;
    bool flat = true;
    for (int w : common) flat = flat && c.walls()[w]->is_flat();
    if (flat && common.size() == 1) return m; // already on the plane
    for (int pass = 0; pass < (common.size() > 1 ? 20 : 1); ++pass)
        for (int w : common) m = c.walls()[w]->project(m);
    return m;
}

} // namespace

Cluster refine(const Cluster& c) {
    // The walls stay attached as they were (a vertex that drifted off a curved wall by the
    // linearised constraint stays on it); a midpoint gets the walls its edge's ends share.
    ClusterSpec spec = cluster_spec(c);
    spec.surfaces.clear();
    // Edges shared by surfaces (triple lines) get one midpoint: keyed by the sorted pair.
    std::map<std::pair<int, int>, int> midpoint;
    std::map<std::pair<int, int>, bool> boundary;
    for (const BoundaryEdge& e : c.boundary_edges()) boundary[{std::min(e.a, e.b), std::max(e.a, e.b)}] = true;
    // In a periodic cluster the facet's corners (xa, xb) are whole: the midpoint sits in the
    // frame of the edge's lower vertex, and each facet gives it that vertex's offset.
    const auto mid = [&](int a, int b, const Vec3& xa, const Vec3& xb, const Vec3& shift_lo) {
        const std::pair<int, int> key{std::min(a, b), std::max(a, b)};
        auto [it, fresh] = midpoint.try_emplace(key, static_cast<int>(spec.vertices.size()));
        const CurvePoint *ca = c.curve_point(a), *cb = c.curve_point(b);
        if (fresh && ca && cb && ca->curve == cb->curve && c.is_wire_edge(a, b)) {
            const Curve& curve = *c.curves()[ca->curve];
            const double p = curve_midpoint(curve, *ca, *cb, c.position(a), c.position(b));
            spec.curve_points.push_back({it->second, ca->curve, p});
            spec.vertices.push_back(curve.point(p));
        } else if (fresh && boundary.count(key)) {
            for (int w : common_walls(c, a, b)) spec.attachments.push_back({it->second, w});
            spec.vertices.push_back(wall_midpoint(c, a, b));
        } else if (fresh) {
            spec.vertices.push_back(0.5 * (xa + xb) - shift_lo);
        }
        return it->second;
    };
    for (const Surface& s : c.surfaces()) {
        ClusterSpec::Surface out;
        out.sigma = s.sigma;
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const Tri& t = s.triangles[f];
            const auto x = s.corners(c.positions(), f);
            const auto shift = [&](int a) { return s.shifts.empty() ? Vec3::Zero().eval() : s.shifts[f][a]; };
            const auto m = [&](int a, int b) { // the midpoint of corners a, b and its offset
                const int lo = t[a] < t[b] ? a : b;
                return std::pair{mid(t[a], t[b], x[a], x[b], shift(lo)), lo};
            };
            const auto [m01, l01] = m(0, 1);
            const auto [m12, l12] = m(1, 2);
            const auto [m20, l20] = m(2, 0);
            out.triangles.push_back({t[0], m01, m20});
            out.triangles.push_back({m01, t[1], m12});
            out.triangles.push_back({m20, m12, t[2]});
            out.triangles.push_back({m01, m12, m20});
            if (s.offsets.empty()) continue;
            const auto& k = s.offsets[f];
            out.offsets.push_back({k[0], k[l01], k[l20]});
            out.offsets.push_back({k[l01], k[1], k[l12]});
            out.offsets.push_back({k[l20], k[l12], k[2]});
            out.offsets.push_back({k[l01], k[l12], k[l20]});
        }
        spec.surfaces.push_back(std::move(out));
    }
    // A midpoint is fixed where the edge is part of a fixed frame: a wire, or an edge whose
    // facets are all fixed (a held face). An edge across a film between two fixed vertices
    // (a catenoid's seam from ring to ring) gets a free midpoint, as Evolver's unfixed edges do.
    std::map<std::pair<int, int>, bool> on_free_facet;
    for (const Surface& s : c.surfaces())
        for (const Tri& t : s.triangles) {
            const bool free = !(c.is_fixed(t[0]) && c.is_fixed(t[1]) && c.is_fixed(t[2]));
            for (int k = 0; k < 3; ++k) {
                const int a = t[k], b = t[(k + 1) % 3];
                on_free_facet[{std::min(a, b), std::max(a, b)}] |= free;
            }
        }
    for (const auto& [ends, m] : midpoint)
        if (c.is_fixed(ends.first) && c.is_fixed(ends.second) &&
            (c.is_wire_edge(ends.first, ends.second) || !on_free_facet[ends]))
            spec.fixed.push_back(m);
    Cluster r(std::move(spec));
    if (r.n_bodies() != c.n_bodies())
        throw TopologyError("refine: the refined cluster has " + std::to_string(r.n_bodies()) +
                            " bodies, the original " + std::to_string(c.n_bodies()));
    carry_over(c, r);
    return r;
}

} // namespace froth
