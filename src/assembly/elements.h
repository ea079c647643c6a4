#pragma once
/// The element kernels of every scheme, on one triangle (x0, x1, x2) of a surface:
///   P1 stiffness (isotropic):  K_ab = (e_a . e_b) / (4 |sigma|), so K X = grad |sigma|   (3.5b)
///   anisotropic (1.24a,b):     sum_l w_l K^(l) (x) Gt_l, the matrix of
///                              <nabla_s^Gt X, nabla_s^Gt chi>_gamma, lagged weights for r > 1
///                              (3.9)
///   Newton correction (3.9):   the derivative of those weights (weight_jacobian)
/// and the loops that visit every facet of a cluster with its sigma-scaled element matrix.
/// Everything that assembles a stiffness (assembly/stiffness.h, the schemes, minimize) goes
/// through these.

#include "anisotropy/anisotropy.h"
#include "geometry/geometry.h"

#include <Eigen/Core>

#include <array>
#include <cmath>
#include <type_traits>
#include <vector>

namespace froth {

/// P1 stiffness of one triangle: K_ab = (e_a . e_b) / (4 |sigma|), e_a the edge opposite a,
/// traversed cyclically. Symmetric, rows sum to zero, and K X = gradient of the area.
Eigen::Matrix3d local_stiffness(const Vec3& x0, const Vec3& x1, const Vec3& x2);

using ElementMatrix = Eigen::Matrix<double, 9, 9>;

/// Discrete energy of one triangle (x0, x1, x2), E = gamma(nu) |sigma| with nu |sigma| =
/// (x1 - x0) x (x2 - x0) / 2 (the normal from the vertex order).
double element_energy(const Anisotropy& gamma, const std::array<Eigen::Vector3d, 3>& x);

/// The element matrix of <nabla_s^Gt ., nabla_s^Gt .>_gamma (1.24a,b) on one triangle, rows and
/// columns 3a + d (vertex a, coordinate d): sum_l w_l K^(l) (x) Gt_l, where
/// K^(l)_ab = (e_a, e_b)_Gt_l / (4 A_l), e_a the edge opposite vertex a (cyclic:
/// e_0 = x2 - x1, e_1 = x0 - x2, e_2 = x1 - x0), A_l = 1/2 sqrt((e1,e1)(e2,e2) - (e1,e2)^2)
/// in the Gt_l inner product (= gamma_l(nu) |sigma|), and w_l = [gamma_l(nu*)/gamma(nu*)]^(r-1)
/// the lagged weights at the given normal nu_star (ignored, all 1, for r = 1).
/// For r = 1, or nu_star the triangle's own normal, M X = grad of element_energy.
/// Throws GeometryError for a degenerate triangle.
ElementMatrix element_matrix(const Anisotropy& gamma, const std::array<Eigen::Vector3d, 3>& x,
                             const Eigen::Vector3d& nu_star);
/// The derivative of the weights for Newton's method on (3.9): with M(y) =
/// element_matrix(gamma, x, nu(y)) (x the triangle on Gamma^m, y the same triangle at a new
/// iterate, nu(y) its normal), d/dy [M(y) y] = M(y) + weight_jacobian(gamma, x, y), and
/// weight_jacobian = sum_l (M_l y) (dw_l/dy)^T with M_l the unweighted term matrices. Not
/// symmetric; zero for r = 1. Throws GeometryError for a degenerate x or y.
ElementMatrix weight_jacobian(const Anisotropy& gamma, const std::array<Eigen::Vector3d, 3>& x,
                              const std::array<Eigen::Vector3d, 3>& y);
/// r = 1 form (weights 1); throws InvalidInput for r != 1 (use the lagged form).
ElementMatrix element_matrix(const Anisotropy& gamma, const std::array<Eigen::Vector3d, 3>& x);

/// The normals nu^{m+1} at which (3.9) weighs the terms of an r > 1 anisotropy, per surface and
/// facet (the current iterate of the r > 1 iteration, numerics.md §5). Surfaces with r = 1
/// ignore them; null (or an empty entry) means each facet's own normal on X^m.
using FacetNormals = std::vector<std::vector<Vec3>>;

/// Unit facet normals of the cluster's surfaces at positions X.
FacetNormals facet_normals(const Cluster& c, const std::vector<Vec3>& X);

/// The tension of an isotropic surface: sigma, times s for gamma = s |.|.
inline double isotropic_weight(const Surface& s) {
    return s.gamma ? s.sigma * std::sqrt(s.gamma->G(0)(0, 0)) : s.sigma;
}

/// g(t, M) or, if it takes them, g(t, M, shifts): the facet's corner shifts (all zero outside
/// a periodic cluster).
template <class G, class M> void call_element(G& g, const Surface& s, std::size_t f, const M& m) {
    if constexpr (std::is_invocable_v<G&, const Tri&, const M&, const std::array<Vec3, 3>&>) {
        static const std::array<Vec3, 3> none = {Vec3::Zero(), Vec3::Zero(), Vec3::Zero()};
        g(s.triangles[f], m, s.shifts.empty() ? none : s.shifts[f]);
    } else {
        g(s.triangles[f], m);
    }
}

/// Calls f(surface, triangle, K) with the scalar P1 stiffness of every facet.
template <class F> void for_each_facet(const Cluster& c, F&& f) {
    const auto& X = c.positions();
    for (int i = 0; i < c.n_surfaces(); ++i) {
        const Surface& s = c.surface(i);
        for (std::size_t k = 0; k < s.triangles.size(); ++k) {
            const auto x = s.corners(X, k);
            f(i, s.triangles[k], local_stiffness(x[0], x[1], x[2]));
        }
    }
}

/// The stiffness of every facet: iso(t, w K) on isotropic surfaces (w K times I_3), and
/// aniso(t, M) with M the sigma-scaled 9x9 element matrix of (3.9) on the others, its r > 1
/// weights taken at the lagged normals. Both may take a third argument, the facet's corner
/// shifts (zero but in a periodic cluster, Surface::shifts), for what they apply to positions.
template <class Iso, class Aniso>
void for_each_element(const Cluster& c, const FacetNormals* lagged, Iso&& iso, Aniso&& aniso) {
    const auto& X = c.positions();
    for (int i = 0; i < c.n_surfaces(); ++i) {
        const Surface& s = c.surface(i);
        if (s.isotropic()) {
            const double w = isotropic_weight(s);
            for (std::size_t f = 0; f < s.triangles.size(); ++f) {
                const auto x = s.corners(X, f);
                call_element(iso, s, f, w * local_stiffness(x[0], x[1], x[2]));
            }
            continue;
        }
        const bool lag = s.gamma->r() != 1.0 && lagged && !(*lagged)[i].empty();
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const std::array<Vec3, 3> x = s.corners(X, f);
            const Vec3 nu = lag ? (*lagged)[i][f] : area_vector2(x).normalized();
            call_element(aniso, s, f, s.sigma * element_matrix(*s.gamma, x, nu));
        }
    }
}

} // namespace froth
