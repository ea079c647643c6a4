#pragma once
/// Sparse direct solvers behind a pimpl, so that no SuiteSparse header leaks out of this module.
///
/// Time stepping solves a sequence of systems with one sparsity pattern and slowly changing
/// values. solve() therefore keeps the last factorisation and uses it as the preconditioner of
/// GMRES on the new matrix; while that converges in a few iterations (a factor a few steps old
/// typically needs 6-10), no refactorisation is needed, and a solve costs a handful of
/// triangular solves instead of a factorisation. When it stops paying, solve() refactorises.
/// Either way the answer meets the same normwise backward error, |b - A x| <= 1e-15 (|A| |x| +
/// |b|), about what the direct solve's own round-off gives (a fresh factorisation of an
/// ill-conditioned system may stop at up to 1e-11).
/// Large saddle points (surface diffusion) can take the block preconditioner of saddle_point.h,
/// two Cholesky factors, in place of the LU: more GMRES iterations, far less fill.

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <memory>
#include <string>

namespace froth {

using SparseMatrix = Eigen::SparseMatrix<double, Eigen::ColMajor, int>;

enum class Factorization {
    Cholesky, ///< symmetric positive definite: CHOLMOD supernodal LL^T (reads the lower half)
    LU,       ///< any nonsingular matrix, here symmetric indefinite saddle points: UMFPACK
};

/// The fill-reducing ordering of a Cholesky factor: CHOLMOD's default (AMD, METIS only when
/// AMD's fill is high) analyses faster, METIS's nested dissection gives cheaper triangular
/// solves. Time stepping solves many times on one factor and takes the second; minimize
/// factorises every iteration and keeps the first (sparse_solvers.cpp has the measurements).
enum class Ordering { Default, NestedDissection };

/// How saddle points are solved: an LU (UMFPACK), GMRES with the block preconditioner of two
/// Cholesky factors (saddle_point.h), or the blocks from kBlockThreshold unknowns on (Auto).
enum class SaddleSolver { Auto, LU, Blocks };

/// "auto", "lu" or "blocks". \throw InvalidInput for anything else.
SaddleSolver parse_saddle_solver(const std::string& name);

/// Whether a saddle point of this many unknowns is to be solved with the blocks.
bool prefers_blocks(SaddleSolver how, long unknowns);

struct SolveStats {
    int iterations = 0;        ///< GMRES iterations (0: the residual was met at once)
    bool refactorized = false; ///< a new numeric factorisation was made for this solve
    double residual = 0;       ///< backward error |b - A x| / (|A|_F |x| + |b|)
    bool blocks = false;       ///< solved with the block preconditioner of a saddle point
};

class SparseDirectSolver {
  public:
    /// reuse = false refactorises for every solve (the plain direct method, for comparisons);
    /// `ordering` is for Cholesky (the LU always orders by METIS).
    explicit SparseDirectSolver(Factorization kind, bool reuse = true,
                                Ordering ordering = Ordering::Default);
    Factorization kind() const { return kind_; }
    ~SparseDirectSolver();
    /// A copy shares the last factorisation (read-only, copy on write: whichever copy
    /// refactorises first gets a factor of its own), so a copied solver continues exactly as
    /// the original would: c:clone() is an exact replay.
    SparseDirectSolver(const SparseDirectSolver&);
    SparseDirectSolver& operator=(const SparseDirectSolver&);
    /// Solves A x = b; the pattern of A must not change between calls, and A is stored in full
    /// (Cholesky reads its lower half).
    /// \throw SolverError if A is not finite, singular, (Cholesky) not positive definite, or
    ///        the solve does not reach the tolerance even with a fresh factorisation.
    /// A looser `tolerance` (a normwise backward error above 1e-15) is for solves whose result
    /// only needs to be close (the order-2 predictor): GMRES stops there.
    Eigen::VectorXd solve(const SparseMatrix& A, const Eigen::VectorXd& b, SolveStats* stats = nullptr,
                          double tolerance = 1e-15);
    /// Factorises A afresh (the pattern's analysis is kept) and solves A X = B for all columns
    /// of B with that factor: the plain direct method, one pair of triangular solves per
    /// column, for iterations that correct their own round-off (minimize).
    /// \throw SolverError as solve() does, or if the result is not finite.
    Eigen::MatrixXd solve_fresh(const SparseMatrix& A, const Eigen::MatrixXd& B);
    /// LU only: factorise with UMFPACK's 64-bit version (umfpack_dl) from now on. A solver
    /// switches by itself at the first system whose factor the int version cannot index
    /// (UMFPACK_ERROR_out_of_memory: the 186k-vertex double bubble's SD step); public so that
    /// the 64-bit path can be tested on small systems.
    void use_long_indices();
    /// Applies the last factorisation to the columns of B (a matrix the factor was made for, or
    /// one near it in an iteration that tolerates that). \throw SolverError if there is none.
    Eigen::MatrixXd solve_with_last_factor(const Eigen::MatrixXd& B) const;

    /// LU only: the system is a saddle point [H B; B^T -C] whose first n unknowns are the
    /// positions (saddle_point.h), solved as `how` says: with the blocks, GMRES on the block
    /// preconditioner of two Cholesky factors instead of an LU, to the same backward error
    /// (an LU after all if a block is not positive definite or GMRES does not converge in
    /// kBlockIterations). n = 0: not a saddle point (an LU).
    void set_saddle_point(int n, SaddleSolver how) { saddle_split_ = n, saddle_solver_ = how; }
    /// The next solve() factorises afresh: the matrix is about to change by more than a lagged
    /// factor serves well.
    void refresh_next() { last_iterations_ = 1 << 20; }
    /// SaddleSolver::Auto's switch: the blocks from this many unknowns on (docs/benchmarks.md
    /// "Surface diffusion at scale").
    static constexpr int kBlockThreshold = 100000;

  private:
    void factorize(const SparseMatrix& A, bool allow_blocks = true);
    bool uses_blocks(const SparseMatrix& A) const;
    void factorize_long(const SparseMatrix& A);
    Eigen::MatrixXd apply_factor(const Eigen::MatrixXd& B) const;
    struct Impl;
    static std::shared_ptr<Impl> configured_impl(Ordering ordering);
    std::shared_ptr<Impl> impl_;
    Factorization kind_;
    bool reuse_;
    Ordering ordering_;
    bool analyzed_ = false, factorized_ = false;
    int last_iterations_ = 0;
    int fresh_iterations_ = 0; ///< what the last fresh factorisation's solve took
    int saddle_split_ = 0;
    SaddleSolver saddle_solver_ = SaddleSolver::Auto;
    bool blocks_failed_ = false;
};

} // namespace froth
