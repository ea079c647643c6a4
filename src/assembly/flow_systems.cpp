#include "assembly/flow_systems.h"

#include <cmath>

namespace froth {

Eigen::Matrix3d local_stiffness(const Vec3& x0, const Vec3& x1, const Vec3& x2) {
    const Vec3 e[3] = {x2 - x1, x0 - x2, x1 - x0};
    const double four_area = 2.0 * (x1 - x0).cross(x2 - x0).norm();
    Eigen::Matrix3d K;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) K(a, b) = e[a].dot(e[b]) / four_area;
    return K;
}

FacetNormals facet_normals(const Cluster& c, const std::vector<Vec3>& X) {
    FacetNormals nu(c.n_surfaces());
    for (int i = 0; i < c.n_surfaces(); ++i)
        for (const Tri& t : c.surface(i).triangles) nu[i].push_back(area_vector2(X, t).normalized());
    return nu;
}

namespace {

/// Calls f(surface, triangle, K) with the scalar P1 stiffness of every facet.
template <class F> void for_each_facet(const Cluster& c, F&& f) {
    const auto& X = c.positions();
    for (int i = 0; i < c.n_surfaces(); ++i)
        for (const Tri& t : c.surface(i).triangles)
            f(i, t, local_stiffness(X[t[0]], X[t[1]], X[t[2]]));
}

/// The tension of an isotropic surface: sigma, times s for gamma = s |.|.
double isotropic_weight(const Surface& s) {
    return s.gamma ? s.sigma * std::sqrt(s.gamma->G(0)(0, 0)) : s.sigma;
}

/// The stiffness of every facet: iso(t, w K) on isotropic surfaces (w K times I_3), and
/// aniso(t, M) with M the sigma-scaled 9x9 element matrix of (3.9) on the others, its r > 1
/// weights taken at the lagged normals.
template <class Iso, class Aniso>
void for_each_element(const Cluster& c, const FacetNormals* lagged, Iso&& iso, Aniso&& aniso) {
    const auto& X = c.positions();
    for (int i = 0; i < c.n_surfaces(); ++i) {
        const Surface& s = c.surface(i);
        if (s.isotropic()) {
            const double w = isotropic_weight(s);
            for (const Tri& t : s.triangles) iso(t, w * local_stiffness(X[t[0]], X[t[1]], X[t[2]]));
            continue;
        }
        const bool lag = s.gamma->r() != 1.0 && lagged && !(*lagged)[i].empty();
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const Tri& t = s.triangles[f];
            const std::array<Vec3, 3> x = {X[t[0]], X[t[1]], X[t[2]]};
            const Vec3 nu = lag ? (*lagged)[i][f] : area_vector2(X, t).normalized();
            aniso(t, s.sigma * element_matrix(*s.gamma, x, nu));
        }
    }
}

/// T^T A_gamma T in the position block, which starts at (0, 0).
void add_position_stiffness(const Cluster& c, const PositionBasis& P, const FacetNormals* lagged,
                            SparseBuilder& M) {
    for_each_element(
        c, lagged,
        [&](const Tri& t, const Eigen::Matrix3d& K) {
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b) P.add_scaled_identity(M, t[a], t[b], K(a, b));
        },
        [&](const Tri& t, const ElementMatrix& E) {
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b)
                    P.add_block(M, t[a], t[b], E.block<3, 3>(3 * a, 3 * b));
        });
}

void set_minus_AX(const Cluster& c, const PositionBasis& P, const FacetNormals* lagged,
                  Eigen::VectorXd& rhs) {
    rhs.head(P.size()) = -P.restrict(apply_stiffness(c, c.positions(), lagged));
}

} // namespace

Eigen::VectorXd apply_stiffness(const Cluster& c, const std::vector<Vec3>& X,
                                const FacetNormals* lagged) {
    Eigen::VectorXd y = Eigen::VectorXd::Zero(3 * c.n_vertices());
    for_each_element(
        c, lagged,
        [&](const Tri& t, const Eigen::Matrix3d& K) {
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b) y.segment<3>(3 * t[a]) += K(a, b) * X[t[b]];
        },
        [&](const Tri& t, const ElementMatrix& E) {
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b)
                    y.segment<3>(3 * t[a]) += E.block<3, 3>(3 * a, 3 * b) * X[t[b]];
        });
    return y;
}

void assemble_weight_jacobian(const Cluster& c, const PositionBasis& P, const std::vector<Vec3>& X,
                              int size, SparseBuilder& M) {
    M.begin(size, size);
    const auto& Xm = c.positions();
    for (int i = 0; i < c.n_surfaces(); ++i) {
        const Surface& s = c.surface(i);
        if (s.isotropic() || s.gamma->r() == 1.0) continue;
        for (const Tri& t : s.triangles) {
            const ElementMatrix C =
                s.sigma * weight_jacobian(*s.gamma, {Xm[t[0]], Xm[t[1]], Xm[t[2]]},
                                          {X[t[0]], X[t[1]], X[t[2]]});
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b)
                    P.add_block(M, t[a], t[b], C.block<3, 3>(3 * a, 3 * b));
        }
    }
    M.finish();
}

void assemble_scalar_stiffness(const Cluster& c, const Eigen::VectorXd& diagonal, SparseBuilder& M) {
    M.begin(c.n_vertices(), c.n_vertices());
    const auto& X = c.positions();
    for (const Surface& s : c.surfaces()) {
        const double w = isotropic_weight(s);
        for (const Tri& t : s.triangles) {
            const Eigen::Matrix3d K = w * local_stiffness(X[t[0]], X[t[1]], X[t[2]]);
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b) M.add(t[a], t[b], K(a, b));
        }
    }
    for (int v = 0; v < c.n_vertices(); ++v) M.add(v, v, diagonal[v]);
    M.finish();
}

void assemble_mcf(const Cluster& c, const PairGeometry& g, const PositionBasis& P, double tau,
                  const FacetNormals* lagged, SparseBuilder& M, Eigen::VectorXd& rhs) {
    const int n = P.size();
    M.begin(n, n);
    add_position_stiffness(c, P, lagged, M);
    // (4.6b): kappa_iv = m_iv omega_iv . dX_v / (tau mb_iv) from the lumped (3.7a), so (3.7b)
    // gains m_iv^2 / mb_iv omega_iv omega_iv^T / tau (mb = m for beta = 1).
    const bool beta = !g.mass_beta.empty();
    for (int v = 0; v < c.n_vertices(); ++v) {
        Eigen::Matrix3d B = Eigen::Matrix3d::Zero();
        for (int k = c.pair_begin(v); k < c.pair_begin(v + 1); ++k) {
            const double m = beta ? g.mass[k] * g.mass[k] / g.mass_beta[k] : g.mass[k];
            B += m * g.omega[k] * g.omega[k].transpose();
        }
        P.add_block(M, v, v, B / tau);
    }
    M.finish();
    rhs.resize(n);
    set_minus_AX(c, P, lagged, rhs);
}

void assemble_sd(const Cluster& c, const PairGeometry& g, const KappaBasis& Z,
                 const PositionBasis& P, double tau, const FacetNormals* lagged,
                 SparseBuilder& M, Eigen::VectorXd& rhs) {
    const int n = P.size(), size = n + Z.n_reduced;
    M.begin(size, size);
    add_position_stiffness(c, P, lagged, M);
    // -tau Z^T A_beta Z: the scalar stiffness of each surface, weighted by beta_i(nu_sigma), on
    // its kappa pairs, through Z. (3.8a)
    std::vector<int> facet(c.n_surfaces(), 0);
    for_each_facet(c, [&](int i, const Tri& t, const Eigen::Matrix3d& K) {
        const double beta = g.facet_beta.empty() ? 1.0 : g.facet_beta[i][facet[i]];
        ++facet[i];
        int p[3];
        for (int a = 0; a < 3; ++a) p[a] = c.pair_index(t[a], i);
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                for (int x = Z.start[p[a]]; x < Z.start[p[a] + 1]; ++x)
                    for (int y = Z.start[p[b]]; y < Z.start[p[b] + 1]; ++y)
                        M.add(n + Z.col[x], n + Z.col[y],
                              -tau * beta * K(a, b) * Z.val[x] * Z.val[y]);
    });
    // N Z and its transpose: <kappa nu, eta>^h = m_iv kappa_iv omega_iv . eta_v (3.8b).
    for (int v = 0; v < c.n_vertices(); ++v)
        for (int k = c.pair_begin(v); k < c.pair_begin(v + 1); ++k)
            for (int x = Z.start[k]; x < Z.start[k + 1]; ++x)
                P.add_column_pair(M, v, n + Z.col[x], g.mass[k] * Z.val[x] * g.omega[k]);
    M.finish();
    rhs = Eigen::VectorXd::Zero(size);
    set_minus_AX(c, P, lagged, rhs);
}

} // namespace froth
