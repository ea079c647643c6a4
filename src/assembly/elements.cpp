// The element kernels (elements.h): P1 stiffness, the anisotropic element matrices of
// (1.24a,b)/(3.9) and their Newton correction.
#include "assembly/elements.h"

#include "core/errors.h"
#include "core/format.h"

namespace froth {

using Eigen::Matrix3d;
using Eigen::Vector3d;

Eigen::Matrix3d local_stiffness(const Vec3& x0, const Vec3& x1, const Vec3& x2) {
    const Vec3 e[3] = {x2 - x1, x0 - x2, x1 - x0};
    const double four_area = 2.0 * (x1 - x0).cross(x2 - x0).norm();
    Eigen::Matrix3d K;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            K(a, b) = e[a].dot(e[b]) / four_area;
    return K;
}

FacetNormals facet_normals(const Cluster& c, const std::vector<Vec3>& X) {
    FacetNormals nu(c.n_surfaces());
    for (int i = 0; i < c.n_surfaces(); ++i)
        for (std::size_t f = 0; f < c.surface(i).triangles.size(); ++f)
            nu[i].push_back(area_vector2(c.surface(i).corners(X, f)).normalized());
    return nu;
}

double element_energy(const Anisotropy& gamma, const std::array<Vector3d, 3>& x) {
    const Vector3d n = (x[1] - x[0]).cross(x[2] - x[0]); // 2 |sigma| nu
    return 0.5 * gamma.gamma(n);
}

namespace {

/// Twice the area vector (x1 - x0) x (x2 - x0) of a triangle; throws for a degenerate one.
Vector3d doubled_area_vector(const std::array<Vector3d, 3>& x) {
    const Vector3d n = (x[1] - x[0]).cross(x[2] - x[0]);
    if (!(n.norm() > 0.0) || !n.allFinite())
        throw GeometryError("anisotropy: element matrix of a degenerate triangle");
    return n;
}

/// The edges opposite each vertex, traversed cyclically.
std::array<Vector3d, 3> opposite_edges(const std::array<Vector3d, 3>& x) {
    return {x[2] - x[1], x[0] - x[2], x[1] - x[0]};
}

/// The unweighted matrix of term l: K^(l) (x) Gt_l (see element_matrix).
ElementMatrix term_matrix(const Anisotropy& gamma, int l, const std::array<Vector3d, 3>& e,
                          const Vector3d& n) {
    const Matrix3d& Gt = gamma.G_tilde(l);
    // A_Gt = 1/2 sqrt((e1,e1)(e2,e2) - (e1,e2)^2)_Gt = 1/2 sqrt(n . G n) = gamma_l(nu)|sigma|,
    // evaluated in the cancellation-free second form.
    const double A = 0.5 * gamma.gamma_term(l, n);
    ElementMatrix M;
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            M.block<3, 3>(3 * a, 3 * b) = (e[a].dot(Gt * e[b]) / (4.0 * A)) * Gt;
    return M;
}

} // namespace

ElementMatrix element_matrix(const Anisotropy& gamma, const std::array<Vector3d, 3>& x,
                             const Vector3d& nu_star) {
    const Vector3d n = doubled_area_vector(x);
    const std::array<Vector3d, 3> e = opposite_edges(x);
    const std::vector<double> w = gamma.term_weights(nu_star);
    ElementMatrix M = ElementMatrix::Zero();
    for (int l = 0; l < gamma.n_terms(); ++l)
        M += w[l] * term_matrix(gamma, l, e, n);
    return M;
}

ElementMatrix weight_jacobian(const Anisotropy& gamma, const std::array<Vector3d, 3>& x,
                              const std::array<Vector3d, 3>& y) {
    ElementMatrix C = ElementMatrix::Zero();
    if (gamma.r() == 1.0) return C;
    const Vector3d n = doubled_area_vector(x), n_new = doubled_area_vector(y);
    const std::array<Vector3d, 3> e = opposite_edges(x), e_new = opposite_edges(y);
    const std::vector<Vector3d> dw = gamma.term_weight_gradients(n_new);
    Eigen::Matrix<double, 9, 1> Y, b;
    for (int a = 0; a < 3; ++a)
        Y.segment<3>(3 * a) = y[a];
    for (int l = 0; l < gamma.n_terms(); ++l) {
        // d(n_new . g)/dy_a = g x e_new_a for a fixed g, so dw_l/dy_a = dw_l/dn x e_new_a.
        for (int a = 0; a < 3; ++a)
            b.segment<3>(3 * a) = dw[l].cross(e_new[a]);
        C += (term_matrix(gamma, l, e, n) * Y) * b.transpose();
    }
    return C;
}

ElementMatrix element_matrix(const Anisotropy& gamma, const std::array<Vector3d, 3>& x) {
    if (gamma.r() != 1.0)
        throw InvalidInput("anisotropy: r = " + fmt(gamma.r()) +
                           " needs the lagged element matrix (give nu*)");
    return element_matrix(gamma, x, Vector3d::UnitZ());
}

} // namespace froth
