#include "assembly/flow_systems.h"

namespace froth {

Eigen::Matrix3d local_stiffness(const Vec3& x0, const Vec3& x1, const Vec3& x2) {
    const Vec3 e[3] = {x2 - x1, x0 - x2, x1 - x0};
    const double four_area = 2.0 * (x1 - x0).cross(x2 - x0).norm();
    Eigen::Matrix3d K;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b) K(a, b) = e[a].dot(e[b]) / four_area;
    return K;
}

namespace {

/// Calls f(surface, triangle, K) with the local stiffness of every facet.
template <class F> void for_each_facet(const Cluster& c, F&& f) {
    const auto& X = c.positions();
    for (int i = 0; i < c.n_surfaces(); ++i)
        for (const Tri& t : c.surface(i).triangles)
            f(i, t, local_stiffness(X[t[0]], X[t[1]], X[t[2]]));
}

/// T^T A T: the sigma-weighted vector stiffness in the position block, which starts at (0, 0).
void add_position_stiffness(const Cluster& c, const PositionBasis& P, SparseBuilder& M) {
    for_each_facet(c, [&](int i, const Tri& t, const Eigen::Matrix3d& K) {
        const double sigma = c.surface(i).sigma;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) P.add_scaled_identity(M, t[a], t[b], sigma * K(a, b));
    });
}

void set_minus_AX(const Cluster& c, const PositionBasis& P, Eigen::VectorXd& rhs) {
    rhs.head(P.size()) = -P.restrict(apply_stiffness(c, c.positions()));
}

} // namespace

Eigen::VectorXd apply_stiffness(const Cluster& c, const std::vector<Vec3>& X) {
    Eigen::VectorXd y = Eigen::VectorXd::Zero(3 * c.n_vertices());
    for_each_facet(c, [&](int i, const Tri& t, const Eigen::Matrix3d& K) {
        const double sigma = c.surface(i).sigma;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b) y.segment<3>(3 * t[a]) += sigma * K(a, b) * X[t[b]];
    });
    return y;
}

void assemble_mcf(const Cluster& c, const PairGeometry& g, const PositionBasis& P, double tau,
                  SparseBuilder& M, Eigen::VectorXd& rhs) {
    const int n = P.size();
    M.begin(n, n);
    add_position_stiffness(c, P, M);
    // (4.6b): kappa_iv = omega_iv . dX_v / tau, so (3.5b) gains m_iv omega_iv omega_iv^T / tau.
    for (int v = 0; v < c.n_vertices(); ++v) {
        Eigen::Matrix3d B = Eigen::Matrix3d::Zero();
        for (int k = c.pair_begin(v); k < c.pair_begin(v + 1); ++k)
            B += g.mass[k] * g.omega[k] * g.omega[k].transpose();
        P.add_block(M, v, v, B / tau);
    }
    M.finish();
    rhs.resize(n);
    set_minus_AX(c, P, rhs);
}

void assemble_sd(const Cluster& c, const PairGeometry& g, const KappaBasis& Z,
                 const PositionBasis& P, double tau, SparseBuilder& M, Eigen::VectorXd& rhs) {
    const int n = P.size(), size = n + Z.n_reduced;
    M.begin(size, size);
    add_position_stiffness(c, P, M);
    // -tau Z^T A_s Z: the scalar stiffness of each surface on its kappa pairs, through Z. (3.6a)
    for_each_facet(c, [&](int i, const Tri& t, const Eigen::Matrix3d& K) {
        int p[3];
        for (int a = 0; a < 3; ++a) p[a] = c.pair_index(t[a], i);
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                for (int x = Z.start[p[a]]; x < Z.start[p[a] + 1]; ++x)
                    for (int y = Z.start[p[b]]; y < Z.start[p[b] + 1]; ++y)
                        M.add(n + Z.col[x], n + Z.col[y], -tau * K(a, b) * Z.val[x] * Z.val[y]);
    });
    // N Z and its transpose: <kappa nu, eta>^h = m_iv kappa_iv omega_iv . eta_v (3.6b).
    for (int v = 0; v < c.n_vertices(); ++v)
        for (int k = c.pair_begin(v); k < c.pair_begin(v + 1); ++k)
            for (int x = Z.start[k]; x < Z.start[k + 1]; ++x)
                P.add_column_pair(M, v, n + Z.col[x], g.mass[k] * Z.val[x] * g.omega[k]);
    M.finish();
    rhs = Eigen::VectorXd::Zero(size);
    set_minus_AX(c, P, rhs);
}

} // namespace froth
