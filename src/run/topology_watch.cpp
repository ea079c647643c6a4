#include "run/topology_watch.h"

#include "checks/self_intersection.h"
#include "core/format.h"
#include "geometry/geometry.h"

#include <algorithm>
#include <cmath>

namespace froth {
namespace {

std::string at_time(const Cluster& c) { return " at t = " + fmt(c.time()); }

std::optional<TopologyEvent> vanishing_body(const Cluster& c, double fraction) {
    const std::vector<double> V = body_volumes(c);
    for (std::size_t b = 0; b < V.size(); ++b) {
        const double v0 = c.initial_volumes()[b];
        if (V[b] < fraction * v0)
            return TopologyEvent{"vanishing body",
                                 "body " + std::to_string(b + 1) + " is vanishing: volume " +
                                     fmt(V[b]) + " of initially " + fmt(v0) + at_time(c),
                                 c.time(), static_cast<int>(b)};
    }
    return std::nullopt;
}

std::optional<TopologyEvent> collapsing_edge_or_facet(const Cluster& c, const WatchOptions& o) {
    const auto& X = c.positions();
    // The facet angle furthest below its surface's limit, as angle / limit.
    double sum = 0, shortest = INFINITY, angle_ratio = INFINITY, smallest_angle = 180;
    long count = 0;
    int s_edge = 0, f_edge = 0, s_angle = 0, f_angle = 0;
    for (int i = 0; i < c.n_surfaces(); ++i) {
        const Surface& s = c.surface(i);
        const double limit = s.gamma && s.gamma->nearly_crystalline() ? 0.1 * o.min_facet_angle
                                                                      : o.min_facet_angle;
        const auto& tris = s.triangles;
        for (int f = 0; f < static_cast<int>(tris.size()); ++f)
            for (int k = 0; k < 3; ++k) {
                const auto x = s.corners(X, f);
                const Vec3 u = x[(k + 1) % 3] - x[k];
                const Vec3 w = x[(k + 2) % 3] - x[k];
                const double len = u.norm();
                sum += len, ++count;
                if (len < shortest) shortest = len, s_edge = i, f_edge = f;
                const double angle = std::atan2(u.cross(w).norm(), u.dot(w)) * 180.0 / M_PI;
                if (angle / limit < angle_ratio)
                    angle_ratio = angle / limit, smallest_angle = angle, s_angle = i, f_angle = f;
            }
    }
    auto facet = [](int s, int f) {
        return "facet " + std::to_string(f + 1) + " of surface " + std::to_string(s + 1);
    };
    const double mean = sum / count;
    if (shortest < o.min_edge_fraction * mean)
        return TopologyEvent{"collapsing edge",
                             "an edge of " + facet(s_edge, f_edge) + " is collapsing: length " +
                                 fmt(shortest) + ", mean edge " + fmt(mean) + at_time(c),
                             c.time()};
    if (angle_ratio < 1)
        return TopologyEvent{"collapsing facet",
                             facet(s_angle, f_angle) + " is collapsing: corner angle " +
                                 fmt(smallest_angle) + " degrees" + at_time(c),
                             c.time()};
    return std::nullopt;
}

} // namespace

EdgeLengths edge_lengths(const Cluster& c) {
    double sum = 0, longest = 0;
    long count = 0;
    for (const Surface& s : c.surfaces())
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const auto x = s.corners(c.positions(), f);
            for (int k = 0; k < 3; ++k) {
                const double l = (x[(k + 1) % 3] - x[k]).norm();
                sum += l, longest = std::max(longest, l);
            }
            count += 3;
        }
    return {count ? sum / count : 0, longest};
}

double mean_edge_length(const Cluster& c) { return edge_lengths(c).mean; }

std::optional<int> shrinking_triple_line(const Cluster& c, double limit,
                                         const std::vector<int>& skip) {
    if (c.quadruple_points().size() < 2) return std::nullopt;
    const auto quadruple = [&](int v) { return c.vertex_junction_edges(v).size() == 4; };
    std::optional<int> shortest;
    double best = limit;
    const auto& lines = c.triple_lines();
    for (int l = 0; l < static_cast<int>(lines.size()); ++l) {
        const TripleLine& tl = lines[l];
        if (tl.closed || tl.vertices.front() == tl.vertices.back() ||
            !quadruple(tl.vertices.front()) || !quadruple(tl.vertices.back()))
            continue;
        if (std::find(skip.begin(), skip.end(), l) != skip.end()) continue;
        double length = 0;
        for (std::size_t i = 1; i < tl.vertices.size() && length < best; ++i) {
            const int a = tl.vertices[i - 1], b = tl.vertices[i];
            length += (c.position(b) - c.position(a) + c.edge_shift(a, b)).norm();
        }
        if (length < best) best = length, shortest = l;
    }
    return shortest;
}

bool TopologyWatch::tests_crossings(int step) const {
    const int every = options_.self_intersection_every;
    return options_.enabled && every > 0 && step % every == 0 && self_intersection_available();
}

std::optional<TopologyEvent> TopologyWatch::check(const Cluster& c, int step) const {
    if (!options_.enabled) return std::nullopt;
    if (auto e = vanishing_body(c, options_.min_volume_fraction)) return e;
    if (auto e = collapsing_edge_or_facet(c, options_)) return e;
    if (tests_crossings(step)) {
        const auto crossings = find_self_intersections(c, 1);
        if (!crossings.empty()) {
            const FacetCrossing& x = crossings.front();
            auto facet = [](const FacetRef& r) {
                return "facet " + std::to_string(r.facet + 1) + " of surface " +
                       std::to_string(r.surface + 1);
            };
            return TopologyEvent{"self-intersection",
                                 facet(x.a) + " crosses " + facet(x.b) + at_time(c), c.time()};
        }
    }
    return std::nullopt;
}

} // namespace froth
