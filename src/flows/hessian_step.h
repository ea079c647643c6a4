#pragma once
/// Newton's step for minimize (Evolver's `hessian` with `hessian_normal`): near an equilibrium
/// the BGN step of minimize.h converges only linearly, at a rate set by how far the stiffness
/// A (the Dirichlet energy's Hessian) is from the area's second variation; in a foam, whose
/// films meet in many junctions, that rate is slow (Weaire-Phelan's residual stalls at 4e-5 in
/// 1000 steps). Newton's step uses the second variation itself.
///
/// The unknowns are normal displacements: at vertex v, dX_v = N_v z_v with N_v an orthonormal
/// basis (3 x r_v) of the span of T_v T_v^T omega_iv over its surfaces i (the film normal at a
/// film vertex, r = 1; the plane normal to a triple line, r = 2; everything at a quadruple
/// point, r = 3; within the walls' tangents T_v), so the mesh keeps its tangential layout and
/// the step's fixed point is the residual's zero (minimize.h, EquilibriumState). With
/// N = diag(N_v), H the Hessian of E - sum_b p_b V_b at the current pressures
/// (assembly/lagrangian_hessian.h), G the volume gradients and M = diag(m_v I_{r_v}) the
/// lumped mass:
///
///   [ N^T H N + mu M   N^T G ] [  z ]   [ -N^T grad E ]
///   [ G^T N            0     ] [ -p ] = [  V* - V     ]
///
/// solved by the Schur complement with an LU of the first block (it need not be definite:
/// -p d^2 V makes a bubble's constant mode negative, which the volume constraint removes);
/// with many bodies the Schur complement of an earlier step preconditions GMRES on the new
/// one (LaggedSchurComplement, indefinite), as the plain steps' CG.
/// mu > 0 damps it towards a gradient step (Levenberg-Marquardt), and makes the first block
/// regular where translations leave N^T H N nearly singular.

#include "assembly/position_basis.h"
#include "geometry/geometry.h"
#include "mesh/cluster.h"
#include "solvers/schur_complement.h"

#include <Eigen/Core>

#include <vector>

namespace froth {

/// Q (dim(v) x r) with orthonormal columns spanning T_v^T omega_iv over the surfaces i at v,
/// in the reduced coordinates of P (rank by singular values above 1e-8 of the largest).
Eigen::MatrixXd normal_basis(const Cluster& c, const PositionBasis& P, const PairGeometry& g,
                             int v);

struct HessianStep {
    std::vector<Vec3> X;       ///< the positions after the step (volumes to first order)
    Eigen::VectorXd pressures; ///< the multipliers p of the step, one per volume constraint
};

/// The step above from c's positions, with the Hessian at `pressures` (one per volume
/// constraint) and damping mu relative to sigma_mean / R^2 (R^2 = area / 4 pi).
/// Isotropic clusters without walls only (the caller checks). `schur`: made with
/// definite = false, kept from step to step.
/// \throw SolverError if the system is singular.
HessianStep hessian_step(const Cluster& c, const PositionBasis& P, const PairGeometry& g,
                         const std::vector<double>& pressures, const Eigen::VectorXd& dV, double mu,
                         LaggedSchurComplement& schur);

} // namespace froth
