#pragma once
/// The volume-exact surface diffusion step (structure-preserving, after Bao and Zhao's SP-PFEM
/// and Bao, Garcke, Nürnberg and Zhao 2022 for clusters; numerics.md "Volume-exact surface
/// diffusion"). The seed's (3.6a) tests the velocity against the normals of Gamma^m:
///   < (X^{m+1} - X^m) / tau, chi nu^m >^h = -< beta grad kappa, grad chi >,
/// and with chi the indicator of body b its left side is V_b's derivative at X^m only, so the
/// volume changes by O(tau^2) per step. With X(s) = X^m + s dX the area vectors are quadratic in
/// s, so replacing m_iv omega_iv = (1/6) sum_{sigma in Gamma_i, sigma ∋ v} (x_1 - x_0) x (x_2 - x_0)
/// by its average over s in [0, 1] (Simpson's rule is exact),
///   w_iv = (1/6) sum_sigma [ e_1 x e_2 + (e_1 x d_2 + d_1 x e_2) / 2 + d_1 x d_2 / 3 ],
/// in both off-diagonal blocks of (3.8) (the system stays symmetric, so testing with
/// (dX, kappa) gives tau |grad kappa|^2_beta + <grad X^{m+1}, grad dX> = 0 and the seed's
/// Theorem 3.4 bound E(X^{m+1}) <= E(X^m) holds for every tau) makes
///   sum_{pairs k of body b} chi_bk w_k . dX_v = V_b(X^{m+1}) - V_b(X^m)
/// exactly for bodies closed by films or flat walls. The weights depend on dX: the step is a
/// fixed point, found by iterating the linear solve with the weights of the last iterate.
/// The kappa rows carry sum_b c_b chi_b m (a uniform normal velocity per body) with c chosen so
/// that the weighted motion of each body is swept_b; the stepper adjusts swept_b by the volume
/// error each solve leaves, so the fixed point has every body at its target volume, including
/// what curved walls' lids add beyond the films and the linear solves' round-off.

#include "geometry/geometry.h"
#include "assembly/kappa_basis.h"
#include "assembly/position_basis.h"
#include "assembly/sparse_builder.h"

#include <Eigen/Core>

#include <vector>

namespace froth {

/// w_k of the header for every (surface, vertex) pair, for the step X^m -> X^m + dX.
std::vector<Vec3> simpson_pair_weights(const Cluster& c, const std::vector<Vec3>& dX);

/// The pair geometry g with m_k omega_k replaced by the weights w (mass unchanged).
PairGeometry with_pair_weights(PairGeometry g, const std::vector<Vec3>& w);

/// The kappa-row right-hand side (one value per pair) sum_b c_b chi_bk m_k for which the
/// solution's weighted motion sum_k chi_bk w_k . dX_v equals swept_b: c = S^-1 swept with
/// S_ab = sum_k chi_ak chi_bk m_k (the mass Gram matrix of the body indicators).
Eigen::VectorXd volume_rhs(const Cluster& c, const PairGeometry& g, const Eigen::VectorXd& swept);

/// The derivative of the first block's sum_k kappa_k w_k(dX) with respect to dX at the
/// iterate (dX, kappa per pair): with u_1 = e_1 / 2 + d_1 / 3, u_2 = e_2 / 2 + d_2 / 3 the
/// facet's averaged area vector has d/dD_1 = -[u_2]x, d/dD_2 = [u_1]x, d/dD_0 = [u_2 - u_1]x.
/// It is of the size of the stiffness for the low modes (kappa ~ 2 / R against 1 / R^2), which
/// is why the plain iteration over the weights contracts only by about 0.3 a solve; adding it
/// to the matrix (a Newton step in dX with the small (dW / dX)^T dX of the kappa rows left
/// out) converges in two or three. T^T C T in the position block of a size x size matrix.
void assemble_weight_derivative(const Cluster& c, const PositionBasis& P,
                                const std::vector<Vec3>& dX, const Eigen::VectorXd& kappa,
                                int size, SparseBuilder& M);

/// sum_k chi_bk w_k . dX_v for every body b: the volume the pairs' weighted motion sweeps.
Eigen::VectorXd pair_sweep(const Cluster& c, const std::vector<Vec3>& w, const std::vector<Vec3>& dX);

/// kappa per pair from the reduced unknowns k (kappa = Z k) starting at `offset` of z.
Eigen::VectorXd pair_kappa(const KappaBasis& Z, const Eigen::VectorXd& z, int offset);

/// Adds Z^T r to the kappa rows of a system whose kappa unknowns start at `offset`.
void add_kappa_rhs(const KappaBasis& Z, const Eigen::VectorXd& r, int offset, Eigen::VectorXd& rhs);

} // namespace froth
