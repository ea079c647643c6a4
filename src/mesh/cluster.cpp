#include "mesh/cluster.h"

#include "core/errors.h"
#include "core/format.h"
#include "mesh/csr.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <string>

namespace froth {
namespace {

std::string vertex_name(int v) { return "vertex " + std::to_string(v + 1); }
std::string surface_name(int s) { return "surface " + std::to_string(s + 1); }

} // namespace

Cluster::Cluster(ClusterSpec spec) {
    check_spec(spec);
    X_ = std::move(spec.vertices);
    period_ = spec.period;
    walls_ = std::move(spec.walls);
    surfaces_.resize(spec.surfaces.size());
    std::vector<std::pair<int, int>> vertex_surface;
    for (std::size_t i = 0; i < spec.surfaces.size(); ++i) {
        Surface& s = surfaces_[i];
        s.triangles = std::move(spec.surfaces[i].triangles);
        s.sigma = spec.surfaces[i].sigma;
        if (period_) {
            s.offsets = std::move(spec.surfaces[i].offsets);
            s.offsets.resize(s.triangles.size()); // none given: all zero
            s.shifts.resize(s.triangles.size());
            for (std::size_t f = 0; f < s.offsets.size(); ++f)
                for (int a = 0; a < 3; ++a)
                    s.shifts[f][a] = *period_ * Eigen::Vector3i(s.offsets[f][a].data()).cast<double>();
        }
        for (const Tri& t : s.triangles) s.vertices.insert(s.vertices.end(), t.begin(), t.end());
        std::sort(s.vertices.begin(), s.vertices.end());
        s.vertices.erase(std::unique(s.vertices.begin(), s.vertices.end()), s.vertices.end());
        for (int v : s.vertices) vertex_surface.emplace_back(v, static_cast<int>(i));
        n_facets_ += static_cast<int>(s.triangles.size());
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const auto x = s.corners(X_, f);
            initial_area_ += 0.5 * (x[1] - x[0]).cross(x[2] - x[0]).norm();
        }
    }
    build_csr_lists(n_vertices(), vertex_surface, vs_start_, vs_list_);
    curves_ = std::move(spec.curves);
    curve_points_ = std::move(spec.curve_points);
    std::sort(curve_points_.begin(), curve_points_.end(),
              [](const CurvePoint& a, const CurvePoint& b) { return a.vertex < b.vertex; });
    fixed_.assign(n_vertices(), 0); // before the edges: a free edge between fixed vertices is a wire
    for (int v : spec.fixed) fixed_[v] = 1;
    n_fixed_ = static_cast<int>(std::count(fixed_.begin(), fixed_.end(), 1));
    for (int v = 0; v < n_vertices(); ++v)
        if (vs_start_[v] == vs_start_[v + 1])
            throw TopologyError("cluster: " + vertex_name(v) + " is not a corner of any facet");

    if (!spec.attachments.empty()) {
        std::vector<std::pair<int, int>> vertex_wall;
        for (const auto& [v, w] : spec.attachments) vertex_wall.emplace_back(v, w);
        build_csr_lists(n_vertices(), vertex_wall, vw_start_, vw_list_);
        given_attachments_ = true;
    }
    if (period_) index_edge_offsets();
    classify_edges();
    attach_walls();
    build_triple_lines();
    check_tension_triangles("cluster");
    std::vector<std::pair<int, int>> vertex_edge;
    for (int e = 0; e < static_cast<int>(junction_edges_.size()); ++e) {
        vertex_edge.emplace_back(junction_edges_[e].a, e);
        vertex_edge.emplace_back(junction_edges_[e].b, e);
    }
    build_csr_lists(n_vertices(), vertex_edge, vj_start_, vj_list_);
    if (period_)
        orient_periodic_bodies(spec.bodies);
    else
        orient_bodies(spec.bodies, spec.volconst);
    target_volumes_ = initial_volumes_;
}

std::vector<int> Cluster::fixed_vertices() const {
    std::vector<int> ids;
    for (int v = 0; v < n_vertices(); ++v)
        if (fixed_[v]) ids.push_back(v);
    return ids;
}

void Cluster::set_fixed(const std::vector<int>& vertices, bool fixed) {
    for (int v : vertices)
        if (v < 0 || v >= n_vertices())
            throw InvalidInput(std::string(fixed ? "fix" : "unfix") + ": vertex " +
                               std::to_string(v + 1) + " does not exist (the "
                               "cluster has vertices 1.." + std::to_string(n_vertices()) + ")");
    if (!fixed)
        for (const BoundaryEdge& e : wire_edges_)
            for (int v : {e.a, e.b})
                if (std::find(vertices.begin(), vertices.end(), v) != vertices.end())
                    throw InvalidInput("unfix: vertex " + std::to_string(v + 1) + " ends the free "
                                       "boundary edge " + std::to_string(e.a + 1) + "-" +
                                       std::to_string(e.b + 1) + " of surface " +
                                       std::to_string(e.surface + 1) + ", which no wall holds "
                                       "(a wire); it stays fixed");
    for (int v : vertices) fixed_[v] = fixed;
    n_fixed_ = static_cast<int>(std::count(fixed_.begin(), fixed_.end(), 1));
    ++assembly_revision_, ++materials_revision_;
}

void Cluster::set_target_volume(int body, double volume) {
    if (body < 0 || body >= n_bodies())
        throw InvalidInput("set_volume: there is no body " + std::to_string(body + 1) + " (the "
                           "cluster has " + std::to_string(n_bodies()) + ")");
    if (!(std::isfinite(volume) && volume > 0))
        throw InvalidInput("set_volume: body " + std::to_string(body + 1) +
                           ": the volume must be positive and finite, got " + fmt(volume));
    target_volumes_[body] = volume;
}

void Cluster::set_initial_area(double area) {
    if (!(std::isfinite(area) && area > 0))
        throw InvalidInput("set_initial_area: the area must be positive and finite, got " +
                           fmt(area));
    initial_area_ = area;
}

void Cluster::set_volume_references(std::vector<double> initial, std::vector<double> target) {
    if (initial.size() != bodies_.size() || target.size() != bodies_.size())
        throw InvalidInput("set_volume_references: expected " + std::to_string(n_bodies()) +
                           " volumes");
    initial_volumes_ = std::move(initial);
    target_volumes_ = std::move(target);
}

ClusterSpec cluster_spec(const Cluster& c) {
    ClusterSpec spec;
    spec.vertices = c.positions();
    if (c.periodic()) spec.period = c.period();
    for (const Surface& s : c.surfaces()) spec.surfaces.push_back({s.triangles, s.sigma, s.offsets});
    for (const Body& b : c.bodies()) {
        std::vector<int> ids;
        for (const BodyFace& f : b.faces) ids.push_back(f.surface);
        spec.bodies.push_back(std::move(ids));
        spec.volconst.push_back(b.volconst);
    }
    spec.walls = c.walls();
    spec.attachments = c.wall_attachments();
    spec.fixed = c.fixed_vertices();
    spec.curves = c.curves();
    spec.curve_points = c.curve_points();
    return spec;
}

void carry_over(const Cluster& from, Cluster& to) {
    for (int i = 0; i < from.n_surfaces(); ++i) {
        to.set_anisotropy(i, from.surface(i).gamma);
        to.set_mobility(i, from.surface(i).beta);
    }
    to.set_time(from.time());
    to.set_volume_references(from.initial_volumes(), from.target_volumes());
}

void Cluster::check_spec(const ClusterSpec& spec) const {
    const int n = static_cast<int>(spec.vertices.size());
    if (n == 0) throw InvalidInput("cluster: no vertices");
    if (spec.surfaces.empty()) throw InvalidInput("cluster: no surfaces");
    for (const auto& [v, w] : spec.attachments)
        if (v < 0 || v >= n || w < 0 || w >= static_cast<int>(spec.walls.size()))
            throw InvalidInput("cluster: the attachment of vertex " + std::to_string(v + 1) +
                               " to wall " + std::to_string(w + 1) + " is out of range");
    check_curve_points(spec);
    if (spec.period) check_period(spec);
    for (const auto& s : spec.surfaces)
        if (!spec.period && !s.offsets.empty())
            throw InvalidInput("cluster: facet offsets are given but no period");
    if (!spec.volconst.empty() && spec.volconst.size() != spec.bodies.size())
        throw InvalidInput("cluster: " + std::to_string(spec.volconst.size()) + " volconst "
                           "entries for " + std::to_string(spec.bodies.size()) + " bodies");
    for (std::size_t b = 0; b < spec.volconst.size(); ++b)
        if (spec.volconst[b] && !(std::isfinite(*spec.volconst[b]) &&
                                  std::abs(*spec.volconst[b]) <= kMaxCoordinate))
            throw InvalidInput("cluster: body " + std::to_string(b + 1) + ": volconst must be "
                               "a finite number, got " + fmt(*spec.volconst[b]));
    for (std::size_t w = 0; w < spec.walls.size(); ++w)
        if (!spec.walls[w]) throw InvalidInput("cluster: wall " + std::to_string(w + 1) + " is null");
    for (int v : spec.fixed)
        if (v < 0 || v >= n)
            throw InvalidInput("cluster: fixed vertex " + std::to_string(v + 1) +
                               " does not exist (there are " + std::to_string(n) + " vertices)");
    for (int v = 0; v < n; ++v)
        if (!spec.vertices[v].allFinite())
            throw InvalidInput("cluster: " + vertex_name(v) + " has a non-finite coordinate");
        else if (spec.vertices[v].cwiseAbs().maxCoeff() > kMaxCoordinate)
            throw InvalidInput("cluster: " + vertex_name(v) + " has the coordinate " +
                               fmt(spec.vertices[v].cwiseAbs().maxCoeff()) +
                               "; coordinates must be at most 1e100 in magnitude (areas and "
                               "volumes of larger ones overflow)");
    for (std::size_t i = 0; i < spec.surfaces.size(); ++i) {
        const auto& s = spec.surfaces[i];
        const std::string name = surface_name(static_cast<int>(i));
        if (!(std::isfinite(s.sigma) && s.sigma > 0))
            throw InvalidInput("cluster: " + name + " has sigma " + fmt(s.sigma) +
                               "; sigma must be positive");
        if (s.triangles.empty()) throw InvalidInput("cluster: " + name + " has no facets");
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const Tri& t = s.triangles[f];
            const std::string where = name + " facet " + std::to_string(f + 1);
            for (int v : t)
                if (v < 0 || v >= n)
                    throw InvalidInput("cluster: " + where + " names vertex " +
                                       std::to_string(v + 1) + ", but there are " +
                                       std::to_string(n) + " vertices");
            if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
                throw TopologyError("cluster: " + where + " repeats a corner");
            std::array<Vec3, 3> x = {spec.vertices[t[0]], spec.vertices[t[1]], spec.vertices[t[2]]};
            if (spec.period && !s.offsets.empty())
                for (int a = 0; a < 3; ++a)
                    x[a] += *spec.period * Eigen::Vector3i(s.offsets[f][a].data()).cast<double>();
            const Vec3 e1 = x[1] - x[0], e2 = x[2] - x[0];
            const double scale = std::max({e1.squaredNorm(), e2.squaredNorm(),
                                           (e2 - e1).squaredNorm()});
            if (e1.cross(e2).norm() <= 1e-12 * scale)
                throw GeometryError("cluster: " + where + " (vertices " + std::to_string(t[0] + 1) +
                                    ", " + std::to_string(t[1] + 1) + ", " +
                                    std::to_string(t[2] + 1) + ") has zero area");
        }
    }
}

void Cluster::check_period(const ClusterSpec& spec) const {
    const Eigen::Matrix3d& L = *spec.period;
    if (!L.allFinite() || L.cwiseAbs().maxCoeff() > kMaxCoordinate)
        throw InvalidInput("cluster: the period vectors must be finite (at most 1e100)");
    const double scale = L.colwise().norm().prod();
    if (!(std::abs(L.determinant()) > 1e-12 * scale))
        throw InvalidInput("cluster: the period vectors are linearly dependent (det " +
                           fmt(L.determinant()) + "); a periodic box needs three independent ones");
    if (!spec.walls.empty())
        throw InvalidInput("cluster: a periodic cluster cannot have walls (not supported)");
    if (!spec.curves.empty() || std::any_of(spec.volconst.begin(), spec.volconst.end(),
                                            [](const std::optional<double>& v) { return v.has_value(); }))
        throw InvalidInput("cluster: a periodic cluster cannot have wire curves or volconst "
                           "(not supported)");
    for (std::size_t i = 0; i < spec.surfaces.size(); ++i) {
        const auto& s = spec.surfaces[i];
        if (!s.offsets.empty() && s.offsets.size() != s.triangles.size())
            throw InvalidInput("cluster: " + surface_name(static_cast<int>(i)) + " has " +
                               std::to_string(s.offsets.size()) + " offset triples for " +
                               std::to_string(s.triangles.size()) + " facets");
        for (std::size_t f = 0; f < s.offsets.size(); ++f)
            for (const Offset& k : s.offsets[f])
                for (int d : k)
                    if (std::abs(d) > kMaxOffset)
                        throw InvalidInput("cluster: " + surface_name(static_cast<int>(i)) +
                                           " facet " + std::to_string(f + 1) + " has the lattice "
                                           "offset " + std::to_string(d) + "; at most " +
                                           std::to_string(kMaxOffset) + " in magnitude");
    }
}

void Cluster::set_positions(std::vector<Vec3> X) {
    if (X.size() != X_.size()) throw InvalidInput("set_positions: wrong number of vertices");
    X_ = std::move(X);
}

void Cluster::set_sigma(int surface, double sigma) {
    if (surface < 0 || surface >= n_surfaces())
        throw InvalidInput("set_sigma: there is no surface " + std::to_string(surface + 1));
    if (!(std::isfinite(sigma) && sigma > 0))
        throw InvalidInput("set_sigma: " + surface_name(surface) + ": sigma must be positive, got " +
                           fmt(sigma));
    const double old = surfaces_[surface].sigma;
    surfaces_[surface].sigma = sigma;
    try {
        check_tension_triangles("set_sigma");
    } catch (const InvalidInput&) {
        surfaces_[surface].sigma = old; // nothing half-changed
        throw;
    }
    ++materials_revision_;
}

// Young's law at a triple line, sigma_1 nu_1 + sigma_2 nu_2 + sigma_3 nu_3 = 0 (seed (1.8)),
// has a solution with three distinct conormals only if each sigma is less than the sum of the
// other two; otherwise the film of the largest splits the line apart and the seed's schemes
// have no equilibrium to approach (its well-posedness assumes the strict inequality).
void Cluster::check_tension_triangles(const char* op) const {
    for (std::size_t k = 0; k < triple_lines_.size(); ++k) {
        const std::array<int, 3>& s = triple_lines_[k].surfaces;
        const double a = surfaces_[s[0]].sigma, b = surfaces_[s[1]].sigma, c = surfaces_[s[2]].sigma;
        if (a < b + c && b < a + c && c < a + b) continue;
        throw InvalidInput(std::string(op) + ": the tensions at triple line " +
                           std::to_string(k + 1) + " (surfaces " + std::to_string(s[0] + 1) +
                           ", " + std::to_string(s[1] + 1) + ", " + std::to_string(s[2] + 1) +
                           ": sigma " + fmt(a) + ", " + fmt(b) + ", " + fmt(c) +
                           ") break the triangle inequality: each must be less than the sum of "
                           "the other two, or no Young angle exists");
    }
}

void Cluster::set_anisotropy(int surface, std::shared_ptr<const Anisotropy> gamma) {
    if (surface < 0 || surface >= n_surfaces())
        throw InvalidInput("set_anisotropy: there is no surface " + std::to_string(surface + 1));
    surfaces_[surface].gamma = std::move(gamma);
    ++assembly_revision_, ++materials_revision_;
}

void Cluster::set_mobility(int surface, Mobility beta) {
    if (surface < 0 || surface >= n_surfaces())
        throw InvalidInput("set_mobility: there is no surface " + std::to_string(surface + 1));
    surfaces_[surface].beta = std::move(beta);
    ++materials_revision_;
}

bool Cluster::anisotropic() const {
    return std::any_of(surfaces_.begin(), surfaces_.end(),
                       [](const Surface& s) { return !s.isotropic(); });
}

bool Cluster::nonlinear() const {
    return std::any_of(surfaces_.begin(), surfaces_.end(),
                       [](const Surface& s) { return s.gamma && s.gamma->r() != 1.0; });
}

bool Cluster::has_mobilities() const {
    return std::any_of(surfaces_.begin(), surfaces_.end(),
                       [](const Surface& s) { return !s.beta.is_unit(); });
}

int Cluster::pair_index(int v, int s) const {
    for (int k = vs_start_[v]; k < vs_start_[v + 1]; ++k)
        if (vs_list_[k] == s) return k;
    return -1;
}

std::vector<int> Cluster::vertex_walls(int v) const {
    return {vw_list_.begin() + vw_start_[v], vw_list_.begin() + vw_start_[v + 1]};
}

const CurvePoint* Cluster::curve_point(int v) const {
    const auto it = std::lower_bound(curve_points_.begin(), curve_points_.end(), v,
                                     [](const CurvePoint& c, int id) { return c.vertex < id; });
    return it != curve_points_.end() && it->vertex == v ? &*it : nullptr;
}

void Cluster::check_curve_points(const ClusterSpec& spec) const {
    const int n = static_cast<int>(spec.vertices.size());
    std::vector<char> fixed(n, 0), seen(n, 0);
    for (int v : spec.fixed)
        if (v >= 0 && v < n) fixed[v] = 1;
    for (const CurvePtr& curve : spec.curves)
        if (!curve) throw InvalidInput("cluster: a curve is null");
    for (const CurvePoint& c : spec.curve_points) {
        if (c.vertex < 0 || c.vertex >= n || c.curve < 0 ||
            c.curve >= static_cast<int>(spec.curves.size()) || !std::isfinite(c.p))
            throw InvalidInput("cluster: the curve point of vertex " + std::to_string(c.vertex + 1) +
                               " on curve " + std::to_string(c.curve + 1) +
                               " is out of range or its parameter is not finite");
        const std::string who = vertex_name(c.vertex) + " on curve '" +
                                spec.curves[c.curve]->name() + "'";
        if (seen[c.vertex]++) throw InvalidInput("cluster: " + who + " is on two curves");
        if (!fixed[c.vertex])
            throw InvalidInput("cluster: " + who + " must be fixed (froth holds wire vertices; "
                               "the curve places the midpoints of refined wire edges)");
        const Vec3& x = spec.vertices[c.vertex];
        const double d = (spec.curves[c.curve]->point(c.p) - x).norm();
        if (!(d <= 1e-9 * (1 + x.norm())))
            throw InvalidInput("cluster: " + who + " is at distance " + fmt(d) +
                               " from the curve's point at p = " + fmt(c.p));
    }
}

std::vector<std::array<int, 2>> Cluster::wall_attachments() const {
    std::vector<std::array<int, 2>> pairs;
    for (int v = 0; v < n_vertices(); ++v)
        for (int k = vw_start_[v]; k < vw_start_[v + 1]; ++k)
            pairs.push_back({v, vw_list_[k]});
    return pairs;
}

std::vector<int> Cluster::vertex_junction_edges(int v) const {
    return {vj_list_.begin() + vj_start_[v], vj_list_.begin() + vj_start_[v + 1]};
}

} // namespace froth
