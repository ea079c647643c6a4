#include "run/topology_watch.h"

#include "checks/self_intersection.h"
#include "core/format.h"
#include "geometry/geometry.h"
#include "mesh/transitions.h"

#include <algorithm>
#include <cmath>
#include <set>

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

/// True if the edge v -> w is a whole triple line between two quadruple points.
bool quadruple_line_edge(const Cluster& c, int v, int w) {
    const auto& at_v = c.vertex_junction_edges(v);
    if (at_v.size() != 4 || c.vertex_junction_edges(w).size() != 4) return false;
    for (int e : at_v) {
        const JunctionEdge& je = c.junction_edges()[e];
        if (je.a == w || je.b == w) return true;
    }
    return false;
}

std::optional<TopologyEvent> collapsing_edge_or_facet(const Cluster& c, const WatchOptions& o) {
    const auto& X = c.positions();
    // with transitions, a line between quadruple points is the T1's unless far shorter
    const double line_factor = o.lines_to_transitions ? 0.1 : 1;
    // The facet angle furthest below its surface's limit, as angle / limit.
    double sum = 0, shortest = INFINITY, scaled_shortest = INFINITY;
    double angle_ratio = INFINITY, smallest_angle = 180;
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
                const double scaled =
                    line_factor < 1 && quadruple_line_edge(c, tris[f][k], tris[f][(k + 1) % 3])
                        ? len / line_factor
                        : len;
                if (scaled < scaled_shortest)
                    scaled_shortest = scaled, shortest = len, s_edge = i, f_edge = f;
                // the angle at corner k faces the edge k+1 -> k+2: at a needle on a one-edge
                // line the line's T1 removes it, so the angle is judged as that edge is
                const double angle = std::atan2(u.cross(w).norm(), u.dot(w)) * 180.0 / M_PI;
                const bool at_line =
                    line_factor < 1 &&
                    quadruple_line_edge(c, tris[f][(k + 1) % 3], tris[f][(k + 2) % 3]);
                const double ratio = angle / (at_line ? line_factor : 1) / limit;
                if (ratio < angle_ratio)
                    angle_ratio = ratio, smallest_angle = angle, s_angle = i, f_angle = f;
            }
    }
    const double mean = sum / count;
    if (scaled_shortest < o.min_edge_fraction * mean)
        return TopologyEvent{"collapsing edge",
                             "an edge of " + facet_name(s_edge, f_edge) + " is collapsing: length " +
                                 fmt(shortest) + ", mean edge " + fmt(mean) + at_time(c),
                             c.time(), -1, s_edge, f_edge};
    if (angle_ratio < 1)
        return TopologyEvent{"collapsing facet",
                             facet_name(s_angle, f_angle) + " is collapsing: corner angle " +
                                 fmt(smallest_angle) + " degrees" + at_time(c),
                             c.time(), -1, s_angle, f_angle};
    return std::nullopt;
}

} // namespace

int unresolved_cell_near(const Cluster& c, int surface, int facet) {
    const auto centre = [&](int s, int f) {
        const auto x = c.surface(s).corners(c.positions(), f);
        return Vec3((x[0] + x[1] + x[2]) / 3);
    };
    const Vec3 at = centre(surface, facet);
    const double edge = mean_edge_length(c);
    const Eigen::Matrix3d to_lattice =
        c.periodic() ? Eigen::Matrix3d(c.period().inverse()) : Eigen::Matrix3d::Zero();
    const auto within = [&](int b) { // a facet centre of body b within two mean edges
        for (const BodyFace& face : c.bodies()[b].faces)
            for (int f = 0; f < static_cast<int>(c.surface(face.surface).triangles.size()); ++f) {
                Vec3 d = centre(face.surface, f) - at;
                if (c.periodic()) d -= c.period() * (to_lattice * d).array().round().matrix();
                if (d.norm() < 2 * edge) return true;
            }
        return false;
    };
    const std::vector<double> volumes = body_volumes(c);
    double mean_cell = 0;
    for (double v : volumes) mean_cell += std::abs(v) / static_cast<double>(volumes.size());
    const double unresolved = std::min(4.0 / 3.0 * M_PI * edge * edge * edge, 0.1 * mean_cell);
    int smallest = -1;
    for (int b = 0; b < c.n_bodies(); ++b)
        if (volumes[b] < unresolved && (smallest < 0 || volumes[b] < volumes[smallest]) && within(b))
            smallest = b;
    return smallest;
}

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

namespace {

bool between_quadruple_points(const Cluster& c, const TripleLine& tl) {
    const auto quadruple = [&](int v) { return c.vertex_junction_edges(v).size() == 4; };
    return !tl.closed && tl.vertices.front() != tl.vertices.back() &&
           quadruple(tl.vertices.front()) && quadruple(tl.vertices.back());
}

/// A line's length, a closed one's with its closing edge.
double line_length(const Cluster& c, const TripleLine& tl) {
    double length = 0;
    const std::size_t n = tl.vertices.size();
    for (std::size_t i = tl.closed ? 0 : 1; i < n; ++i) {
        const int a = tl.vertices[(i + n - 1) % n], b = tl.vertices[i];
        length += (c.position(b) - c.position(a) + c.edge_shift(a, b)).norm();
    }
    return length;
}

/// The cells of a triple line's films, sorted.
std::vector<int> cells_around(const std::vector<std::array<int, 2>>& cells,
                              const TripleLine& tl) {
    std::set<int> around;
    for (int s : tl.surfaces) around.insert(cells[s].begin(), cells[s].end());
    return {around.begin(), around.end()};
}

/// The cell at quadruple point q that is not one of `around` (-2 if none or several).
int fourth_cell(const Cluster& c, const std::vector<std::array<int, 2>>& cells, int q,
                const std::vector<int>& around) {
    std::set<int> at;
    for (int k = c.pair_begin(q); k < c.pair_begin(q + 1); ++k)
        for (int cell : cells[c.pair_surface(k)])
            if (std::find(around.begin(), around.end(), cell) == around.end()) at.insert(cell);
    return at.size() == 1 ? *at.begin() : -2;
}

} // namespace

std::vector<Junction> quadruple_lines(const Cluster& c) {
    std::vector<Junction> out;
    if (c.quadruple_points().size() < 2) return out;
    const auto cells = surface_cells(c);
    const auto& lines = c.triple_lines();
    for (int l = 0; l < static_cast<int>(lines.size()); ++l) {
        const TripleLine& tl = lines[l];
        if (!between_quadruple_points(c, tl)) continue;
        Junction j{l, line_length(c, tl), cells_around(cells, tl)};
        const int d = fourth_cell(c, cells, tl.vertices.front(), j.cells);
        const int e = fourth_cell(c, cells, tl.vertices.back(), j.cells);
        j.cells.push_back(std::min(d, e));
        j.cells.push_back(std::max(d, e));
        out.push_back(std::move(j));
    }
    return out;
}

std::vector<Junction> collapsible_films(const Cluster& c) {
    std::vector<Junction> out;
    if (c.quadruple_points().size() < 2) return out;
    const auto cells = surface_cells(c);
    std::vector<std::vector<int>> border(c.n_surfaces()); // each surface's triple lines
    const auto& lines = c.triple_lines();
    for (int l = 0; l < static_cast<int>(lines.size()); ++l)
        for (int s : lines[l].surfaces) border[s].push_back(l);
    for (int s = 0; s < c.n_surfaces(); ++s) {
        const std::size_t n = border[s].size();
        const bool disc = n == 1 && lines[border[s][0]].closed;
        if ((n != 2 && n != 3 && !disc) || cells[s][0] == cells[s][1]) continue;
        Junction j{s, 0, {std::min(cells[s][0], cells[s][1]), std::max(cells[s][0], cells[s][1])}};
        std::set<int> sides;
        bool ok = true;
        for (int l : border[s]) {
            ok = ok && (disc || between_quadruple_points(c, lines[l]));
            j.size += line_length(c, lines[l]);
            for (int cell : cells_around(cells, lines[l]))
                if (cell != j.cells[0] && cell != j.cells[1]) sides.insert(cell);
        }
        if (!ok || sides.size() != n) continue;
        j.cells.insert(j.cells.end(), sides.begin(), sides.end());
        double area = 0;
        for (std::size_t f = 0; f < c.surface(s).triangles.size(); ++f) {
            const auto x = c.surface(s).corners(c.positions(), f);
            area += 0.5 * (x[1] - x[0]).cross(x[2] - x[0]).norm();
        }
        j.width = 2 * area / j.size;
        out.push_back(std::move(j));
    }
    return out;
}

std::string crossing_text(const FacetCrossing& x) {
    return facet_name(x.a.surface, x.a.facet) + " crosses " + facet_name(x.b.surface, x.b.facet);
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
            return TopologyEvent{"self-intersection", crossing_text(x) + at_time(c), c.time()};
        }
    }
    return std::nullopt;
}

} // namespace froth
