#include "solvers/sparse_solvers.h"

#include "core/errors.h"

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>

#include <cstdlib>

#include <malloc.h>

// OpenBLAS, when it is the system BLAS (Debian's libopenblas0-pthread), spins its threads on
// the small dense fronts of our factorisations: with 2 cores one thread is ~10% faster and
// leaves the other core free. Weak, so any other BLAS links as well.
extern "C" void openblas_set_num_threads(int) __attribute__((weak));

namespace froth {
namespace {

/// Process-wide settings that pay off for repeated factorisations (measured in
/// docs/benchmarks.md): one BLAS thread, and glibc malloc keeping freed memory instead of
/// returning each factor's workspace to the kernel (mmap/munmap churn cost ~20% of an SD step).
void tune_for_factorisations() {
    static const bool once = [] {
        if (openblas_set_num_threads && !std::getenv("OPENBLAS_NUM_THREADS"))
            openblas_set_num_threads(1);
        mallopt(M_MMAP_MAX, 0);
        mallopt(M_TRIM_THRESHOLD, 1 << 30);
        return true;
    }();
    (void)once;
}

void check_finite(const SparseMatrix& A, const char* who) {
    for (int k = 0; k < A.nonZeros(); ++k)
        if (!std::isfinite(A.valuePtr()[k]))
            throw SolverError(std::string(who) + ": the system matrix has non-finite entries");
}

} // namespace

struct SpdSolver::Impl {
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt;
};

SpdSolver::SpdSolver() : impl_(std::make_unique<Impl>()) {
    tune_for_factorisations();
    impl_->llt.cholmod().print = 0; // failures become SolverError, not stderr noise
}
SpdSolver::~SpdSolver() = default;

void SpdSolver::analyze(const SparseMatrix& A) {
    impl_->llt.analyzePattern(A);
    analyzed_ = true;
}

void SpdSolver::factorize(const SparseMatrix& A) {
    check_finite(A, "cholesky");
    impl_->llt.factorize(A);
    if (impl_->llt.info() != Eigen::Success)
        throw SolverError("cholesky: the system matrix is not positive definite "
                          "(degenerate facets or a violated assumption (A) of the seed)");
}

Eigen::VectorXd SpdSolver::solve(const Eigen::VectorXd& b) const { return impl_->llt.solve(b); }

struct LuSolver::Impl {
    Eigen::UmfPackLU<SparseMatrix> lu;
};

LuSolver::LuSolver() : impl_(std::make_unique<Impl>()) {
    tune_for_factorisations();
    // Our saddle points have a symmetric pattern: AMD on A + A' with diagonal pivots preferred
    // keeps the fill of a Cholesky-like factor (measured in bench/, docs/benchmarks.md).
    // METIS nested dissection beats AMD by about 1.5x on surface meshes of 3k vertices.
    impl_->lu.umfpackControl()(UMFPACK_STRATEGY) = UMFPACK_STRATEGY_SYMMETRIC;
    impl_->lu.umfpackControl()(UMFPACK_ORDERING) = UMFPACK_ORDERING_METIS;
}
LuSolver::~LuSolver() = default;

void LuSolver::analyze(const SparseMatrix& A) {
    impl_->lu.analyzePattern(A);
    if (impl_->lu.info() != Eigen::Success) throw SolverError("lu: symbolic analysis failed");
    analyzed_ = true;
}

void LuSolver::factorize(const SparseMatrix& A) {
    check_finite(A, "lu");
    impl_->lu.factorize(A);
    if (impl_->lu.info() != Eigen::Success)
        throw SolverError("lu: the system matrix is singular (degenerate facets or a violated "
                          "assumption (A) of the seed)");
}

Eigen::VectorXd LuSolver::solve(const Eigen::VectorXd& b) const { return impl_->lu.solve(b); }

} // namespace froth
