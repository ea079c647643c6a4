#include "solvers/sparse_solvers.h"

#include "core/errors.h"
#include "solvers/gmres.h"

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>

#include <cstdlib>
#include <string>

#include <malloc.h>

// OpenBLAS, when it is the system BLAS (Debian's libopenblas0-pthread), spins its threads on
// the small dense fronts of our factorisations: with 2 cores one thread is ~10% faster and
// leaves the other core free. Weak, so any other BLAS links as well.
extern "C" void openblas_set_num_threads(int) __attribute__((weak));
// Debian's CHOLMOD is built with OpenMP and asks for 4 threads on large supernodes (a
// num_threads clause, which OMP_NUM_THREADS does not override); their start-up and futex
// hand-offs made a minimize 10% slower at 1k and 20k vertices on 2 cores. With dynamic teams
// libgomp gives at most the CPUs it found at start (one in the froth executable, app/main.cpp)
// less the load.
extern "C" void omp_set_dynamic(int) __attribute__((weak));

namespace froth {
namespace {

// A GMRES iteration costs one pair of triangular solves, about 1/16 of a factorisation on the
// default scene, and a lagged factor needs about one more iteration per step of lag: so a
// solve that needed more than kRefactorAfter iterations makes the next one refactorise first
// (a rule of thumb from that cost ratio; docs/benchmarks.md "Solver settings").
// Normwise backward errors |b - Ax| / (|A|_F |x| + |b|). A solve must reach kTolerance, about
// what a fresh direct solve gives: with a looser 1e-13, solves near equilibrium let the energy
// rise by ~1e-12 (triple bubble, measured), against Theorem 3.2. A fresh factorisation whose
// polished solve stops short of it (an ill-conditioned system, e.g. tau = 10) is still
// accepted up to kAcceptable.
constexpr double kTolerance = 1e-15;
constexpr double kAcceptable = 1e-11;
constexpr int kRefactorAfter = 8;
constexpr int kLaggedIterations = 20; // a lagged factor that needs more has failed
constexpr int kFreshIterations = 10;

/// Process-wide settings that pay off for repeated factorisations (docs/benchmarks.md,
/// "Solver settings"): one BLAS thread, and glibc malloc keeping freed memory instead of
/// returning each factor's workspace to the kernel (mmap/munmap churn cost ~13% of an SD step).
void tune_for_factorisations() {
    static const bool once = [] {
        if (openblas_set_num_threads && !std::getenv("OPENBLAS_NUM_THREADS"))
            openblas_set_num_threads(1);
        if (omp_set_dynamic && !std::getenv("OMP_DYNAMIC")) omp_set_dynamic(1);
        mallopt(M_MMAP_MAX, 0);
        mallopt(M_TRIM_THRESHOLD, 1 << 30);
        return true;
    }();
    (void)once;
}

} // namespace

/// UMFPACK's estimate of the reciprocal condition number, min |U_ii| / max |U_ii|, which Eigen
/// keeps in a protected member.
struct UmfPackLU : Eigen::UmfPackLU<SparseMatrix> {
    double rcond() const { return m_umfpackInfo(UMFPACK_RCOND); }
};

struct SparseDirectSolver::Impl {
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt;
    UmfPackLU lu;
};

std::shared_ptr<SparseDirectSolver::Impl> SparseDirectSolver::configured_impl() {
    auto impl = std::make_shared<Impl>();
    impl->llt.cholmod().print = 0; // failures become SolverError, not stderr noise
    // Our saddle points have a symmetric pattern: AMD/METIS on A + A' with diagonal pivots
    // preferred; METIS nested dissection beats AMD by about 1.5x on surface meshes. UMFPACK's
    // own iterative refinement is off: GMRES below does that job (and more) for less.
    auto& control = impl->lu.umfpackControl();
    control(UMFPACK_STRATEGY) = UMFPACK_STRATEGY_SYMMETRIC;
    control(UMFPACK_ORDERING) = UMFPACK_ORDERING_METIS;
    control(UMFPACK_IRSTEP) = 0;
    return impl;
}

SparseDirectSolver::SparseDirectSolver(Factorization kind, bool reuse)
    : impl_(configured_impl()), kind_(kind), reuse_(reuse) {
    tune_for_factorisations();
}

SparseDirectSolver::~SparseDirectSolver() = default;
SparseDirectSolver::SparseDirectSolver(const SparseDirectSolver&) = default;
SparseDirectSolver& SparseDirectSolver::operator=(const SparseDirectSolver&) = default;

void SparseDirectSolver::factorize(const SparseMatrix& A) {
    const std::string who = kind_ == Factorization::Cholesky ? "cholesky" : "lu";
    for (int k = 0; k < A.nonZeros(); ++k)
        if (!std::isfinite(A.valuePtr()[k]))
            throw SolverError(who + ": the system matrix has non-finite entries");
    if (impl_.use_count() > 1) { // shared with a copy: factorise into a fresh one (same analysis)
        impl_ = configured_impl();
        analyzed_ = false;
    }
    factorized_ = false;
    bool ok;
    if (kind_ == Factorization::Cholesky) {
        if (!analyzed_) impl_->llt.analyzePattern(A);
        impl_->llt.factorize(A);
        ok = impl_->llt.info() == Eigen::Success;
    } else {
        if (!analyzed_) impl_->lu.analyzePattern(A);
        if (impl_->lu.info() != Eigen::Success) throw SolverError("lu: symbolic analysis failed");
        impl_->lu.factorize(A);
        // A pivot that is zero only up to round-off passes UMFPACK's own check; an rcond near
        // machine epsilon catches it (our saddle points have 1e-7 .. 0.2 for tau 1e-6 .. 10).
        ok = impl_->lu.info() == Eigen::Success && impl_->lu.rcond() > 1e-14;
    }
    analyzed_ = true;
    if (!ok)
        throw SolverError(who + ": the system matrix is " +
                          (kind_ == Factorization::Cholesky ? "not positive definite" : "singular") +
                          " (degenerate facets or a violated assumption (A) of the seed)");
    factorized_ = true;
}

Eigen::MatrixXd SparseDirectSolver::solve_fresh(const SparseMatrix& A, const Eigen::MatrixXd& B) {
    if (A.rows() == 0) return B; // nothing to solve for (every vertex fixed); CHOLMOD would crash
    factorize(A);
    Eigen::MatrixXd X = kind_ == Factorization::Cholesky ? Eigen::MatrixXd(impl_->llt.solve(B))
                                                         : Eigen::MatrixXd(impl_->lu.solve(B));
    last_iterations_ = kRefactorAfter + 1; // a later solve() must not trust this factor blindly
    if (!X.allFinite()) throw SolverError("solve: the direct solve produced non-finite values");
    return X;
}

Eigen::MatrixXd SparseDirectSolver::solve_with_last_factor(const Eigen::MatrixXd& B) const {
    if (B.rows() == 0) return B;
    if (!factorized_) throw SolverError("solve: no factorisation to reuse");
    Eigen::MatrixXd X = kind_ == Factorization::Cholesky ? Eigen::MatrixXd(impl_->llt.solve(B))
                                                         : Eigen::MatrixXd(impl_->lu.solve(B));
    if (!X.allFinite()) throw SolverError("solve: the direct solve produced non-finite values");
    return X;
}

Eigen::VectorXd SparseDirectSolver::apply_factor(const Eigen::VectorXd& b) const {
    if (kind_ == Factorization::Cholesky) return impl_->llt.solve(b);
    return impl_->lu.solve(b);
}

Eigen::VectorXd SparseDirectSolver::solve(const SparseMatrix& A, const Eigen::VectorXd& b,
                                          SolveStats* stats) {
    if (A.rows() == 0) return b; // every vertex fixed: an empty system, which CHOLMOD would not take
    SolveStats s;
    auto apply_A = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return A * v; };
    auto apply_P = [&](const Eigen::VectorXd& v) { return apply_factor(v); };
    // The backward error, not the relative residual, is what a direct solve guarantees; with
    // tau = 10 the saddle point is too ill-conditioned for a small relative residual.
    const double norm_A = A.norm(); // Frobenius: bounds the 2-norm from above
    auto backward_error = [&](const Eigen::VectorXd& x) {
        return (b - apply_A(x)).norm() / (norm_A * x.norm() + b.norm());
    };
    auto target = [&](const Eigen::VectorXd& x0) { return kTolerance * (norm_A * x0.norm() + b.norm()); };
    Eigen::VectorXd x;
    bool need_factor = !(reuse_ && factorized_ && last_iterations_ <= kRefactorAfter);
    if (!need_factor) {
        x = apply_factor(b);
        s.iterations = detail::gmres(apply_A, apply_P, b, x, target(x), kLaggedIterations);
        need_factor = s.iterations < 0;
    }
    if (need_factor) {
        factorize(A);
        s.refactorized = true;
        x = apply_factor(b);
        s.iterations = detail::gmres(apply_A, apply_P, b, x, target(x), kFreshIterations);
        if (s.iterations < 0) s.iterations = kFreshIterations;
        if (!x.allFinite() || !(backward_error(x) <= kAcceptable))
            throw SolverError("solve: no accurate solution even with a fresh factorisation "
                              "(the system is numerically singular)");
    }
    last_iterations_ = s.iterations;
    s.residual = backward_error(x);
    if (stats) *stats = s;
    return x;
}

} // namespace froth
