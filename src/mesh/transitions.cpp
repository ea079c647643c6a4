// Topological transitions (transitions.h): a vanishing cell collapses to a point.
//
// The pop of body b replaces every vertex of b's films by one point P. A facet of another film
// with one corner there keeps it as P; one with two or three is gone (it lay along a triple
// line of b or inside b's boundary). What is left around P is, in each film, a fan of facets
// from P: open where P is on a triple line, closed where P is inside the film. The cells
// around P are b's neighbours: with F <= 4 of them P is a Plateau point (F = 4: a quadruple
// point, six films and four triple lines; F = 3: a point of a triple line; F = 2: of a film),
// so the cluster is valid as it stands and the flow smooths the rest.
#include "mesh/transitions.h"

#include "mesh/transition_surgery.h"

#include "core/errors.h"
#include "core/format.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace froth {
namespace {

std::string body_name(int b) { return "pop_body: body " + std::to_string(b + 1); }

/// Refuses what a pop cannot take: walls, wires, fixed and curve vertices on the body.
void check_free_body(const Cluster& c, int b, const std::vector<int>& vertices) {
    if (!c.bodies()[b].lids.empty())
        throw TopologyError(body_name(b) + " meets walls or wires; only a cell bounded by "
                            "films alone can pop");
    for (int v : vertices) {
        if (c.is_fixed(v) || c.curve_point(v))
            throw TopologyError(body_name(b) + " has a fixed vertex (" + std::to_string(v + 1) +
                                "); it cannot collapse");
        if (!c.vertex_walls(v).empty())
            throw TopologyError(body_name(b) + " has vertex " + std::to_string(v + 1) +
                                " on a wall; it cannot collapse");
    }
}

/// The vertices of b's films, each with its unwrapped position u = X[v] + L d and lattice
/// offset d: one connected copy of the cell (all d = 0 in a cluster without a period).
struct UnwrappedBody {
    std::map<int, Vec3> u;
    std::map<int, Offset> d;
};

UnwrappedBody unwrap_body(const Cluster& c, int b) {
    const auto& X = c.positions();
    // vertex -> (surface, facet) of the body's films
    std::map<int, std::vector<std::pair<int, int>>> facets_at;
    for (const BodyFace& bf : c.bodies()[b].faces) {
        const Surface& s = c.surface(bf.surface);
        for (int f = 0; f < static_cast<int>(s.triangles.size()); ++f)
            for (int v : s.triangles[f]) facets_at[v].push_back({bf.surface, f});
    }
    UnwrappedBody w;
    if (facets_at.empty()) return w;
    double size = 0; // for the consistency test of a wrapping cell
    std::vector<int> queue{facets_at.begin()->first};
    w.u[queue[0]] = X[queue[0]];
    for (std::size_t q = 0; q < queue.size(); ++q) {
        const int v = queue[q];
        for (const auto& [si, f] : facets_at[v]) {
            const Surface& s = c.surface(si);
            const auto x = s.corners(X, f);
            const Tri& t = s.triangles[f];
            const int a = static_cast<int>(std::find(t.begin(), t.end(), v) - t.begin());
            for (int k = 0; k < 3; ++k) {
                const Vec3 uk = w.u[v] + (x[k] - x[a]);
                size = std::max(size, (x[k] - x[a]).norm());
                auto [it, fresh] = w.u.try_emplace(t[k], uk);
                if (fresh) queue.push_back(t[k]);
                else if ((it->second - uk).norm() > 1e-6 * std::max(size, 1e-300))
                    throw TopologyError(body_name(b) + " wraps around the periodic box (vertex " +
                                        std::to_string(t[k] + 1) + " meets itself shifted); it "
                                        "cannot collapse to a point");
            }
        }
    }
    for (const auto& [v, u] : w.u) w.d[v] = surgery::lattice_offset(c, u, X[v]);
    return w;
}

/// The expected number of junction edges at a Plateau point among F cells.
int plateau_junction_edges(int cells) { return cells == 4 ? 4 : cells == 3 ? 2 : 0; }

} // namespace

std::set<int> neighbour_cells(const Cluster& c, int b) {
    std::vector<int> count(c.n_surfaces(), 0); // bodies listing each surface
    std::vector<int> other(c.n_surfaces(), -1);
    for (int k = 0; k < c.n_bodies(); ++k)
        for (const BodyFace& f : c.bodies()[k].faces) {
            ++count[f.surface];
            if (k != b) other[f.surface] = k;
        }
    std::set<int> cells;
    std::set<int> seen;
    for (const BodyFace& f : c.bodies()[b].faces) {
        if (!seen.insert(f.surface).second)
            throw TopologyError(body_name(b) + " bounds surface " + std::to_string(f.surface + 1) +
                                " on both sides: it wraps around the periodic box and cannot "
                                "collapse to a point");
        cells.insert(count[f.surface] > 1 ? other[f.surface] : -1);
    }
    return cells;
}

Cluster pop_body(const Cluster& c, int b, TransitionRecord* record) {
    if (b < 0 || b >= c.n_bodies())
        throw InvalidInput("pop_body: body " + std::to_string(b + 1) + " does not exist (the "
                           "cluster has " + std::to_string(c.n_bodies()) + ")");
    const std::set<int> cells = neighbour_cells(c, b);
    const int F = static_cast<int>(cells.size());
    if (F > 4)
        throw TopologyError(body_name(b) + " has " + std::to_string(F) + " neighbouring cells; "
                            "a cell pops only with at most 4 (a tetrahedron, or a lens on a "
                            "triple line or a film): its faces must shrink away first");
    std::vector<char> popped_surface(c.n_surfaces(), 0);
    for (const BodyFace& f : c.bodies()[b].faces) popped_surface[f.surface] = 1;
    const UnwrappedBody w = unwrap_body(c, b);
    std::vector<int> body_vertices;
    for (const auto& [v, u] : w.u) body_vertices.push_back(v);
    check_free_body(c, b, body_vertices);
    Vec3 P = Vec3::Zero();
    for (const auto& [v, u] : w.u) P += u;
    P /= static_cast<double>(w.u.size());

    // New ids: the other vertices in order, then P; unused ones are dropped at the end.
    const int n = c.n_vertices();
    std::vector<int> id(n, -1);
    int next_id = 0;
    for (int v = 0; v < n; ++v)
        if (!w.u.count(v)) id[v] = next_id++;
    const int p_id = next_id;

    ClusterSpec spec;
    spec.period = c.periodic() ? std::optional<Eigen::Matrix3d>(c.period()) : std::nullopt;
    std::vector<int> surface_id(c.n_surfaces(), -1);
    std::vector<int> kept_surfaces;
    int removed_facets = 0;
    for (int si = 0; si < c.n_surfaces(); ++si) {
        const Surface& s = c.surface(si);
        if (popped_surface[si]) {
            removed_facets += static_cast<int>(s.triangles.size());
            continue;
        }
        ClusterSpec::Surface out;
        out.sigma = s.sigma;
        std::vector<std::pair<int, int>> link;
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const Tri& t = s.triangles[f];
            Tri nt;
            std::array<Offset, 3> k{};
            int at_p = 0;
            for (int a = 0; a < 3; ++a) {
                if (!s.offsets.empty()) k[a] = s.offsets[f][a];
                const auto it = w.d.find(t[a]);
                nt[a] = it == w.d.end() ? id[t[a]] : p_id;
                if (it == w.d.end()) continue;
                ++at_p;
                for (int j = 0; j < 3; ++j) k[a][j] -= it->second[j];
            }
            if (at_p > 1) {
                ++removed_facets;
                continue;
            }
            for (int a = 0; a < 3; ++a)
                if (nt[a] == p_id) link.push_back({nt[(a + 1) % 3], nt[(a + 2) % 3]});
            out.triangles.push_back(nt);
            if (spec.period) out.offsets.push_back(k);
        }
        surgery::check_one_fan(link, si, body_name(b));
        if (out.triangles.empty()) continue;
        surface_id[si] = static_cast<int>(spec.surfaces.size());
        kept_surfaces.push_back(si);
        spec.surfaces.push_back(std::move(out));
    }
    for (int k = 0; k < c.n_bodies(); ++k) {
        if (k == b) continue;
        std::vector<int> ids;
        for (const BodyFace& f : c.bodies()[k].faces)
            if (surface_id[f.surface] >= 0) ids.push_back(surface_id[f.surface]);
        if (ids.empty())
            throw TopologyError(body_name(b) + ": body " + std::to_string(k + 1) + " would "
                                "be left without films");
        spec.bodies.push_back(std::move(ids));
        spec.volconst.push_back(c.bodies()[k].volconst);
    }
    if (spec.surfaces.empty())
        throw TopologyError(body_name(b) + " is all the cluster has");

    // Vertices: the kept ones, P, then drop those no facet uses any more.
    std::vector<Vec3> V(p_id + 1);
    for (int v = 0; v < n; ++v)
        if (id[v] >= 0) V[id[v]] = c.position(v);
    V[p_id] = P;
    const std::vector<int> used = surgery::keep_used_vertices(spec, V);
    surgery::copy_vertex_lists(c, [&](int old) { return id[old] < 0 ? -1 : used[id[old]]; }, spec);
    Cluster r = surgery::rebuild(std::move(spec), body_name(b), "its collapse");
    const int p_new = used[p_id];
    if (p_new >= 0 &&
        static_cast<int>(r.vertex_junction_edges(p_new).size()) != plateau_junction_edges(F))
        throw TopologyError(body_name(b) + ": its " + std::to_string(F) + " neighbouring cells "
                            "would meet at the point in " +
                            std::to_string(r.vertex_junction_edges(p_new).size()) +
                            " triple-line edges, not as at a Plateau point; refine the mesh "
                            "around the body first");

    surgery::carry_over_without_body(c, b, kept_surfaces, r);

    if (record) {
        const double volume = body_volume(c, c.bodies()[b], c.positions());
        record->kind = "pop body";
        record->body = b;
        record->point = P;
        record->neighbours = F;
        record->removed_vertices = c.n_vertices() - r.n_vertices();
        record->removed_facets = removed_facets;
        record->where = "body " + std::to_string(b + 1) + " (volume " + fmt(volume) + ", " +
                        std::to_string(F) + " neighbouring cells) at " + point_text(P);
    }
    return r;
}

} // namespace froth
