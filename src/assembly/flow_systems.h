#pragma once
/// The linear systems of one time step of the schemes (3.7)/(3.8) and (3.10)/(3.11) (numerics.md
/// §5), assembled in the unknowns of the shared-vertex cluster. Positions vertex by vertex: dX_v = T_v y_v
/// (position_basis.h; T_v = I off the walls).
///
/// Mean curvature flow, (3.5a,b) with kappa eliminated as in (4.6b) (mass lumping makes
/// M diagonal):  ( A + 1/tau sum_i blockdiag_v(m_iv omega_iv omega_iv^T) ) dX = -A X^m.
///
/// Surface diffusion, (3.6a,b) with kappa = Z k (kappa_basis.h), symmetric saddle point:
///   [ A         N Z        ] [dX]   [-A X^m]
///   [ Z^T N^T  -tau Z^T A_s Z ] [k ] = [  0   ]
/// A = sum_i sigma_i (P1 stiffness of Gamma_i) x I_3 on isotropic surfaces and the anisotropic
/// A_gamma of (3.9) on the others (numerics.md §4), A_s = per-surface scalar stiffness weighted
/// by beta_i(nu_sigma), N maps kappa_iv to m_iv omega_iv at vertex v; with mobilities the
/// lumped masses in (4.6b) become m_iv^2 / mb_iv.

#include "assembly/kappa_basis.h"
#include "assembly/position_basis.h"
#include "assembly/sparse_builder.h"
#include "anisotropy/anisotropy.h"
#include "geometry/geometry.h"

#include <Eigen/Core>

namespace froth {

/// P1 stiffness of one triangle: K_ab = (e_a . e_b) / (4 |sigma|), e_a the edge opposite a,
/// traversed cyclically. Symmetric, rows sum to zero, and K X = gradient of the area.
Eigen::Matrix3d local_stiffness(const Vec3& x0, const Vec3& x1, const Vec3& x2);

/// The normals nu^{m+1} at which (3.9) weighs the terms of an r > 1 anisotropy, per surface and
/// facet (the current iterate of the r > 1 iteration, numerics.md §5). Surfaces with r = 1
/// ignore them; null (or an empty entry) means each facet's own normal on X^m.
using FacetNormals = std::vector<std::vector<Vec3>>;

/// Unit facet normals of the cluster's surfaces at positions X.
FacetNormals facet_normals(const Cluster& c, const std::vector<Vec3>& X);

/// y = A_gamma X, the stiffness built on the cluster's current positions applied to X. For
/// r = 1 (and isotropic surfaces) A_gamma X^m = grad E_gamma(X^m) (1.24b).
Eigen::VectorXd apply_stiffness(const Cluster& c, const std::vector<Vec3>& X,
                                const FacetNormals* lagged = nullptr);

/// The Newton correction of the position block for r > 1 (numerics.md "Anisotropic schemes"):
/// the derivative of the (3.9) weights w(nu(X)) in A_gamma(w(nu(X))) X, T^T C T with
/// C = sum over the facets of r > 1 surfaces of sigma_i weight_jacobian (anisotropy.h), in a
/// size x size matrix (the position unknowns first, as in the flow systems).
void assemble_weight_jacobian(const Cluster& c, const PositionBasis& P, const std::vector<Vec3>& X,
                              int size, SparseBuilder& M);

/// The scalar P1 stiffness of all surfaces, sum_i w_i K_i with w_i the isotropic tension, plus
/// diag(diagonal) (one entry per vertex): n_vertices x n_vertices. For an isotropic cluster
/// without walls A = this (x) I_3, so a system with a proximal term of the full lumped mass
/// splits into three scalar ones (minimize). \pre every surface is isotropic.
void assemble_scalar_stiffness(const Cluster& c, const Eigen::VectorXd& diagonal, SparseBuilder& M);

/// The systems in the reduced position unknowns y of P (dX_v = T_v y_v, (3.10)/(3.11)); with
/// no walls P is the identity and these are (3.7)/(3.8) ((3.5)/(3.6) when isotropic).
void assemble_mcf(const Cluster& c, const PairGeometry& g, const PositionBasis& P, double tau,
                  const FacetNormals* lagged, SparseBuilder& M, Eigen::VectorXd& rhs);

void assemble_sd(const Cluster& c, const PairGeometry& g, const KappaBasis& Z,
                 const PositionBasis& P, double tau, const FacetNormals* lagged,
                 SparseBuilder& M, Eigen::VectorXd& rhs);

} // namespace froth
