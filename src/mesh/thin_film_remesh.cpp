// Mesh upkeep (transitions.h, remesh_thin_films): a film narrower than its mesh.
//
// In grain networks a film between two long, nearly parallel triple lines narrows (a strip
// 0.008 wide between lines 0.3 long, against facets of 0.15) while it keeps the film vertices
// it was meshed with. They end up within a hundredth of the mesh size of the lines, their
// facets are caps and needles, and neither collapses (a film vertex joined to a line vertex
// and to its neighbour on the line breaks the link condition) nor flips mend them. Such a
// film needs no interior vertex: its facets are replaced by a triangulation of its border
// alone, the one that maximises the smallest angle (dynamic programming over the border
// polygon, O(n^3) for n border vertices), with every facet facing the film's way. The border,
// and so every other film, line and quadruple point, stays as it is.
#include "mesh/transitions.h"

#include "core/errors.h"
#include "mesh/transition_surgery.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <vector>

namespace froth {
namespace {

/// A film's border as one loop in the film's orientation (the facets' edges that no other
/// facet of the film has), its vertices' positions unwrapped into one frame; empty if the
/// border is not one loop.
struct Border {
    std::vector<int> vertices;
    std::vector<Vec3> x;
};

Border border_loop(const Cluster& c, int si) {
    const Surface& s = c.surface(si);
    std::map<std::pair<int, int>, int> count; // undirected edge -> facets
    for (const Tri& t : s.triangles)
        for (int k = 0; k < 3; ++k) ++count[std::minmax(t[k], t[(k + 1) % 3])];
    std::map<int, int> next;
    for (const Tri& t : s.triangles)
        for (int k = 0; k < 3; ++k)
            if (count[std::minmax(t[k], t[(k + 1) % 3])] == 1)
                if (!next.emplace(t[k], t[(k + 1) % 3]).second) return {}; // pinched
    if (next.size() < 3u) return {};
    Border b;
    int v = next.begin()->first;
    Vec3 x = c.position(v);
    do {
        b.vertices.push_back(v);
        b.x.push_back(x);
        const auto w_it = next.find(v);
        if (w_it == next.end()) return {}; // an open border: not a film's
        const int w = w_it->second;
        x += c.position(w) - c.position(v) + c.edge_shift(v, w);
        v = w;
    } while (v != b.vertices.front() && b.vertices.size() <= next.size());
    if (b.vertices.size() != next.size()) return {}; // more than one loop
    return b;
}

double smallest_angle(const Vec3& a, const Vec3& b, const Vec3& c) {
    const auto at = [](const Vec3& p, const Vec3& q, const Vec3& r) {
        const Vec3 u = q - p, w = r - p;
        return std::atan2(u.cross(w).norm(), u.dot(w));
    };
    return std::min({at(a, b, c), at(b, c, a), at(c, a, b)});
}

/// The triangulation of the loop that maximises its smallest angle among those whose
/// triangles face `normal` (triples of loop indices in the loop's orientation); empty if
/// there is none.
std::vector<std::array<int, 3>> best_triangulation(const std::vector<Vec3>& x,
                                                   const Vec3& normal) {
    const int n = static_cast<int>(x.size());
    // q[i][j]: the best smallest angle of the polygon i..j (j > i + 1); -1 none
    std::vector<std::vector<double>> q(n, std::vector<double>(n, -1));
    std::vector<std::vector<int>> split(n, std::vector<int>(n, -1));
    for (int i = 0; i + 1 < n; ++i) q[i][i + 1] = M_PI; // an edge: no triangle yet
    for (int len = 2; len < n; ++len)
        for (int i = 0; i + len < n; ++i) {
            const int j = i + len;
            for (int k = i + 1; k < j; ++k) {
                if (q[i][k] < 0 || q[k][j] < 0) continue;
                if ((x[k] - x[i]).cross(x[j] - x[i]).dot(normal) <= 0) continue;
                const double v = std::min({q[i][k], q[k][j], smallest_angle(x[i], x[k], x[j])});
                if (v > q[i][j]) q[i][j] = v, split[i][j] = k;
            }
        }
    if (q[0][n - 1] <= 0) return {};
    std::vector<std::array<int, 3>> out;
    std::vector<std::pair<int, int>> todo{{0, n - 1}};
    while (!todo.empty()) {
        const auto [i, j] = todo.back();
        todo.pop_back();
        if (j - i < 2) continue;
        const int k = split[i][j];
        out.push_back({i, k, j});
        todo.push_back({i, k}), todo.push_back({k, j});
    }
    return out;
}

/// Surface si's facets replaced by a triangulation of its border (into spec), or false if
/// the film is not one to remesh.
bool remesh_film(const Cluster& c, int si, const std::vector<int>& rank, double max_width,
                 ClusterSpec& spec) {
    const Surface& s = c.surface(si);
    const Border b = border_loop(c, si);
    if (b.vertices.empty()) return false;
    std::set<int> inside;
    for (const Tri& t : s.triangles) inside.insert(t.begin(), t.end());
    for (int v : b.vertices) inside.erase(v);
    if (inside.empty()) return false; // nothing to remove
    for (int v : inside)
        if (rank[v] != 0) return false; // held vertices, or junctions inside
    for (int v : b.vertices)
        if (rank[v] < 1) return false; // a border on a wall, or held
    double area = 0, perimeter = 0;
    Vec3 normal = Vec3::Zero();
    for (std::size_t f = 0; f < s.triangles.size(); ++f) {
        const auto x = s.corners(c.positions(), f);
        const Vec3 a = (x[1] - x[0]).cross(x[2] - x[0]);
        area += 0.5 * a.norm(), normal += a;
    }
    const int n = static_cast<int>(b.vertices.size());
    for (int i = 0; i < n; ++i) perimeter += (b.x[(i + 1) % n] - b.x[i]).norm();
    if (!(2 * area / perimeter < max_width)) return false;
    const std::vector<std::array<int, 3>> tris = best_triangulation(b.x, normal);
    if (tris.empty()) return false;
    ClusterSpec::Surface out;
    out.sigma = spec.surfaces[si].sigma;
    for (const auto& t : tris) {
        out.triangles.push_back({b.vertices[t[0]], b.vertices[t[1]], b.vertices[t[2]]});
        if (spec.period) {
            std::array<Offset, 3> k;
            for (int j = 0; j < 3; ++j)
                k[j] = surgery::lattice_offset(c, b.x[t[j]], c.position(b.vertices[t[j]]));
            out.offsets.push_back(k);
        }
    }
    spec.surfaces[si] = std::move(out);
    return true;
}

} // namespace

EdgeCollapseResult remesh_thin_films(const Cluster& c, double max_width) {
    EdgeCollapseResult r;
    const std::vector<int> rank = surgery::vertex_ranks(c);
    ClusterSpec spec = cluster_spec(c);
    const int before = c.n_vertices();
    int films = 0;
    for (int si = 0; si < c.n_surfaces(); ++si) films += remesh_film(c, si, rank, max_width, spec);
    if (films == 0) return r;
    const std::vector<int> used = surgery::keep_used_vertices(spec, c.positions());
    surgery::copy_vertex_lists(c, [&](int v) { return used[v]; }, spec);
    try {
        r.cluster.emplace(surgery::rebuild(std::move(spec), "remesh_thin_films", "the remesh"));
    } catch (const TopologyError&) {
        return {};
    }
    if (r.cluster->triple_lines().size() != c.triple_lines().size() ||
        r.cluster->quadruple_points().size() != c.quadruple_points().size())
        return {};
    carry_over(c, *r.cluster);
    r.collapsed = before - r.cluster->n_vertices();
    return r;
}

} // namespace froth
