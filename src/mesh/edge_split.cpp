// Mesh upkeep (transitions.h, split_long_edges): Evolver's `l`, the split of edges that a
// growing film has stretched, without changing the cluster's topology; and
// split_films_emptied_by_t1 and split_films_emptied_by_collapse, the same splits on the sides
// of a film that a T1 or a film's collapse would leave without a facet.
//
// An edge (a, b) gets its midpoint m; each facet (a, b, q) at it (two inside a film, three
// along a triple line) becomes (a, m, q) and (m, b, q) in the same orientation, so the
// films, their junctions and the bodies' volumes are kept (m lies on the straight edge). The
// splits of one pass touch disjoint facets. Edges on walls and wires are left (their
// midpoints would have to be projected, as refine does).
#include "mesh/transitions.h"

#include "core/errors.h"
#include "mesh/transition_surgery.h"

#include <algorithm>
#include <functional>
#include <map>
#include <set>

namespace froth {

namespace {

using EdgeKey = std::pair<int, int>;

/// The splits of the edges for which split(a, b, length) is true (a < b), longest first, each
/// at the fraction `at` of its length from a (the midpoint by default).
EdgeSplitResult split_edges_where(const Cluster& c,
                                  const std::function<bool(int, int, double)>& split_it,
                                  double at = 0.5) {
    EdgeSplitResult r;
    // the edges to split, with their lengths and the facets at each
    std::map<EdgeKey, std::pair<double, std::vector<std::array<int, 2>>>> edges;
    for (int si = 0; si < c.n_surfaces(); ++si) {
        const Surface& s = c.surface(si);
        for (int f = 0; f < static_cast<int>(s.triangles.size()); ++f) {
            const auto x = s.corners(c.positions(), f);
            for (int k = 0; k < 3; ++k) {
                const double l = (x[(k + 1) % 3] - x[k]).norm();
                const auto key = std::minmax(s.triangles[f][k], s.triangles[f][(k + 1) % 3]);
                if (split_it(key.first, key.second, l))
                    edges[key].first = l, edges[key].second.push_back({si, f});
            }
        }
    }
    if (edges.empty()) return r;
    std::set<std::pair<int, int>> held;
    for (const BoundaryEdge& e : c.boundary_edges()) held.insert(std::minmax(e.a, e.b));
    for (const BoundaryEdge& e : c.wire_edges()) held.insert(std::minmax(e.a, e.b));
    std::vector<std::pair<double, std::pair<int, int>>> order;
    for (const auto& [e, lf] : edges)
        if (!held.count(e)) order.push_back({-lf.first, e});
    std::sort(order.begin(), order.end());

    ClusterSpec spec = cluster_spec(c);
    std::vector<Vec3> V = c.positions();
    std::set<std::array<int, 2>> touched;
    std::vector<std::vector<char>> split(c.n_surfaces()); // facets replaced by two new ones
    for (int si = 0; si < c.n_surfaces(); ++si) split[si].assign(c.surface(si).triangles.size(), 0);
    for (const auto& [negative_length, e] : order) {
        const auto& facets = edges[e].second;
        if (std::any_of(facets.begin(), facets.end(), [&](const auto& f) { return touched.count(f); }))
            continue;
        const auto [a, b] = e;
        const int m = static_cast<int>(V.size());
        V.push_back(c.position(a) + at * (c.position(b) - c.position(a) + c.edge_shift(a, b)));
        for (const auto& [si, f] : facets) {
            touched.insert({si, f});
            auto& s = spec.surfaces[si];
            const Tri t = s.triangles[f];
            int i = 0; // the edge is t[i] -> t[i + 1]
            while (!((t[i] == a && t[(i + 1) % 3] == b) || (t[i] == b && t[(i + 1) % 3] == a))) ++i;
            const int x0 = t[i], x1 = t[(i + 1) % 3], x2 = t[(i + 2) % 3];
            s.triangles.push_back({x0, m, x2});
            s.triangles.push_back({m, x1, x2});
            if (!s.offsets.empty()) {
                const auto k = s.offsets[f];
                const Offset km = x0 == a ? k[i] : k[(i + 1) % 3]; // m is in a's frame
                s.offsets.push_back({k[i], km, k[(i + 2) % 3]});
                s.offsets.push_back({km, k[(i + 1) % 3], k[(i + 2) % 3]});
            }
            split[si][f] = 1;
        }
        ++r.split;
    }
    for (int si = 0; si < c.n_surfaces(); ++si) {
        auto& s = spec.surfaces[si];
        std::size_t kept = 0;
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            if (f < split[si].size() && split[si][f]) continue;
            s.triangles[kept] = s.triangles[f];
            if (!s.offsets.empty()) s.offsets[kept] = s.offsets[f];
            ++kept;
        }
        s.triangles.resize(kept);
        if (!s.offsets.empty()) s.offsets.resize(kept);
    }
    const std::vector<int> used = surgery::keep_used_vertices(spec, V);
    surgery::copy_vertex_lists(c, [&](int v) { return used[v]; }, spec);
    r.cluster.emplace(surgery::rebuild(std::move(spec), "split_long_edges", "the splits"));
    carry_over(c, *r.cluster);
    return r;
}

/// A line film whose line collapses to a point folds over it where a vertex w off the line
/// follows (or precedes) the point in two of the fans' facets: w is joined to two line
/// vertices, and its facets between them do not reach the line (the 200-grain network's stop
/// at t = 1.540: w joined to both ends of a line of two edges, the vertex beside w joined to
/// all three, so that after the collapse the two would share two facets of opposite sides).
/// The edges from such a w to the line are added to `sides`: their midpoints part the fan.
void part_folds(const std::vector<Tri>& tris, const std::set<int>& on_line,
                std::set<EdgeKey>& sides) {
    std::map<int, int> starts, ends; // the link's edges (x, y) around the collapsed point
    std::vector<std::pair<int, int>> touching; // (line vertex, w) of the one-corner facets
    for (const Tri& t : tris) {
        const int on = static_cast<int>(
            std::count_if(t.begin(), t.end(), [&](int v) { return on_line.count(v) > 0; }));
        if (on != 1) continue;
        int j = 0;
        while (!on_line.count(t[j])) ++j;
        ++starts[t[(j + 1) % 3]], ++ends[t[(j + 2) % 3]];
        touching.push_back({t[j], t[(j + 1) % 3]});
        touching.push_back({t[j], t[(j + 2) % 3]});
    }
    for (const auto& [v, w] : touching)
        if (starts[w] > 1 || ends[w] > 1) sides.insert(std::minmax(v, w));
}

/// Adds to `sides` the other edges of the films among `films` whose every facet has two
/// corners in `collapsing`: a collapse of those vertices to one point leaves such a film (a
/// triangle of one facet on the collapsing line, say) without a facet.
void add_sides_of_emptied_films(const Cluster& c, const std::set<int>& collapsing,
                                const std::vector<int>& films, std::set<EdgeKey>& sides) {
    const auto corners_collapsing = [&](const Tri& t) {
        return std::count_if(t.begin(), t.end(), [&](int v) { return collapsing.count(v) > 0; });
    };
    for (int si : films) {
        const auto& tris = c.surface(si).triangles;
        const bool emptied = std::all_of(tris.begin(), tris.end(),
                                         [&](const Tri& t) { return corners_collapsing(t) >= 2; });
        if (!emptied) continue;
        for (const Tri& t : tris)
            for (int k = 0; k < 3; ++k)
                if (!collapsing.count(t[k]) || !collapsing.count(t[(k + 1) % 3]))
                    sides.insert(std::minmax(t[k], t[(k + 1) % 3]));
    }
}

/// The edges `sides` split at their midpoints: one pass splits an edge per facet, so a
/// facet's two sides take two passes, and facets that share edges to split may take more
/// (a split edge is gone, so each pass splits one or ends). None if no edge could be split.
std::optional<Cluster> split_sides(const Cluster& c, const std::set<EdgeKey>& sides) {
    std::optional<Cluster> out;
    for (std::size_t pass = 0; pass < sides.size(); ++pass) {
        const Cluster& from = out ? *out : c;
        EdgeSplitResult r = split_edges_where(from, [&](int a, int b, double) {
            return sides.count({a, b}) > 0;
        });
        if (!r.cluster) break;
        out = std::move(r.cluster);
    }
    return out;
}

} // namespace

namespace surgery {
Cluster split_edge(const Cluster& c, int a, int b, double t) {
    if (a > b) std::swap(a, b), t = 1 - t;
    EdgeSplitResult r = split_edges_where(c, [&](int x, int y, double) { return x == a && y == b; }, t);
    if (!r.cluster)
        throw TopologyError("split_edge: vertices " + std::to_string(a + 1) + " and " +
                            std::to_string(b + 1) + " share no edge that can be split");
    return std::move(*r.cluster);
}
} // namespace surgery

EdgeSplitResult split_long_edges(const Cluster& c, double max_length) {
    return split_edges_where(c, [&](int, int, double l) { return l > max_length; });
}

std::optional<Cluster> split_films_emptied_by_t1(const Cluster& c, int line,
                                                 bool part_common_neighbours) {
    const TripleLine& tl = c.triple_lines().at(line);
    const std::set<int> on_line(tl.vertices.begin(), tl.vertices.end());
    std::set<EdgeKey> sides; // the other edges of the films the T1 would empty
    add_sides_of_emptied_films(c, on_line, {tl.surfaces.begin(), tl.surfaces.end()}, sides);
    // a vertex w joined to a through a film of the fourth cell D there and to b through one of
    // E's: after the T1 both films would have the edge from w to a new corner, which with the
    // line's film beside it would be an edge of four films (the 200-grain network stopped so
    // at t = 0.97, w a quadruple point at the far corner of a triangle whose third side, the
    // line, was 1.3e-5 long); the edges (a, w) and (b, w) are split, and their midpoints part
    // the fans
    if (part_common_neighbours && !tl.closed) {
        const int a = tl.vertices.front(), b = tl.vertices.back();
        const std::set<int> line_films(tl.surfaces.begin(), tl.surfaces.end());
        const auto neighbours_off_line = [&](int end) {
            std::set<int> out;
            for (int si = 0; si < c.n_surfaces(); ++si) {
                if (line_films.count(si)) continue;
                for (const Tri& t : c.surface(si).triangles)
                    for (int k = 0; k < 3; ++k)
                        if (t[k] == end)
                            for (int w : {t[(k + 1) % 3], t[(k + 2) % 3]})
                                if (!on_line.count(w)) out.insert(w);
            }
            return out;
        };
        const std::set<int> at_a = neighbours_off_line(a), at_b = neighbours_off_line(b);
        for (int w : at_a)
            if (at_b.count(w)) sides.insert(std::minmax(a, w)), sides.insert(std::minmax(b, w));
        for (int si : tl.surfaces) part_folds(c.surface(si).triangles, on_line, sides);
    }
    if (sides.empty()) return std::nullopt;
    return split_sides(c, sides);
}

std::optional<Cluster> split_films_emptied_by_collapse(const Cluster& c, int film) {
    std::set<EdgeKey> sides;
    for (const TripleLine& tl : c.triple_lines()) {
        if (std::find(tl.surfaces.begin(), tl.surfaces.end(), film) == tl.surfaces.end()) continue;
        // the film itself goes; the others along this side lose the facets on it
        std::vector<int> beside;
        for (int si : tl.surfaces)
            if (si != film) beside.push_back(si);
        add_sides_of_emptied_films(c, std::set<int>(tl.vertices.begin(), tl.vertices.end()),
                                   beside, sides);
    }
    if (sides.empty()) return std::nullopt;
    return split_sides(c, sides);
}

} // namespace froth
