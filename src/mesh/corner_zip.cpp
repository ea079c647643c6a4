// Mesh upkeep (transitions.h, zip_squeezed_corner): a film's corner that two of its triple
// lines close like a zip.
//
// Film D|E has a corner at the quadruple point q, where its sides, the lines (D, E, X) and
// (D, E, Y), leave q. When the film narrows there faster than its mesh (grain networks: a
// thin triangular film whose tip retracts), the lines' first vertices a and b come together
// and the film's edge (a, b) across the corner collapses. Neither end can go onto q alone,
// since the film's facet (a, c, b) on the other side of that edge would turn over, and (a, b)
// joins two lines. Both go onto q at once: the facets with two of q, a, b go (the corner's
// facet (q, a, b), the film's facets on (a, b), the films X|D, X|E along (q, a) and Y|D, Y|E
// along (q, b)), the others take q, which keeps its place. The lines lose their first edges,
// the quadruple point moves up the film by one edge: the retreat of the corner, which a
// parametric step cannot make since it keeps every vertex on its line.
//
// zip_slit: the same corner closed over a whole edge, a slit. The first vertex a of the line
// (D, E, X) lies on the first edge (q, b) of (D, E, Y), inside it (b may be a quadruple point:
// a one-edge line), so no edge of the film is short. In cross-section the slit is a 2D
// Plateau border of vanishing length, four films at a point; what resolves it is the 2D T1
// along the slit: the lines' other cells X and Y meet there, the quadruple point moving to
// where the lines part. The edge (q, b) is split at a's foot m, and a and m go onto q at
// their midpoint: the lines (D, E, X) and (D, E, Y) lose the slit, q's two other lines, the
// sides of the film X|Y, reach along it to the new q. Repeated, this walks q up a longer slit.
#include "mesh/transitions.h"

#include "core/errors.h"
#include "mesh/transition_surgery.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace froth {
namespace {

/// Lines that leave a quadruple point this close in angle (radians, 15 degrees) run
/// together: at a Plateau point they part at 109.5 degrees.
constexpr double kTogether = 15 * M_PI / 180;

/// A quadruple point q and the first vertices of its lines that come together: each
/// joined to another by a film's edge shorter than min_length across a corner at q (a side
/// of q's facet there, or beyond film vertices next to q).
struct Squeeze {
    double length; // the shortest such edge
    int q;
    std::set<int> first; // two, or three (three lines running together from q)
};

std::vector<Squeeze> squeezed_corners(const Cluster& c, double min_length) {
    const std::vector<int> rank = surgery::vertex_ranks(c);
    std::set<std::pair<int, int>> junction;
    for (const JunctionEdge& e : c.junction_edges()) junction.insert(std::minmax(e.a, e.b));
    const auto on_line = [&](int u, int v) { return junction.count(std::minmax(u, v)) > 0; };
    // along the lines: the quadruple points next to a line vertex, and for a quadruple
    // point the first vertices of its lines (the same edges seen from either end)
    std::vector<std::vector<int>> point_of(c.n_vertices()), first_of(c.n_vertices());
    for (const JunctionEdge& e : c.junction_edges())
        for (const auto& [v, w] : {std::pair{e.a, e.b}, std::pair{e.b, e.a}})
            if (rank[v] == 1 && rank[w] == 2) point_of[v].push_back(w), first_of[w].push_back(v);
    std::map<int, Squeeze> at; // by q
    for (int si = 0; si < c.n_surfaces(); ++si) {
        const Surface& s = c.surface(si);
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const auto x = s.corners(c.positions(), f);
            for (int k = 0; k < 3; ++k) {
                const int a = s.triangles[f][k], b = s.triangles[f][(k + 1) % 3];
                const double l = (x[(k + 1) % 3] - x[k]).norm();
                if (!(l < min_length && rank[a] == 1 && rank[b] == 1 && !on_line(a, b)))
                    continue;
                // the corner's facet (q, a, b), or film vertices between a and b at q
                for (int q : point_of[a]) {
                    if (std::find(point_of[b].begin(), point_of[b].end(), q) == point_of[b].end())
                        continue;
                    Squeeze& z = at.try_emplace(q, Squeeze{l, q, {}}).first->second;
                    z.length = std::min(z.length, l);
                    z.first.insert(a), z.first.insert(b);
                }
            }
        }
    }
    // a third line that leaves q within kTogether of a squeezed one runs with them: the
    // three first vertices go together, or the zip of two would turn the facets between
    // them over
    const auto towards = [&](int q, int v) {
        return (c.position(v) + c.edge_shift(q, v) - c.position(q)).normalized();
    };
    std::vector<Squeeze> out;
    for (auto& [q, z] : at) {
        for (int w : first_of[q])
            for (int v : std::set<int>(z.first))
                if (!z.first.count(w) && towards(q, w).dot(towards(q, v)) > std::cos(kTogether))
                    z.first.insert(w);
        if (z.first.size() <= 3u) out.push_back(std::move(z));
    }
    std::sort(out.begin(), out.end(),
              [](const Squeeze& x, const Squeeze& y) { return x.length < y.length; });
    return out;
}

/// The zip of one squeeze, q at `target` (in q's frame); none if it would change the
/// topology or turn a facet over.
std::optional<Cluster> zip(const Cluster& c, const Squeeze& z, const Vec3& target) {
    const std::string what = "zip_squeezed_corner";
    std::map<int, Offset> d{{z.q, Offset{0, 0, 0}}}; // the vertices in q's frame
    std::set<int> touched = surgery::surfaces_at(c, z.q);
    for (int v : z.first) {
        d[v] = surgery::lattice_offset(c, c.position(v) + c.edge_shift(z.q, v), c.position(v));
        const std::set<int> at = surgery::surfaces_at(c, v);
        touched.insert(at.begin(), at.end());
    }
    ClusterSpec spec = cluster_spec(c);
    std::vector<surgery::MovedFacet> moved;
    try {
        for (int si : touched) surgery::collapse_onto(c, spec, si, d, z.q, moved, what);
    } catch (const TopologyError&) {
        return std::nullopt; // a film would pinch at q
    }
    for (int si : touched)
        if (spec.surfaces[si].triangles.empty()) return std::nullopt; // a film would vanish
    std::vector<Vec3> V = c.positions();
    V[z.q] = target;
    if (surgery::turns_a_facet(spec, V, moved)) return std::nullopt;
    const std::vector<int> used = surgery::keep_used_vertices(spec, V);
    surgery::copy_vertex_lists(c, [&](int v) { return used[v]; }, spec);
    std::optional<Cluster> r;
    try {
        r.emplace(surgery::rebuild(std::move(spec), what, "the zip"));
    } catch (const TopologyError&) {
        return std::nullopt;
    }
    // the same junctions: lines and quadruple points, q still one
    if (r->triple_lines().size() != c.triple_lines().size() ||
        r->quadruple_points().size() != c.quadruple_points().size() ||
        r->vertex_junction_edges(used[z.q]).size() != c.vertex_junction_edges(z.q).size())
        return std::nullopt;
    carry_over(c, *r);
    return r;
}

/// The zip of one squeeze: q keeps its place, or (three lines running together) moves to the
/// first vertices' centre, where the lines part.
std::optional<Cluster> zip(const Cluster& c, const Squeeze& z) {
    if (z.first.size() == 3u) {
        Vec3 centre = Vec3::Zero();
        for (int v : z.first) centre += c.position(v) + c.edge_shift(z.q, v);
        if (auto r = zip(c, z, centre / 3.0)) return r;
    }
    return zip(c, z, c.position(z.q));
}

/// A slit at quadruple point q: the first vertex a of one of q's lines lies `distance` from
/// the first edge (q, b) of another line of a film they share, at its point q + t (b - q).
struct Slit {
    double distance;
    int q, a, b;
    double t;
};

/// The slits narrower than min_length, narrowest first; the foot of a must lie inside
/// (q, b) (t in [0.1, 0.9]: near its ends a short edge collapses or zip_squeezed_corner
/// acts) and the lines must leave q within kTogether.
std::vector<Slit> find_slits(const Cluster& c, double min_length) {
    const std::vector<int> rank = surgery::vertex_ranks(c);
    std::vector<Slit> out;
    for (int q : c.quadruple_points()) {
        if (rank[q] != 2) continue;
        const std::vector<int> at_q = c.vertex_junction_edges(q);
        const auto other_end = [&](int e) {
            const JunctionEdge& j = c.junction_edges()[e];
            return j.a == q ? j.b : j.a;
        };
        const auto unwrapped = [&](int v) -> Vec3 { return c.position(v) + c.edge_shift(q, v); };
        for (int ea : at_q)
            for (int eb : at_q) {
                const JunctionEdge &ja = c.junction_edges()[ea], &jb = c.junction_edges()[eb];
                if (ja.line == jb.line) continue;
                const int a = other_end(ea), b = other_end(eb);
                if (rank[a] != 1 || rank[b] < 1) continue;
                const bool share_a_film = std::any_of(
                    ja.surfaces.begin(), ja.surfaces.end(), [&](int s) {
                        return std::find(jb.surfaces.begin(), jb.surfaces.end(), s) !=
                               jb.surfaces.end();
                    });
                if (!share_a_film) continue;
                const Vec3 x = c.position(q), ua = unwrapped(a) - x, ub = unwrapped(b) - x;
                const double t = ua.dot(ub) / ub.squaredNorm();
                if (!(t >= 0.1 && t <= 0.9)) continue;
                const double distance = (ua - t * ub).norm();
                if (distance < min_length &&
                    ua.normalized().dot(ub.normalized()) > std::cos(kTogether))
                    out.push_back({distance, q, a, b, t});
            }
    }
    std::sort(out.begin(), out.end(),
              [](const Slit& x, const Slit& y) { return x.distance < y.distance; });
    return out;
}

/// The zip of one slit: (q, b) split at a's foot m, a and m onto q at their midpoint, or
/// where that turns a facet over, q in its place.
std::optional<Cluster> zip(const Cluster& c, const Slit& z) {
    std::optional<Cluster> made;
    try {
        made.emplace(surgery::split_edge(c, z.q, z.b, z.t));
    } catch (const TopologyError&) {
        return std::nullopt; // an edge on a wall or wire
    }
    const Cluster& split = *made;
    const int m = c.n_vertices();
    const Squeeze squeeze{z.distance, z.q, {z.a, m}};
    const Vec3 x = split.position(z.q);
    const Vec3 part = x + 0.5 * (split.position(z.a) + split.edge_shift(z.q, z.a) +
                                 split.position(m) + split.edge_shift(z.q, m) - 2 * x);
    if (auto r = zip(split, squeeze, part)) return r;
    return zip(split, squeeze, x);
}

} // namespace

EdgeCollapseResult zip_slit(const Cluster& c, double min_length) {
    EdgeCollapseResult r;
    const std::vector<Slit> slits = find_slits(c, min_length);
    for (const Slit& z : slits)
        if ((r.cluster = zip(c, z))) {
            r.collapsed = 2;
            return r;
        }
    return r;
}

EdgeCollapseResult zip_squeezed_corner(const Cluster& c, double min_length) {
    EdgeCollapseResult r;
    const std::vector<Squeeze> corners = squeezed_corners(c, min_length);
    if (corners.empty()) return r;
    for (const Squeeze& z : corners)
        if ((r.cluster = zip(c, z))) {
            r.collapsed = static_cast<int>(z.first.size());
            return r;
        }
    // a squeezed corner's neighbours are often flat caps, which the zip would turn over:
    // the flips mend them (and keep the vertex ids)
    EquiangulateResult flipped = equiangulate(c);
    if (!flipped.cluster) return r;
    for (const Squeeze& z : corners)
        if ((r.cluster = zip(*flipped.cluster, z))) {
            r.collapsed = static_cast<int>(z.first.size());
            return r;
        }
    return r;
}

} // namespace froth
