#include "geometry/geometry.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <string>

namespace froth {

std::pair<int, int> find_degenerate_facet(const Cluster& c, const std::vector<Vec3>& X) {
    for (int i = 0; i < c.n_surfaces(); ++i) {
        const Surface& s = c.surface(i);
        for (int f = 0; f < static_cast<int>(s.triangles.size()); ++f) {
            const auto x = s.corners(X, f);
            const double scale = (x[1] - x[0]).squaredNorm() + (x[2] - x[0]).squaredNorm();
            if (!(area_vector2(x).norm() > 1e-12 * scale)) return {i, f};
        }
    }
    return {-1, -1};
}

std::string facet_name(int surface, int facet) {
    return "facet " + std::to_string(facet + 1) + " of surface " + std::to_string(surface + 1);
}

void project_onto_walls_of(const Cluster& c, std::vector<Vec3>& X) {
    for (int v = 0; v < c.n_vertices(); ++v) {
        const std::vector<int> walls = c.vertex_walls(v);
        for (int pass = 0; pass < (walls.size() > 1 ? 20 : 1); ++pass)
            for (int w : walls) X[v] = c.walls()[w]->project(X[v]);
    }
}

std::vector<double> surface_areas(const Cluster& c) {
    std::vector<double> areas(c.n_surfaces(), 0.0);
    for (int i = 0; i < c.n_surfaces(); ++i)
        for (std::size_t f = 0; f < c.surface(i).triangles.size(); ++f)
            areas[i] += 0.5 * area_vector2(c.surface(i).corners(c.positions(), f)).norm();
    return areas;
}

double energy(const Cluster& c) {
    // E_gamma = sum_i sum_sigma sigma_i gamma_i(nu_sigma) |sigma|, with gamma 1-homogeneous.
    double e = 0;
    for (const Surface& s : c.surfaces())
        for (std::size_t f = 0; f < s.triangles.size(); ++f)
            e += 0.5 * s.density(area_vector2(s.corners(c.positions(), f)));
    return e;
}

std::vector<double> body_volumes(const Cluster& c) { return body_volumes(c, c.positions()); }

std::vector<double> body_volumes(const Cluster& c, const std::vector<Vec3>& X) {
    std::vector<double> volumes;
    for (const Body& b : c.bodies()) volumes.push_back(body_volume(c, b, X));
    return volumes;
}

namespace {
double max_relative_deviation(const std::vector<double>& volumes, const std::vector<double>& ref) {
    double e = 0;
    for (std::size_t b = 0; b < volumes.size(); ++b)
        e = std::max(e, std::abs(volumes[b] - ref[b]) / ref[b]);
    return e;
}
} // namespace

double max_volume_loss(const Cluster& c, const std::vector<double>& volumes) {
    return max_relative_deviation(volumes, c.initial_volumes());
}

double max_target_deviation(const Cluster& c, const std::vector<double>& volumes) {
    return max_relative_deviation(volumes, c.target_volumes());
}

namespace {

/// beta_i(nu_sigma) per facet and the lumped <beta(nu^m) ., .>^h masses of (3.7a)/(3.8a).
void add_mobilities(const Cluster& c, PairGeometry& g) {
    g.facet_beta.resize(c.n_surfaces());
    g.mass_beta.assign(c.n_pairs(), 0.0);
    for (int i = 0; i < c.n_surfaces(); ++i) {
        const Surface& s = c.surface(i);
        const std::string where = "surface " + std::to_string(i + 1);
        g.facet_beta[i].resize(s.triangles.size());
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const Vec3 a2 = area_vector2(s.corners(c.positions(), f));
            const double beta = s.beta(a2.normalized(), s.sigma, s.gamma.get(), where);
            g.facet_beta[i][f] = beta;
            for (int v : s.triangles[f]) g.mass_beta[c.pair_index(v, i)] += beta * a2.norm() / 6;
        }
    }
}

} // namespace

PairGeometry pair_geometry(const Cluster& c) {
    PairGeometry g;
    g.mass.assign(c.n_pairs(), 0.0);
    g.omega.assign(c.n_pairs(), Vec3::Zero());
    for (int i = 0; i < c.n_surfaces(); ++i)
        for (std::size_t f = 0; f < c.surface(i).triangles.size(); ++f) {
            const Tri& t = c.surface(i).triangles[f];
            const Vec3 a2 = area_vector2(c.surface(i).corners(c.positions(), f)); // 2 |sigma| nu
            const double area = 0.5 * a2.norm();
            for (int v : t) {
                const int k = c.pair_index(v, i);
                g.mass[k] += area / 3.0;
                g.omega[k] += 0.5 * a2;
            }
        }
    for (int k = 0; k < c.n_pairs(); ++k) g.omega[k] /= 3.0 * g.mass[k];
    if (c.has_mobilities()) add_mobilities(c, g);
    return g;
}

Eigen::VectorXd vertex_masses(const Cluster& c, const PairGeometry& g) {
    Eigen::VectorXd m = Eigen::VectorXd::Zero(c.n_vertices());
    for (int v = 0; v < c.n_vertices(); ++v)
        for (int k = c.pair_begin(v); k < c.pair_begin(v + 1); ++k)
            m[v] += g.mass[k];
    return m;
}

Vec3 line_direction(const Cluster& c, const PairGeometry& g, int v) {
    const int surfaces = c.pair_begin(v + 1) - c.pair_begin(v);
    if (surfaces < 2 || surfaces > 3) return Vec3::Zero();
    Eigen::Matrix3d B = Eigen::Matrix3d::Zero();
    for (int k = c.pair_begin(v); k < c.pair_begin(v + 1); ++k)
        B += g.mass[k] * g.omega[k] * g.omega[k].transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(B); // eigenvalues increasing
    return eig.eigenvectors().col(0);
}

MeshQuality mesh_quality(const Cluster& c) {
    const auto& X = c.positions();
    MeshQuality q;
    q.min_angle = 180;
    q.min_area = INFINITY;
    for (const Surface& s : c.surfaces())
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const auto x = s.corners(X, f);
            double len[3];
            for (int k = 0; k < 3; ++k) {
                const Vec3 u = x[(k + 1) % 3] - x[k];
                const Vec3 w = x[(k + 2) % 3] - x[k];
                const double angle = std::atan2(u.cross(w).norm(), u.dot(w)) * 180.0 / M_PI;
                q.min_angle = std::min(q.min_angle, angle);
                q.max_angle = std::max(q.max_angle, angle);
                len[k] = u.norm();
            }
            const auto [lo, hi] = std::minmax({len[0], len[1], len[2]});
            q.max_edge_ratio = std::max(q.max_edge_ratio, hi / lo);
            q.min_area = std::min(q.min_area, 0.5 * area_vector2(x).norm());
        }
    return q;
}

std::vector<double> vertex_mean_curvature(const Cluster& c) {
    // The area gradient at a vertex is the discrete mean curvature vector times its mass:
    // d|sigma|/dx_a = 1/2 nu x (x_c - x_b) for the facet (a, b, c).
    const auto& X = c.positions();
    std::vector<Vec3> grad(c.n_vertices(), Vec3::Zero()), normal(c.n_vertices(), Vec3::Zero());
    std::vector<double> mass(c.n_vertices(), 0.0);
    std::vector<int> owner(c.n_vertices(), -1);
    for (int i = 0; i < c.n_surfaces(); ++i)
        for (int v : c.surface(i).vertices)
            if (owner[v] < 0) owner[v] = i;
    for (int i = 0; i < c.n_surfaces(); ++i)
        for (std::size_t f = 0; f < c.surface(i).triangles.size(); ++f) {
            const Tri& t = c.surface(i).triangles[f];
            const auto x = c.surface(i).corners(X, f);
            const Vec3 a2 = area_vector2(x);
            const Vec3 nu = a2.normalized();
            for (int k = 0; k < 3; ++k) {
                const int v = t[k];
                if (owner[v] != i) continue;
                grad[v] += 0.5 * nu.cross(x[(k + 2) % 3] - x[(k + 1) % 3]);
                normal[v] += 0.5 * a2;
                mass[v] += a2.norm() / 6.0;
            }
        }
    std::vector<double> H(c.n_vertices(), 0.0);
    for (int v = 0; v < c.n_vertices(); ++v)
        if (mass[v] > 0) H[v] = grad[v].dot(normal[v].normalized()) / mass[v];
    return H;
}

} // namespace froth
