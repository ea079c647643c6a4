#pragma once
/// A block preconditioner for the symmetric saddle points of surface diffusion,
///   K = [ H    B ]   H: n x n, positive semidefinite (the position stiffness),
///       [ B^T -C ]   C: m x m, positive semidefinite (tau times the kappa stiffness),
/// built from two Cholesky factorisations instead of one LU of K, whose fill grows too fast
/// for 10^6 vertices (7.3 GB at 164k vertices). It is the augmented-Lagrangian preconditioner
/// (Benzi and Olshanskii 2006; Golub and Greif 2003) with a diagonal weight W:
///   E = [ I  B W ]     E K = [ H^  B (I - W C) ]     H^ = H + B W B^T,
///       [ 0  I   ],          [ B^T  -C         ],
///   P = [ H^  B (I - W C) ]   S^ = W^{-1} + C,
///       [ 0   -S^         ],
/// and GMRES runs on K with P^{-1} E as its right preconditioner: the eigenvalues of
/// K P^{-1} E are 1 and those of S S^{-1}, S = C + B^T H^{-1} B (I - W C) the Schur complement
/// of E K. With W = (sigma D)^{-1}, D_j = |B e_j| (the mass of kappa dof j) and
/// sigma = sqrt(mean diag C / mean diag H), a Fourier model of a flat film (H = gamma k^2 M,
/// B = M, C = tau beta k^2 M) gives S S^{-1} = (1 + s^2) / (1 + s)^2 in [1/2, 1] with
/// s = sqrt(tau beta gamma) k^2: bounded whatever the mesh size h and tau, so the iteration
/// count does not grow with the mesh (numerics.md "Surface diffusion at scale"). H^ is SPD when
/// no motion of the positions leaves both the stiffness and the kappa rows unchanged (the
/// seed's assumption (A)); S^ is SPD by construction. Nonsymmetric K (the volume-exact step's
/// Newton system) are preconditioned with their symmetric parts.

#include "solvers/sparse_solvers.h"

#include <memory>

namespace froth {

class SaddlePointPreconditioner {
  public:
    SaddlePointPreconditioner();
    ~SaddlePointPreconditioner();
    SaddlePointPreconditioner(SaddlePointPreconditioner&&) noexcept;
    SaddlePointPreconditioner& operator=(SaddlePointPreconditioner&&) noexcept;
    /// Factorises H^ and S^ of K, whose first n unknowns are the positions (the patterns'
    /// analyses are kept for the next K of the same pattern). Returns false if a block is not
    /// positive definite in floating point (then an LU of K is the way).
    bool factorize(const SparseMatrix& K, int n);
    /// P^{-1} E r.
    Eigen::VectorXd apply(const Eigen::VectorXd& r) const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

} // namespace froth
