// Junction topology of a cluster, derived from the triangles alone (numerics.md §1):
// an edge in 2 triangles of one surface is interior, in 3 surfaces a triple-junction edge; every
// other count is an error. Bodies get their signs by propagating orientation across shared edges.

#include "core/errors.h"
#include "core/format.h"
#include "mesh/cluster.h"

#include <algorithm>
#include <cstdint>
#include <cmath>
#include <map>
#include <numbers>
#include <string>

namespace froth {
namespace {

/// One triangle side: the undirected edge (lo, hi) seen from one facet.
struct HalfEdge {
    int lo, hi;
    int surface, facet;
    int dir;      ///< +1 if the facet traverses lo -> hi
    int opposite; ///< the facet's third corner
};

std::vector<HalfEdge> collect_half_edges(const std::vector<Surface>& surfaces) {
    std::vector<HalfEdge> h;
    for (int s = 0; s < static_cast<int>(surfaces.size()); ++s) {
        const auto& tris = surfaces[s].triangles;
        for (int f = 0; f < static_cast<int>(tris.size()); ++f)
            for (int k = 0; k < 3; ++k) {
                const int a = tris[f][k], b = tris[f][(k + 1) % 3], c = tris[f][(k + 2) % 3];
                h.push_back({std::min(a, b), std::max(a, b), s, f, a < b ? 1 : -1, c});
            }
    }
    std::sort(h.begin(), h.end(), [](const HalfEdge& x, const HalfEdge& y) {
        return std::tie(x.lo, x.hi, x.surface) < std::tie(y.lo, y.hi, y.surface);
    });
    return h;
}

std::string edge_name(int a, int b) {
    return "edge " + std::to_string(a + 1) + "-" + std::to_string(b + 1);
}

// Solid angle of the triangle abc seen from p, signed by the triangle's orientation (Van
// Oosterom and Strackee 1983): summed over a closed outward surface it is 4 pi inside, 0 outside.
double solid_angle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
    const Vec3 x = a - p, y = b - p, z = c - p;
    const double lx = x.norm(), ly = y.norm(), lz = z.norm();
    return 2 * std::atan2(x.dot(y.cross(z)),
                          lx * ly * lz + x.dot(y) * lz + y.dot(z) * lx + z.dot(x) * ly);
}

// The surfaces of one body as shells: sets of surfaces joined by shared edges (component[s]),
// each consistently signed on its own. A body around a cavity (a bubble in a bubble) has
// several; a shell inside an odd number of the others bounds a cavity and must face into it.
// Turns every shell outward, then flips those at odd depth.
void orient_shells(const std::vector<Surface>& surfaces, const std::vector<Vec3>& X,
                   std::map<int, int>& sign, const std::map<int, int>& component, int shells) {
    std::vector<double> volume(shells, 0.0);
    std::vector<Vec3> probe(shells); // a facet centroid of each shell: on no other shell
    for (auto [s, sg] : sign)
        for (const Tri& t : surfaces[s].triangles) {
            volume[component.at(s)] += sg * cone_volume(X[t[0]], X[t[1]], X[t[2]]);
            probe[component.at(s)] = (X[t[0]] + X[t[1]] + X[t[2]]) / 3;
        }
    std::vector<int> outward(shells); // the sign that turns each shell outward
    for (int c = 0; c < shells; ++c)
        outward[c] = volume[c] < 0 ? -1 : 1;
    std::vector<int> depth(shells, 0);
    for (int c = 0; c < shells; ++c) {
        std::vector<double> angle(shells, 0.0); // of each shell, turned outward, seen from c
        for (auto [s, sg] : sign) {
            const int d = component.at(s);
            for (const Tri& t : surfaces[s].triangles)
                angle[d] += sg * outward[d] * solid_angle(probe[c], X[t[0]], X[t[1]], X[t[2]]);
        }
        for (int d = 0; d < shells; ++d)
            if (d != c && angle[d] > 2 * std::numbers::pi) ++depth[c]; // winding number 1
    }
    for (auto& [s, sg] : sign)
        sg *= outward[component.at(s)] * (depth[component.at(s)] % 2 ? -1 : 1);
}

} // namespace

void Cluster::classify_edges() {
    const std::vector<HalfEdge> h = collect_half_edges(surfaces_);
    for (std::size_t i = 0; i < h.size();) {
        std::size_t j = i;
        while (j < h.size() && h[j].lo == h[i].lo && h[j].hi == h[i].hi) ++j;
        const int count = static_cast<int>(j - i);
        const std::string edge = edge_name(h[i].lo, h[i].hi);
        if (count == 1) {
            const int a = h[i].lo, b = h[i].hi;
            if (fixed_[a] && fixed_[b] && !on_common_wall(a, b)) {
                wire_edges_.push_back({a, b, h[i].surface}); // h is sorted by (lo, hi)
            } else if (walls_.empty()) {
                throw TopologyError("cluster: " + edge + " of surface " +
                                    std::to_string(h[i].surface + 1) +
                                    " is a free boundary edge (in one facet only) and no wall is"
                                    " attached; close the surface, give walls (froth.plane, ...)"
                                    " or fix both its vertices (a wire)");
            } else {
                boundary_edges_.push_back({a, b, h[i].surface});
            }
        } else if (count == 2) {
            if (h[i].surface != h[i + 1].surface)
                throw TopologyError("cluster: " + edge + " is shared by exactly two surfaces (" +
                                    std::to_string(h[i].surface + 1) + " and " +
                                    std::to_string(h[i + 1].surface + 1) +
                                    "); a film split in two must be one surface");
            if (h[i].dir == h[i + 1].dir)
                throw TopologyError("cluster: surface " + std::to_string(h[i].surface + 1) +
                                    " is not consistently oriented: facets " +
                                    std::to_string(h[i].facet + 1) + " and " +
                                    std::to_string(h[i + 1].facet + 1) + " both traverse " +
                                    edge + " the same way");
        } else if (count == 3) {
            if (h[i].surface == h[i + 1].surface || h[i + 1].surface == h[i + 2].surface)
                throw TopologyError("cluster: " + edge + " has three facets but only two surfaces"
                                    " (surface " + std::to_string(h[i + 1].surface + 1) +
                                    " folds onto itself there)");
            JunctionEdge e{h[i].lo, h[i].hi, {}, {}, {}, -1};
            for (int k = 0; k < 3; ++k) {
                e.surfaces[k] = h[i + k].surface;
                e.o[k] = h[i + k].dir;
                e.opposite[k] = h[i + k].opposite;
            }
            junction_edges_.push_back(e);
        } else {
            throw TopologyError("cluster: " + edge + " is shared by " + std::to_string(count) +
                                " facets; only triple junction lines (3 surfaces) are supported,"
                                " not quadruple lines");
        }
        i = j;
    }
}

void Cluster::build_triple_lines() {
    const int n_edges = static_cast<int>(junction_edges_.size());
    std::vector<std::vector<int>> at(n_vertices());
    for (int e = 0; e < n_edges; ++e) {
        at[junction_edges_[e].a].push_back(e);
        at[junction_edges_[e].b].push_back(e);
    }
    // A line continues through a vertex with exactly two junction edges of the same surfaces.
    auto passes = [&](int v) {
        return at[v].size() == 2 &&
               junction_edges_[at[v][0]].surfaces == junction_edges_[at[v][1]].surfaces;
    };
    auto walk = [&](int start_vertex, int start_edge) {
        TripleLine line;
        line.surfaces = junction_edges_[start_edge].surfaces;
        const int id = static_cast<int>(triple_lines_.size());
        int v = start_vertex, e = start_edge;
        line.vertices.push_back(v);
        while (e >= 0 && junction_edges_[e].line < 0) {
            junction_edges_[e].line = id;
            v = junction_edges_[e].a == v ? junction_edges_[e].b : junction_edges_[e].a;
            if (v == start_vertex) {
                line.closed = true;
                break;
            }
            line.vertices.push_back(v);
            e = passes(v) ? (at[v][0] == e ? at[v][1] : at[v][0]) : -1;
        }
        triple_lines_.push_back(std::move(line));
    };
    for (int v = 0; v < n_vertices(); ++v)
        if (!at[v].empty() && !passes(v))
            for (int e : at[v])
                if (junction_edges_[e].line < 0) walk(v, e);
    for (int e = 0; e < n_edges; ++e) // what is left are closed loops
        if (junction_edges_[e].line < 0) walk(junction_edges_[e].a, e);
    for (int v = 0; v < n_vertices(); ++v)
        if (at[v].size() >= 3) quadruple_points_.push_back(v);
}

void Cluster::orient_bodies(const std::vector<std::vector<int>>& body_surfaces,
                             const std::vector<std::optional<double>>& volconst) {
    const std::vector<HalfEdge> h = collect_half_edges(surfaces_);
    for (std::size_t b = 0; b < body_surfaces.size(); ++b) {
        const std::string name = "body " + std::to_string(b + 1);
        std::map<int, int> sign; // surface -> sign, 0 = not yet known
        for (int s : body_surfaces[b]) {
            if (s < 0 || s >= n_surfaces())
                throw InvalidInput("cluster: " + name + " names surface " + std::to_string(s + 1) +
                                   ", but there are " + std::to_string(n_surfaces()) + " surfaces");
            if (!sign.emplace(s, 0).second)
                throw InvalidInput("cluster: " + name + " names surface " + std::to_string(s + 1) +
                                   " twice");
        }
        if (sign.empty()) throw InvalidInput("cluster: " + name + " has no surfaces");
        // Edges of the body with the half-edges of its own surfaces: each must appear twice.
        std::vector<std::pair<const HalfEdge*, const HalfEdge*>> links;
        for (std::size_t i = 0; i < h.size();) {
            std::size_t j = i;
            std::vector<const HalfEdge*> mine;
            for (; j < h.size() && h[j].lo == h[i].lo && h[j].hi == h[i].hi; ++j)
                if (sign.count(h[j].surface)) mine.push_back(&h[j]);
            // A free boundary edge (on a wall or a wire) ends the body at a lid.
            const bool free_edge = j - i == 1;
            if (!mine.empty() && mine.size() != 2 && !(free_edge && mine.size() == 1))
                throw TopologyError("cluster: " + name + " is not closed: " +
                                    edge_name(h[i].lo, h[i].hi) + " is in " +
                                    std::to_string(mine.size()) + " of its facets, not 2" +
                                    (walls_.empty() ? "" : " (and is not on a wall)"));
            if (mine.size() == 2 && mine[0]->surface != mine[1]->surface)
                links.emplace_back(mine[0], mine[1]);
            i = j;
        }
        // Propagate: across a shared edge the two signed facets must traverse it oppositely.
        std::map<int, int> shell; // surface -> the shell (set of edge-joined surfaces) it is in
        int shells = 0;
        for (auto& [s, sg] : sign) {
            if (sg != 0) continue;
            sg = 1;
            shell[s] = shells++;
            for (bool changed = true; changed;) {
                changed = false;
                for (auto [p, q] : links) {
                    int& sp = sign[p->surface];
                    int& sq = sign[q->surface];
                    if (sp != 0 && sq == 0)
                        sq = -sp * p->dir * q->dir, shell[q->surface] = shell[p->surface],
                        changed = true;
                    if (sq != 0 && sp == 0)
                        sp = -sq * p->dir * q->dir, shell[p->surface] = shell[q->surface],
                        changed = true;
                    if (sp != 0 && sq != 0 && sp * p->dir == sq * q->dir)
                        throw TopologyError("cluster: " + name + " cannot be oriented: its "
                                            "surfaces " + std::to_string(p->surface + 1) + " and " +
                                            std::to_string(q->surface + 1) + " disagree at " +
                                            edge_name(p->lo, p->hi));
                }
            }
        }
        // (With walls or wires a shell may be open, closed by lids: no winding number; left as
        // signed.)
        if (shells > 1 && walls_.empty() && wire_edges_.empty())
            orient_shells(surfaces_, X_, sign, shell, shells);
        Body body;
        for (auto [s, sg] : sign) body.faces.push_back({s, sg, {}});
        find_lids(body);
        // Oriented by the volume its films and lids enclose; a volconst only shifts it.
        const double enclosed = body_volume(*this, body, X_);
        double area = 0;
        for (const BodyFace& f : body.faces)
            for (const Tri& t : surfaces_[f.surface].triangles)
                area += 0.5 * (X_[t[1]] - X_[t[0]]).cross(X_[t[2]] - X_[t[0]]).norm();
        if (std::abs(enclosed) <= 1e-12 * std::pow(area, 1.5))
            throw TopologyError("cluster: " + name + " encloses no volume (its films and lids "
                                "bound " + fmt(enclosed) + ")");
        if (enclosed < 0) {
            for (BodyFace& f : body.faces) f.sign = -f.sign;
            for (Lid& lid : body.lids)
                for (auto& e : lid.edges) std::swap(e[0], e[1]);
        }
        if (!volconst.empty() && volconst[b]) {
            body.volconst = volconst[b];
            for (Lid& lid : body.lids) lid.evolver_content = true;
        }
        initial_volumes_.push_back(body_volume(*this, body, X_));
        bodies_.push_back(std::move(body));
    }
}

} // namespace froth
