#pragma once
/// Sparse direct solvers behind a pimpl, so that no SuiteSparse header leaks out of this module.
/// Both follow the same protocol: analyze(A) once per sparsity pattern (the cluster's topology
/// never changes during a run), factorize(A) whenever the values change, then solve(b).

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <string>

namespace froth {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

/// Symmetric positive definite systems: CHOLMOD supernodal Cholesky (only the lower triangle
/// of A is read).
class SpdSolver {
  public:
    SpdSolver();
    ~SpdSolver();
    void analyze(const SparseMatrix& A);
    /// \throw SolverError if A is not positive definite or not finite.
    void factorize(const SparseMatrix& A);
    Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
    bool analyzed() const { return analyzed_; }

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    bool analyzed_ = false;
};

/// General square systems (our symmetric indefinite saddle points): UMFPACK LU with pivoting.
class LuSolver {
  public:
    LuSolver();
    ~LuSolver();
    void analyze(const SparseMatrix& A);
    /// \throw SolverError if A is singular or not finite.
    void factorize(const SparseMatrix& A);
    Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
    bool analyzed() const { return analyzed_; }

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    bool analyzed_ = false;
};

} // namespace froth
