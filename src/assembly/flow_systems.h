#pragma once
/// The linear systems of one time step of the isotropic schemes (numerics.md §5), assembled in
/// the unknowns of the shared-vertex cluster. Positions vertex by vertex: dX_v = T_v y_v
/// (position_basis.h; T_v = I off the walls).
///
/// Mean curvature flow, (3.5a,b) with kappa eliminated as in (4.6b) (mass lumping makes
/// M diagonal):  ( A + 1/tau sum_i blockdiag_v(m_iv omega_iv omega_iv^T) ) dX = -A X^m.
///
/// Surface diffusion, (3.6a,b) with kappa = Z k (kappa_basis.h), symmetric saddle point:
///   [ A         N Z        ] [dX]   [-A X^m]
///   [ Z^T N^T  -tau Z^T A_s Z ] [k ] = [  0   ]
/// A = sum_i sigma_i (P1 stiffness of Gamma_i) x I_3, A_s = per-surface scalar stiffness,
/// N maps kappa_iv to m_iv omega_iv at vertex v.

#include "assembly/kappa_basis.h"
#include "assembly/position_basis.h"
#include "assembly/sparse_builder.h"
#include "geometry/geometry.h"

#include <Eigen/Core>

namespace froth {

/// P1 stiffness of one triangle: K_ab = (e_a . e_b) / (4 |sigma|), e_a the edge opposite a,
/// traversed cyclically. Symmetric, rows sum to zero, and K X = gradient of the area.
Eigen::Matrix3d local_stiffness(const Vec3& x0, const Vec3& x1, const Vec3& x2);

/// y = A X for the sigma-weighted vector stiffness (the energy gradient: A X = grad E).
Eigen::VectorXd apply_stiffness(const Cluster& c, const std::vector<Vec3>& X);

/// The systems in the reduced position unknowns y of P (dX_v = T_v y_v, (3.10)/(3.11)); with
/// no walls P is the identity and these are (3.5)/(3.6).
void assemble_mcf(const Cluster& c, const PairGeometry& g, const PositionBasis& P, double tau,
                  SparseBuilder& M, Eigen::VectorXd& rhs);

void assemble_sd(const Cluster& c, const PairGeometry& g, const KappaBasis& Z,
                 const PositionBasis& P, double tau, SparseBuilder& M, Eigen::VectorXd& rhs);

} // namespace froth
