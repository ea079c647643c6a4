#pragma once
/// Sparse direct solvers behind a pimpl, so that no SuiteSparse header leaks out of this module.
/// Protocol: analyze(A) once per sparsity pattern (the cluster's topology never changes during
/// a run), factorize(A) whenever the values change, then solve(b).

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>

namespace froth {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

enum class Factorization {
    Cholesky, ///< symmetric positive definite: CHOLMOD supernodal LL^T (reads the lower half)
    LU,       ///< any nonsingular matrix, here symmetric indefinite saddle points: UMFPACK
};

class SparseDirectSolver {
  public:
    explicit SparseDirectSolver(Factorization kind);
    ~SparseDirectSolver();
    void analyze(const SparseMatrix& A);
    /// \throw SolverError if A is not finite, singular, or (Cholesky) not positive definite.
    void factorize(const SparseMatrix& A);
    Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
    bool analyzed() const { return analyzed_; }

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    Factorization kind_;
    bool analyzed_ = false;
};

} // namespace froth
