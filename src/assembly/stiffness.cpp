// Stiffness assembly on a whole cluster (stiffness.h) from the element kernels of elements.h.
#include "assembly/stiffness.h"

namespace froth {

void add_position_stiffness(const Cluster& c, const PositionBasis& P, const FacetNormals* lagged,
                            SparseBuilder& M) {
    for_each_element(
        c, lagged,
        [&](const Tri& t, const Eigen::Matrix3d& K) {
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b)
                    P.add_scaled_identity(M, t[a], t[b], K(a, b));
        },
        [&](const Tri& t, const ElementMatrix& E) {
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b)
                    P.add_block(M, t[a], t[b], E.block<3, 3>(3 * a, 3 * b));
        });
}

void set_minus_stiffness_rhs(const Cluster& c, const PositionBasis& P, const FacetNormals* lagged,
                             Eigen::VectorXd& rhs) {
    rhs.head(P.size()) = -P.restrict(apply_stiffness(c, c.positions(), lagged));
}

namespace {

/// y = A_gamma Y over the facets' corners: Y_v, plus the corner's lattice shift when Y holds
/// positions (a periodic cluster's facets reach across the box), not when it is a motion.
Eigen::VectorXd stiffness_times(const Cluster& c, const std::vector<Vec3>& Y,
                                const FacetNormals* lagged, bool positions) {
    Eigen::VectorXd y = Eigen::VectorXd::Zero(3 * c.n_vertices());
    const auto corner = [&](const Tri& t, const std::array<Vec3, 3>& shift, int b) -> Vec3 {
        return positions ? Vec3(Y[t[b]] + shift[b]) : Y[t[b]];
    };
    for_each_element(
        c, lagged,
        [&](const Tri& t, const Eigen::Matrix3d& K, const std::array<Vec3, 3>& shift) {
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b)
                    y.segment<3>(3 * t[a]) += K(a, b) * corner(t, shift, b);
        },
        [&](const Tri& t, const ElementMatrix& E, const std::array<Vec3, 3>& shift) {
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b)
                    y.segment<3>(3 * t[a]) += E.block<3, 3>(3 * a, 3 * b) * corner(t, shift, b);
        });
    return y;
}

} // namespace

Eigen::VectorXd apply_stiffness(const Cluster& c, const std::vector<Vec3>& X,
                                const FacetNormals* lagged) {
    return stiffness_times(c, X, lagged, true);
}

Eigen::VectorXd apply_stiffness_to_motion(const Cluster& c, const std::vector<Vec3>& D,
                                          const FacetNormals* lagged) {
    return stiffness_times(c, D, lagged, false);
}

void assemble_weight_jacobian(const Cluster& c, const PositionBasis& P, const std::vector<Vec3>& X,
                              int size, SparseBuilder& M) {
    M.begin(size, size);
    const auto& Xm = c.positions();
    for (int i = 0; i < c.n_surfaces(); ++i) {
        const Surface& s = c.surface(i);
        if (s.isotropic() || s.gamma->r() == 1.0) continue;
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const Tri& t = s.triangles[f];
            const ElementMatrix C =
                s.sigma * weight_jacobian(*s.gamma, s.corners(Xm, f), s.corners(X, f));
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b)
                    P.add_block(M, t[a], t[b], C.block<3, 3>(3 * a, 3 * b));
        }
    }
    M.finish();
}

Eigen::VectorXd stiffness_diagonal(const Cluster& c) {
    Eigen::VectorXd d = Eigen::VectorXd::Zero(c.n_vertices());
    for_each_facet(c, [&](int i, const Tri& t, const Eigen::Matrix3d& K) {
        const double w = isotropic_weight(c.surface(i));
        for (int a = 0; a < 3; ++a)
            d[t[a]] += w * K(a, a);
    });
    return d;
}

void assemble_scalar_stiffness(const Cluster& c, const Eigen::VectorXd& diagonal,
                               SparseBuilder& M) {
    M.begin(c.n_vertices(), c.n_vertices());
    const auto& X = c.positions();
    for (const Surface& s : c.surfaces()) {
        const double w = isotropic_weight(s);
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const Tri& t = s.triangles[f];
            const auto x = s.corners(X, f);
            const Eigen::Matrix3d K = w * local_stiffness(x[0], x[1], x[2]);
            for (int a = 0; a < 3; ++a)
                for (int b = 0; b < 3; ++b)
                    M.add(t[a], t[b], K(a, b));
        }
    }
    for (int v = 0; v < c.n_vertices(); ++v)
        M.add(v, v, diagonal[v]);
    M.finish();
}

} // namespace froth
