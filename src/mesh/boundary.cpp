// Films attached to walls (seed (1.25), (3.10), (3.11)): which vertices are constrained to
// which walls, and the lids that close bodies on a wall (numerics.md §1).

#include "core/errors.h"
#include "core/format.h"
#include "mesh/cluster.h"
#include "mesh/csr.h"

#include <Eigen/SVD>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <optional>

namespace froth {
namespace {

std::string vertex_text(int v, const Vec3& x) {
    return "vertex " + std::to_string(v + 1) + " " + point_text(x);
}

/// Rank of a set of unit normals (1, 2 or 3).
int normal_rank(const std::vector<Vec3>& normals) {
    Eigen::MatrixXd N(3, normals.size());
    for (std::size_t k = 0; k < normals.size(); ++k)
        N.col(k) = normals[k];
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(N);
    const auto& s = svd.singularValues();
    int rank = 0;
    for (int k = 0; k < s.size(); ++k)
        rank += s[k] > 1e-8 * s[0];
    return rank;
}

int find_root(std::vector<int>& parent, int v) {
    while (parent[v] != v)
        v = parent[v] = parent[parent[v]];
    return v;
}

} // namespace

double Cluster::wall_tolerance() const {
    // Vertices of the mesh are placed on the walls by the builders up to round-off; a user mesh
    // gets a relative tolerance of 1e-6 of a typical edge length.
    const double edge = std::sqrt(4 / std::sqrt(3.0) * initial_area_ / std::max(n_facets_, 1));
    return 1e-6 * edge;
}

bool Cluster::on_common_wall(int a, int b) const {
    if (given_attachments_) {
        const std::vector<int> wa = vertex_walls(a), wb = vertex_walls(b);
        return std::any_of(wa.begin(), wa.end(), [&](int w) {
            return std::find(wb.begin(), wb.end(), w) != wb.end();
        });
    }
    const double tol = wall_tolerance();
    for (const WallPtr& w : walls_)
        if (w->distance(X_[a]) <= tol && w->distance(X_[b]) <= tol) return true;
    return false;
}

bool Cluster::is_wire_edge(int a, int b) const {
    if (a > b) std::swap(a, b);
    const auto it = std::lower_bound(wire_edges_.begin(), wire_edges_.end(), std::pair{a, b},
                                     [](const BoundaryEdge& e, const std::pair<int, int>& k) {
                                         return std::pair{e.a, e.b} < k;
                                     });
    return it != wire_edges_.end() && it->a == a && it->b == b;
}

void Cluster::attach_walls() {
    const int n = n_vertices();
    freedom_.assign(n, 3);
    std::vector<std::pair<int, int>> vertex_wall;
    std::vector<int> surface_of(n, -1), edge_other(n, -1);
    for (const BoundaryEdge& e : boundary_edges_)
        for (int v : {e.a, e.b})
            surface_of[v] = e.surface, edge_other[v] = v == e.a ? e.b : e.a;
    const double tol = wall_tolerance();
    for (int v = 0; v < n; ++v) {
        if (surface_of[v] < 0) continue;
        std::vector<Vec3> normals;
        double nearest = INFINITY;
        int nearest_wall = 0;
        for (int w = 0; w < static_cast<int>(walls_.size()); ++w) {
            if (given_attachments_) {
                const std::vector<int> given = vertex_walls(v);
                if (std::find(given.begin(), given.end(), w) != given.end())
                    vertex_wall.emplace_back(v, w), normals.push_back(walls_[w]->normal(X_[v]));
                continue;
            }
            const double d = walls_[w]->distance(X_[v]);
            if (d < nearest) nearest = d, nearest_wall = w;
            if (d <= tol) {
                vertex_wall.emplace_back(v, w);
                normals.push_back(walls_[w]->normal(X_[v]));
            }
        }
        const std::string where =
            vertex_text(v, X_[v]) + " of surface " + std::to_string(surface_of[v] + 1);
        if (normals.empty() && given_attachments_)
            throw TopologyError("cluster: " + where + " is on a free boundary edge but has no "
                                "wall among the given attachments");
        if (normals.empty())
            throw TopologyError(
                "cluster: " + where + " is on a free boundary edge (" + std::to_string(v + 1) +
                "-" + std::to_string(edge_other[v] + 1) + ") but on no wall: the nearest, wall " +
                std::to_string(nearest_wall + 1) + " (" + walls_[nearest_wall]->describe() +
                "), is at distance " + fmt(nearest) + " (tolerance " + fmt(tol) + ")");
        freedom_[v] = 3 - normal_rank(normals);
        if (freedom_[v] == 0)
            throw TopologyError("cluster: " + where +
                                " lies on walls whose normals span all "
                                "directions; it could not move");
    }
    if (given_attachments_) {
        for (int v = 0; v < n; ++v)
            if (surface_of[v] < 0 && vw_start_[v] != vw_start_[v + 1])
                throw TopologyError("cluster: " + vertex_text(v, X_[v]) + " is attached to a "
                                    "wall but is on no free boundary edge");
    }
    build_csr_lists(n, vertex_wall, vw_start_, vw_list_);
    for (const BoundaryEdge& e : boundary_edges_) {
        const std::vector<int> wa = vertex_walls(e.a), wb = vertex_walls(e.b);
        if (std::none_of(wa.begin(), wa.end(),
                         [&](int w) { return std::find(wb.begin(), wb.end(), w) != wb.end(); }))
            throw TopologyError("cluster: boundary edge " + std::to_string(e.a + 1) + "-" +
                                std::to_string(e.b + 1) + " of surface " +
                                std::to_string(e.surface + 1) +
                                " has its ends on different walls; a free edge must lie on one");
    }
}

void Cluster::find_lids(Body& body) const {
    if (boundary_edges_.empty() && wire_edges_.empty()) return;
    std::vector<std::array<int, 2>> keys;
    for (const auto* list : {&boundary_edges_, &wire_edges_})
        for (const BoundaryEdge& e : *list)
            keys.push_back({e.a, e.b});
    std::sort(keys.begin(), keys.end());
    std::vector<std::array<int, 2>> edges;
    for (const BodyFace& f : body.faces)
        for (const Tri& t : surfaces_[f.surface].triangles)
            for (int k = 0; k < 3; ++k) {
                const int a = t[k], b = t[(k + 1) % 3];
                if (std::binary_search(keys.begin(), keys.end(),
                                       std::array<int, 2>{std::min(a, b), std::max(a, b)}))
                    edges.push_back(f.sign > 0 ? std::array<int, 2>{a, b}
                                               : std::array<int, 2>{b, a});
            }
    std::vector<int> parent(n_vertices());
    std::iota(parent.begin(), parent.end(), 0);
    for (const auto& e : edges)
        parent[find_root(parent, e[0])] = find_root(parent, e[1]);
    std::vector<int> lid_of(n_vertices(), -1);
    for (const auto& e : edges) {
        int& id = lid_of[find_root(parent, e[0])];
        if (id < 0) {
            id = static_cast<int>(body.lids.size());
            body.lids.push_back({});
        }
        Lid& lid = body.lids[id];
        lid.edges.push_back(e);
        const std::vector<int> wa = vertex_walls(e[0]), wb = vertex_walls(e[1]);
        for (int w : wa) // the walls the edge lies on (attach_walls checked there is one)
            if (std::find(wb.begin(), wb.end(), w) != wb.end() &&
                std::find(lid.walls.begin(), lid.walls.end(), w) == lid.walls.end())
                lid.walls.push_back(w);
    }
}

double lid_volume(const Cluster& c, const Lid& lid, const std::vector<Vec3>& X) {
    Vec3 center = Vec3::Zero();
    for (const auto& e : lid.edges)
        center += X[e[0]];
    center /= static_cast<double>(lid.edges.size());
    // The fan's apex on all the lid's walls (alternating projections: their common line or
    // corner for planes). Any such point closes a flat lid exactly.
    Vec3 apex = center;
    for (int pass = 0; pass < (lid.walls.size() > 1 ? 50 : 1); ++pass)
        for (int w : lid.walls) {
            const Wall& wall = *c.walls()[w];
            apex = wall.gradient(apex).norm() > 0 ? wall.project(apex) : X[lid.edges.front()[0]];
        }
    // On one wall its own flux (curved walls count the lid's bulge); across walls and on wires
    // flat fans, each triangle (apex, b, a). Evolver's convention takes the closing fan out
    // again (its cones less its z dx dy), so there the flat fan serves on any wall.
    double flux = 0, z_content = 0;
    for (const auto& e : lid.edges) {
        const Vec3 &a = X[e[0]], &b = X[e[1]];
        const bool flat = lid.walls.size() != 1 || lid.evolver_content;
        flux += flat ? 0.5 * apex.dot(b.cross(a)) : c.walls()[lid.walls[0]]->fan_flux(apex, a, b);
        if (lid.evolver_content) // z is linear on the triangle: its mean times the z-area
            z_content += (apex[2] + a[2] + b[2]) / 3 * 0.5 * (b - apex).cross(a - apex)[2];
    }
    return flux / 3.0 - z_content;
}

double lid_volume(const Cluster& c, const Lid& lid) {
    return lid_volume(c, lid, c.positions());
}

double body_volume(const Cluster& c, const Body& body, const std::vector<Vec3>& X) {
    // A closed body's films (no lids) enclose the same volume seen from any point, so the
    // cones start at one of its vertices: from the origin their terms grow as |x|^2 and cancel,
    // and a cell 10-20 from it (a 1000-cell foam's box) lost 1e-12 of its volume to round-off.
    std::optional<Vec3> apex;
    if (!body.lids.empty()) apex = Vec3::Zero(); // lids close the films through the origin's cones
    double v = 0;
    for (const BodyFace& f : body.faces) {
        const Surface& s = c.surface(f.surface);
        for (std::size_t k = 0; k < s.triangles.size(); ++k) {
            std::array<Vec3, 3> x = s.corners(X, k);
            if (!f.shift.empty()) // a periodic cell: the facet where the unwrapped cell has it
                for (Vec3& p : x) p += f.shift[k];
            if (!apex) apex = x[0];
            v += f.sign * cone_volume(x[0] - *apex, x[1] - *apex, x[2] - *apex);
        }
    }
    for (const Lid& lid : body.lids)
        v += lid_volume(c, lid, X);
    return v + body.volconst.value_or(0.0);
}

std::vector<int> drop_wall_lids(ClusterSpec& spec) {
    double length = 0;
    int edges = 0;
    for (const auto& surface : spec.surfaces)
        for (const Tri& t : surface.triangles)
            for (int k = 0; k < 3; ++k, ++edges)
                length += (spec.vertices[t[k]] - spec.vertices[t[(k + 1) % 3]]).norm();
    const double tol = 1e-6 * length / std::max(edges, 1);
    auto on_wall = [&](const Tri& t) {
        return std::any_of(spec.walls.begin(), spec.walls.end(), [&](const WallPtr& w) {
            return std::all_of(t.begin(), t.end(),
                               [&](int v) { return w->distance(spec.vertices[v]) <= tol; });
        });
    };
    std::vector<int> kept, new_id(spec.surfaces.size(), -1);
    std::vector<ClusterSpec::Surface> surfaces;
    for (std::size_t i = 0; i < spec.surfaces.size(); ++i) {
        auto& tris = spec.surfaces[i].triangles;
        tris.erase(std::remove_if(tris.begin(), tris.end(), on_wall), tris.end());
        if (tris.empty()) continue;
        new_id[i] = static_cast<int>(kept.size());
        kept.push_back(static_cast<int>(i));
        surfaces.push_back(std::move(spec.surfaces[i]));
    }
    for (auto& body : spec.bodies) {
        std::vector<int> ids;
        for (int s : body)
            if (s >= 0 && s < static_cast<int>(new_id.size()) && new_id[s] >= 0)
                ids.push_back(new_id[s]);
        body = std::move(ids);
    }
    std::vector<int> vertex_id(spec.vertices.size(), -1);
    std::vector<Vec3> vertices;
    for (auto& surface : surfaces)
        for (Tri& t : surface.triangles)
            for (int& v : t) {
                if (vertex_id[v] < 0) {
                    vertex_id[v] = static_cast<int>(vertices.size());
                    vertices.push_back(spec.vertices[v]);
                }
                v = vertex_id[v];
            }
    spec.surfaces = std::move(surfaces);
    spec.vertices = std::move(vertices);
    return kept;
}

} // namespace froth
