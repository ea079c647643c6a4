// Mesh upkeep (transitions.h, collapse_short_edges): Evolver's `t`, the collapse of edges
// too short for the flow to go on, without changing the cluster's topology.
//
// An edge (a, b) collapses onto one vertex: the one of higher rank (a film's interior < a
// triple line < a quadruple point) keeps its place, two of equal rank meet at the midpoint.
// Only collapses that keep every junction are made: an edge inside a film whose ends are
// both on junctions would join two lines, and an edge between two quadruple points is a T1's
// business. The two (or three, along a triple line) facets at the edge go; the others at the
// removed vertex take the kept one. The link condition (the ends' common neighbours are
// exactly the corners opposite the edge) keeps every film a manifold, and a collapse that
// would turn a facet over or take a film's last facet is not made. Collapses of one pass
// touch disjoint neighbourhoods, so each is checked against the geometry before the pass.
#include "mesh/transitions.h"

#include "core/errors.h"
#include "mesh/transition_surgery.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace froth {
namespace {

struct Candidate {
    double length;
    int a, b;       // a < b
    int keep = -1;  // the end that keeps its place, if not the one of higher rank
};

class Collapser {
  public:
    Collapser(const Cluster& c, EdgeCollapseCriteria criteria) : c_(c), criteria_(criteria) {}
    /// One pass; the number of edges collapsed (0: the spec is not needed).
    int pass();
    ClusterSpec& spec() { return spec_; }
    const std::vector<Vec3>& positions() const { return X_; }

  private:
    std::vector<Candidate> candidates() const;
    void hairpin_sides(const Tri& t, const std::array<Vec3, 3>& x, const std::vector<int>& thin,
                       std::vector<Candidate>& out) const;
    void corner_lines(int a, int b, double length, std::vector<Candidate>& out) const;
    /// What a collapse changes in spec_: facets that take the kept vertex, facets that go.
    struct Plan {
        struct Change {
            int surface, facet, corner;
        };
        std::vector<Change> changes;
        std::vector<std::array<int, 2>> dropped;
    };
    bool collapse(const Candidate& e);
    bool plan(int keep, int gone, const Vec3& target, Plan& out) const;
    void apply(int keep, int gone, const Vec3& target, const Plan& p);
    bool link_condition(int a, int b) const;

    const Cluster& c_;
    const EdgeCollapseCriteria criteria_;
    ClusterSpec spec_;
    std::vector<Vec3> X_;
    std::vector<int> rank_;
    std::vector<std::set<int>> neighbours_;
    std::vector<std::vector<std::pair<int, int>>> facets_at_; // (surface, facet) per vertex
    std::set<std::pair<int, int>> junction_;                  // junction edges (a < b)
    std::vector<char> touched_;
    std::vector<std::array<int, 2>> removed_facets_;          // (surface, facet) to drop
    std::vector<int> facets_left_;                            // per surface, after the drops
};

/// The sides k (corners k, k + 1) of the triangle x to collapse if one of its corners is below
/// `angle` degrees (none else): a needle's shortest side; for a flat cap (two corners below
/// `angle`) both sides from its flat corner, the shorter first (the flips' business inside a
/// film, but not where the long side is a triple line; the shorter side may join two lines,
/// which no collapse may, while the other runs along a line to a quadruple point).
std::vector<int> thin_facet_sides(const std::array<Vec3, 3>& x, double angle) {
    std::array<double, 3> l, a;
    for (int k = 0; k < 3; ++k) {
        l[k] = (x[(k + 1) % 3] - x[k]).norm();
        const Vec3 u = x[(k + 1) % 3] - x[k], w = x[(k + 2) % 3] - x[k];
        a[k] = std::atan2(u.cross(w).norm(), u.dot(w)) * 180.0 / M_PI;
    }
    const int thin = std::count_if(a.begin(), a.end(), [&](double d) { return d < angle; });
    if (thin == 0) return {};
    std::array<int, 3> by_length{0, 1, 2};
    std::sort(by_length.begin(), by_length.end(), [&](int i, int j) { return l[i] < l[j]; });
    if (thin == 1) return {by_length[0]};
    return {by_length[0], by_length[1]};
}

std::vector<Candidate> Collapser::candidates() const {
    std::map<std::pair<int, int>, double> length;
    std::vector<Candidate> hairpins;
    for (int si = 0; si < c_.n_surfaces(); ++si) {
        const Surface& s = c_.surface(si);
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const auto x = s.corners(c_.positions(), f);
            const std::vector<int> thin = criteria_.needle_angle > 0
                                              ? thin_facet_sides(x, criteria_.needle_angle)
                                              : std::vector<int>{};
            hairpin_sides(s.triangles[f], x, thin, hairpins);
            for (int k = 0; k < 3; ++k) {
                const double l = (x[(k + 1) % 3] - x[k]).norm();
                if (l < criteria_.min_length || std::find(thin.begin(), thin.end(), k) != thin.end())
                    length[std::minmax(s.triangles[f][k], s.triangles[f][(k + 1) % 3])] = l;
            }
        }
    }
    std::vector<Candidate> out = std::move(hairpins);
    for (const auto& [e, l] : length) {
        out.push_back({l, e.first, e.second});
        corner_lines(e.first, e.second, l, out);
    }
    if (criteria_.valence_three) // onto the neighbour of highest rank, which stays; first
        for (int v = 0; v < c_.n_vertices(); ++v)
            if (rank_[v] == 0 && neighbours_[v].size() == 3) {
                const auto& n = neighbours_[v];
                const int w = *std::max_element(n.begin(), n.end(), [&](int x, int y) {
                    return rank_[x] < rank_[y];
                });
                if (rank_[w] >= 0) out.push_back({0, std::min(v, w), std::max(v, w), w});
            }
    std::sort(out.begin(), out.end(), [](const Candidate& x, const Candidate& y) {
        return x.length < y.length;
    });
    return out;
}

/// A needle of facet t (corners x) whose tip is a triple line's vertex between two of the
/// line's edges (its two sides from the tip), so that the line doubles back on itself there:
/// its shortest side joins two junction vertices across a film and cannot collapse, but the
/// tip can go onto either end along the line (the nearer first), which keeps its place. The
/// 1000-cell foam's minimize stopped on such a hairpin (0.19 degrees at the tip, the line's
/// ends 6e-4 apart beside a quadruple point), which nothing else could collapse or relax.
void Collapser::hairpin_sides(const Tri& t, const std::array<Vec3, 3>& x,
                              const std::vector<int>& thin, std::vector<Candidate>& out) const {
    if (thin.size() != 1) return;
    const int k = (thin[0] + 2) % 3; // the corner opposite the shortest side
    const int tip = t[k], p = t[(k + 1) % 3], q = t[(k + 2) % 3];
    if (rank_[tip] != 1 || rank_[p] <= 0 || rank_[q] <= 0 || junction_.count(std::minmax(p, q)) ||
        !junction_.count(std::minmax(tip, p)) || !junction_.count(std::minmax(tip, q)))
        return;
    for (int j : {(k + 1) % 3, (k + 2) % 3}) {
        const auto [a, b] = std::minmax(tip, t[j]);
        out.push_back({(x[j] - x[k]).norm(), a, b, t[j]});
    }
}

/// A short edge (a, b) across a film between two triple lines that leave one quadruple point q
/// (a film's corner squeezed at q) cannot collapse, but the lines' first edges (a, q) and
/// (b, q) can: they go onto q, and the corner's facet grows to the lines' next vertices.
void Collapser::corner_lines(int a, int b, double length, std::vector<Candidate>& out) const {
    if (rank_[a] != 1 || rank_[b] != 1 || junction_.count({a, b})) return;
    for (int q : neighbours_[a])
        if (rank_[q] == 2 && neighbours_[b].count(q) && junction_.count(std::minmax(a, q)) &&
            junction_.count(std::minmax(b, q)))
            for (int v : {a, b}) out.push_back({length, std::min(v, q), std::max(v, q)});
}

/// The common neighbours of a and b are exactly the corners opposite the edge.
bool Collapser::link_condition(int a, int b) const {
    std::set<int> opposite;
    for (const auto& [si, f] : facets_at_[a]) {
        const Tri& t = spec_.surfaces[si].triangles[f];
        if (std::find(t.begin(), t.end(), b) == t.end()) continue;
        for (int v : t)
            if (v != a && v != b) opposite.insert(v);
    }
    std::set<int> common;
    std::set_intersection(neighbours_[a].begin(), neighbours_[a].end(), neighbours_[b].begin(),
                          neighbours_[b].end(), std::inserter(common, common.begin()));
    return common == opposite;
}

/// The collapse of `gone` onto `keep`, which moves to `target`: the facets that take keep
/// and those that go; false if a facet at either end would turn over or flatten.
bool Collapser::plan(int keep, int gone, const Vec3& target, Plan& out) const {
    out = {};
    const Vec3 shift = c_.edge_shift(keep, gone); // gone's image next to keep
    for (int v : {keep, gone})
        for (const auto& [si, f] : facets_at_[v]) {
            const Tri& t = spec_.surfaces[si].triangles[f];
            const bool both = std::find(t.begin(), t.end(), keep) != t.end() &&
                              std::find(t.begin(), t.end(), gone) != t.end();
            if (both) {
                if (v == keep) out.dropped.push_back({si, f});
                continue;
            }
            const auto x = c_.surface(si).corners(X_, f);
            const Vec3 before = (x[1] - x[0]).cross(x[2] - x[0]);
            const int k = static_cast<int>(std::find(t.begin(), t.end(), v) - t.begin());
            std::array<Vec3, 3> y = x;
            y[k] = target + (x[k] - X_[v]) - (v == gone ? shift : Vec3::Zero());
            if (!surgery::keeps_its_side(before, y)) return false;
            if (v == gone) out.changes.push_back({si, f, k});
        }
    return true;
}

bool Collapser::collapse(const Candidate& e) {
    const int ra = rank_[e.a], rb = rank_[e.b];
    if (ra < 0 || rb < 0 || touched_[e.a] || touched_[e.b]) return false;
    const bool along_line = junction_.count({e.a, e.b}) > 0;
    if (along_line ? (ra == 2 && rb == 2) : (ra > 0 && rb > 0)) return false;
    if (!link_condition(e.a, e.b)) return false;
    // keep the vertex of higher rank (or the candidate's); equal ranks meet halfway, or where
    // the midpoint would turn a facet over, at either end
    std::vector<std::pair<int, Vec3>> options; // (keep, its place after)
    if (e.keep >= 0 || ra != rb) {
        const int keep = e.keep >= 0 ? e.keep : ra > rb ? e.a : e.b;
        options.push_back({keep, X_[keep]});
    } else {
        options = {{e.a, 0.5 * (X_[e.a] + X_[e.b] + c_.edge_shift(e.a, e.b))},
                   {e.a, X_[e.a]},
                   {e.b, X_[e.b]}};
    }
    Plan plan_made;
    for (const auto& [keep, target] : options) {
        const int gone = keep == e.a ? e.b : e.a;
        if (!plan(keep, gone, target, plan_made)) continue;
        // a film of one facet along the edge would vanish: that is a change of topology
        for (const auto& [si, f] : plan_made.dropped)
            if (facets_left_[si] <= 1) return false;
        apply(keep, gone, target, plan_made);
        return true;
    }
    return false;
}

/// Makes the planned collapse in spec_ and X_, and marks both ends' neighbourhoods touched.
void Collapser::apply(int keep, int gone, const Vec3& target, const Plan& p) {
    const Offset d = surgery::lattice_offset(c_, X_[gone] + c_.edge_shift(keep, gone), X_[gone]);
    for (const auto& [si, f] : p.dropped) --facets_left_[si];
    for (const Plan::Change& ch : p.changes) {
        spec_.surfaces[ch.surface].triangles[ch.facet][ch.corner] = keep;
        if (!spec_.surfaces[ch.surface].offsets.empty())
            for (int x = 0; x < 3; ++x)
                spec_.surfaces[ch.surface].offsets[ch.facet][ch.corner][x] -= d[x];
    }
    removed_facets_.insert(removed_facets_.end(), p.dropped.begin(), p.dropped.end());
    X_[keep] = target;
    for (int v : {keep, gone}) {
        touched_[v] = 1;
        for (int w : neighbours_[v]) touched_[w] = 1;
    }
}

int Collapser::pass() {
    spec_ = cluster_spec(c_);
    X_ = c_.positions();
    rank_ = surgery::vertex_ranks(c_);
    neighbours_.assign(c_.n_vertices(), {});
    facets_at_.assign(c_.n_vertices(), {});
    touched_.assign(c_.n_vertices(), 0);
    facets_left_.assign(c_.n_surfaces(), 0);
    for (int si = 0; si < c_.n_surfaces(); ++si) {
        facets_left_[si] = static_cast<int>(c_.surface(si).triangles.size());
        const auto& tris = c_.surface(si).triangles;
        for (int f = 0; f < static_cast<int>(tris.size()); ++f)
            for (int k = 0; k < 3; ++k) {
                facets_at_[tris[f][k]].push_back({si, f});
                neighbours_[tris[f][k]].insert(tris[f][(k + 1) % 3]);
                neighbours_[tris[f][k]].insert(tris[f][(k + 2) % 3]);
            }
    }
    for (const JunctionEdge& e : c_.junction_edges()) junction_.insert(std::minmax(e.a, e.b));
    // lines of three edges (closed) cannot lose one
    for (const TripleLine& line : c_.triple_lines())
        if (line.closed && line.vertices.size() <= 3)
            for (int v : line.vertices) rank_[v] = -1;
    int made = 0;
    for (const Candidate& e : candidates()) made += collapse(e);
    if (!made) return 0;
    std::sort(removed_facets_.begin(), removed_facets_.end());
    for (auto it = removed_facets_.rbegin(); it != removed_facets_.rend(); ++it) {
        auto& s = spec_.surfaces[(*it)[0]];
        s.triangles.erase(s.triangles.begin() + (*it)[1]);
        if (!s.offsets.empty()) s.offsets.erase(s.offsets.begin() + (*it)[1]);
    }
    return made;
}

} // namespace

EdgeCollapseResult collapse_edges(const Cluster& c, const EdgeCollapseCriteria& criteria) {
    EdgeCollapseResult r;
    Collapser collapser(c, criteria);
    r.collapsed = collapser.pass();
    if (r.collapsed == 0) {
        if (criteria.min_length <= 0) return r;
        r = zip_squeezed_corner(c, criteria.min_length);
        return r.cluster || !criteria.slits ? std::move(r) : zip_slit(c, criteria.min_length);
    }
    ClusterSpec& spec = collapser.spec();
    const std::vector<int> used = surgery::keep_used_vertices(spec, collapser.positions());
    surgery::copy_vertex_lists(c, [&](int v) { return used[v]; }, spec);
    r.cluster.emplace(surgery::rebuild(std::move(spec), "collapse_short_edges",
                                       "the collapses"));
    carry_over(c, *r.cluster);
    return r;
}

EdgeCollapseResult collapse_short_edges(const Cluster& c, double min_length) {
    return collapse_edges(c, {min_length});
}

} // namespace froth
