#pragma once
/// The stiffness of a whole cluster in the shared-vertex unknowns, from the element kernels of
/// elements.h: A = sum_i sigma_i (P1 stiffness of Gamma_i) x I_3 on isotropic surfaces and the
/// anisotropic A_gamma of (3.9) on the others (numerics.md §4), in the reduced position
/// unknowns of position_basis.h (dX_v = T_v y_v; T_v = I off the walls). The schemes'
/// systems (schemes/) are built on these.

#include "assembly/elements.h"
#include "assembly/position_basis.h"
#include "assembly/sparse_builder.h"

#include <Eigen/Core>

namespace froth {

/// T^T A_gamma T added into the position block of M, which starts at (0, 0) (A_gamma with the
/// r > 1 weights at `lagged`).
void add_position_stiffness(const Cluster& c, const PositionBasis& P, const FacetNormals* lagged,
                            SparseBuilder& M);

/// rhs.head(P.size()) = -T^T A_gamma X^m: the right-hand side of every scheme's position rows.
void set_minus_stiffness_rhs(const Cluster& c, const PositionBasis& P, const FacetNormals* lagged,
                             Eigen::VectorXd& rhs);

/// y = A_gamma X, the stiffness built on the cluster's current positions applied to X. For
/// r = 1 (and isotropic surfaces) A_gamma X^m = grad E_gamma(X^m) (1.24b).
Eigen::VectorXd apply_stiffness(const Cluster& c, const std::vector<Vec3>& X,
                                const FacetNormals* lagged = nullptr);

/// y = A_gamma D for a motion D (one vector per vertex, the same for all its periodic images):
/// apply_stiffness without the lattice shifts that a periodic cluster's corner positions carry.
Eigen::VectorXd apply_stiffness_to_motion(const Cluster& c, const std::vector<Vec3>& D,
                                          const FacetNormals* lagged = nullptr);

/// The Newton correction of the position block for r > 1 (numerics.md "Anisotropic schemes"):
/// the derivative of the (3.9) weights w(nu(X)) in A_gamma(w(nu(X))) X, T^T C T with
/// C = sum over the facets of r > 1 surfaces of sigma_i weight_jacobian (elements.h), in a
/// size x size matrix (the position unknowns first, as in the schemes' systems).
void assemble_weight_jacobian(const Cluster& c, const PositionBasis& P, const std::vector<Vec3>& X,
                              int size, SparseBuilder& M);

/// The diagonal of the scalar P1 stiffness of all surfaces, sum_i w_i K_i (w_i the isotropic
/// tension, the anisotropic surfaces' scale too): one entry per vertex, about 3.5 sigma at an
/// inner vertex of a film of equilateral facets whatever their size.
Eigen::VectorXd stiffness_diagonal(const Cluster& c);

/// The scalar P1 stiffness of all surfaces, sum_i w_i K_i with w_i the isotropic tension, plus
/// diag(diagonal) (one entry per vertex): n_vertices x n_vertices. For an isotropic cluster
/// without walls A = this (x) I_3, so a system with a proximal term of the full lumped mass
/// splits into three scalar ones (minimize). \pre every surface is isotropic.
void assemble_scalar_stiffness(const Cluster& c, const Eigen::VectorXd& diagonal, SparseBuilder& M);

} // namespace froth
