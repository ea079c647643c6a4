#include "solvers/sparse_solvers.h"

#include "core/errors.h"

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>

#include <cstdlib>
#include <string>

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

} // namespace

struct SparseDirectSolver::Impl {
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt;
    Eigen::UmfPackLU<SparseMatrix> lu;
};

SparseDirectSolver::SparseDirectSolver(Factorization kind)
    : impl_(std::make_unique<Impl>()), kind_(kind) {
    tune_for_factorisations();
    impl_->llt.cholmod().print = 0; // failures become SolverError, not stderr noise
    // Our saddle points have a symmetric pattern: AMD/METIS on A + A' with diagonal pivots
    // preferred; METIS nested dissection beats AMD by about 1.5x on surface meshes.
    impl_->lu.umfpackControl()(UMFPACK_STRATEGY) = UMFPACK_STRATEGY_SYMMETRIC;
    impl_->lu.umfpackControl()(UMFPACK_ORDERING) = UMFPACK_ORDERING_METIS;
}

SparseDirectSolver::~SparseDirectSolver() = default;

void SparseDirectSolver::analyze(const SparseMatrix& A) {
    if (kind_ == Factorization::Cholesky) {
        impl_->llt.analyzePattern(A);
    } else {
        impl_->lu.analyzePattern(A);
        if (impl_->lu.info() != Eigen::Success) throw SolverError("lu: symbolic analysis failed");
    }
    analyzed_ = true;
}

void SparseDirectSolver::factorize(const SparseMatrix& A) {
    const char* who = kind_ == Factorization::Cholesky ? "cholesky" : "lu";
    for (int k = 0; k < A.nonZeros(); ++k)
        if (!std::isfinite(A.valuePtr()[k]))
            throw SolverError(std::string(who) + ": the system matrix has non-finite entries");
    bool ok;
    if (kind_ == Factorization::Cholesky) {
        impl_->llt.factorize(A);
        ok = impl_->llt.info() == Eigen::Success;
    } else {
        impl_->lu.factorize(A);
        ok = impl_->lu.info() == Eigen::Success;
    }
    if (!ok)
        throw SolverError(std::string(who) + ": the system matrix is " +
                          (kind_ == Factorization::Cholesky ? "not positive definite" : "singular") +
                          " (degenerate facets or a violated assumption (A) of the seed)");
}

Eigen::VectorXd SparseDirectSolver::solve(const Eigen::VectorXd& b) const {
    if (kind_ == Factorization::Cholesky) return impl_->llt.solve(b);
    return impl_->lu.solve(b);
}

} // namespace froth
