#include "solvers/sparse_solvers.h"

#include "core/errors.h"
#include "solvers/gmres.h"
#include "solvers/pcg.h"
#include "solvers/saddle_point.h"

#include <Eigen/CholmodSupport>
#include <Eigen/UmfPackSupport>

#include <cstdio>
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
// The block preconditioner of saddle points (saddle_point.h): the GMRES budget, and how many
// iterations more than a fresh preconditioner's a lagged one may take before it is refreshed.
constexpr int kBlockIterations = 100;
constexpr int kBlockSlack = 10;
constexpr int kBlockCycle = 30;

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

/// UMFPACK's estimate of the reciprocal condition number, min |U_ii| / max |U_ii|, and the
/// status of its last call, which Eigen keeps in a protected member (and folds every failure,
/// out of memory included, into "NumericalIssue").
template <class Matrix> struct UmfPackLUWithInfo : Eigen::UmfPackLU<Matrix> {
    double rcond() const { return this->m_umfpackInfo(UMFPACK_RCOND); }
    double status() const { return this->m_umfpackInfo(UMFPACK_STATUS); }
};
using UmfPackLU = UmfPackLUWithInfo<SparseMatrix>;
/// UMFPACK with 64-bit indices (umfpack_dl_*): the int version's factor is limited to 2^31
/// words, which the SD saddle point of a 186k-vertex double bubble (744k unknowns) exceeds:
/// it returned UMFPACK_ERROR_out_of_memory at 3 GB on a 24 GB machine (issue 16).
using SparseMatrixLong = Eigen::SparseMatrix<double, Eigen::ColMajor, SuiteSparse_long>;
using UmfPackLULong = UmfPackLUWithInfo<SparseMatrixLong>;

struct SparseDirectSolver::Impl {
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> llt;
    UmfPackLU lu;
    // Set once the int version ran out of index space: then every factorisation is 64-bit
    // (UMFPACK's solves read the matrix again, so its 64-bit copy lives here).
    std::unique_ptr<UmfPackLULong> lu_long;
    SparseMatrixLong A_long;
    // Saddle points at or above the block threshold: the block preconditioner in place of the
    // LU (saddle_point.h); `blocks` says which of the two the last factorisation made.
    SaddlePointPreconditioner block;
    bool blocks = false;
};

namespace {

/// Our saddle points have a symmetric pattern: AMD/METIS on A + A' with diagonal pivots
/// preferred; METIS nested dissection beats AMD by about 1.5x on surface meshes. UMFPACK's
/// own iterative refinement is off: GMRES does that job (and more) for less.
template <class LU> void configure_umfpack(LU& lu) {
    auto& control = lu.umfpackControl();
    control(UMFPACK_STRATEGY) = UMFPACK_STRATEGY_SYMMETRIC;
    control(UMFPACK_ORDERING) = UMFPACK_ORDERING_METIS;
    control(UMFPACK_IRSTEP) = 0;
}

/// Why UMFPACK did not give a usable factor, for the error message.
template <class LU> std::string umfpack_failure(const LU& lu, long n) {
    const double status = lu.status();
    const std::string size = " (" + std::to_string(n) + " unknowns)";
    if (status == UMFPACK_ERROR_out_of_memory)
        return "UMFPACK ran out of memory factorising the system" + size;
    if (status == UMFPACK_WARNING_singular_matrix)
        return "the system matrix is singular: UMFPACK met a zero pivot" + size +
               " (degenerate facets or a violated assumption (A) of the seed)";
    if (status != UMFPACK_OK)
        return "UMFPACK failed with status " + std::to_string(static_cast<int>(status)) + size;
    char rcond[32];
    std::snprintf(rcond, sizeof rcond, "%.3g", lu.rcond());
    return "the system matrix is nearly singular: UMFPACK's reciprocal condition estimate " +
           std::string(rcond) + " is below 1e-14" + size +
           " (degenerate facets or a violated assumption (A) of the seed)";
}

} // namespace

SaddleSolver parse_saddle_solver(const std::string& name) {
    if (name == "auto") return SaddleSolver::Auto;
    if (name == "lu") return SaddleSolver::LU;
    if (name == "blocks") return SaddleSolver::Blocks;
    throw InvalidInput("sd_solver: unknown solver '" + name +
                       "' (use \"auto\", \"lu\" or \"blocks\")");
}

bool prefers_blocks(SaddleSolver how, long unknowns) {
    return how == SaddleSolver::Blocks ||
           (how == SaddleSolver::Auto && unknowns >= SparseDirectSolver::kBlockThreshold);
}

std::shared_ptr<SparseDirectSolver::Impl> SparseDirectSolver::configured_impl(Ordering ordering) {
    auto impl = std::make_shared<Impl>();
    impl->llt.cholmod().print = 0; // failures become SolverError, not stderr noise
    // Measured 2026-12-04: on the icosphere up to 10k vertices CHOLMOD's default keeps AMD;
    // METIS there makes a lagged CG iteration cheaper: 25 order-2 MCF steps (tau = 4e-3) at
    // 10k vertices 2.45 -> 2.21 s (the first step 0.42 -> 0.48 s, the other 24 steps' solves
    // 1.59 -> 1.28 s), at 2.5k 0.40 -> 0.38 s; from 41k on the default takes METIS itself.
    // minimize, one factorisation an iteration, became 8-16% slower with it (the statics
    // benchmark's rows), so it keeps the default.
    if (ordering == Ordering::NestedDissection) {
        impl->llt.cholmod().nmethods = 1;
        impl->llt.cholmod().method[0].ordering = CHOLMOD_METIS;
    }
    configure_umfpack(impl->lu);
    return impl;
}

SparseDirectSolver::SparseDirectSolver(Factorization kind, bool reuse, Ordering ordering)
    : impl_(configured_impl(ordering)), kind_(kind), reuse_(reuse), ordering_(ordering) {
    tune_for_factorisations();
}

SparseDirectSolver::~SparseDirectSolver() = default;
SparseDirectSolver::SparseDirectSolver(const SparseDirectSolver&) = default;
SparseDirectSolver& SparseDirectSolver::operator=(const SparseDirectSolver&) = default;

bool SparseDirectSolver::uses_blocks(const SparseMatrix& A) const {
    return kind_ == Factorization::LU && !blocks_failed_ && saddle_split_ > 0 &&
           saddle_split_ < A.rows() && prefers_blocks(saddle_solver_, A.rows());
}

void SparseDirectSolver::factorize(const SparseMatrix& A, bool allow_blocks) {
    const std::string who = kind_ == Factorization::Cholesky ? "cholesky" : "lu";
    for (int k = 0; k < A.nonZeros(); ++k)
        if (!std::isfinite(A.valuePtr()[k]))
            throw SolverError(who + ": the system matrix has non-finite entries");
    if (impl_.use_count() > 1) { // shared with a copy: factorise into a fresh one (same analysis)
        const bool long_indices = impl_->lu_long != nullptr;
        impl_ = configured_impl(ordering_);
        if (long_indices) use_long_indices();
        analyzed_ = false;
    }
    factorized_ = false;
    impl_->blocks = false;
    if (allow_blocks && uses_blocks(A)) {
        if (impl_->block.factorize(A, saddle_split_)) {
            impl_->blocks = true, factorized_ = true;
            return;
        }
        blocks_failed_ = true; // not positive definite here: the LU from now on
    }
    if (kind_ == Factorization::Cholesky) {
        if (!analyzed_) impl_->llt.analyzePattern(A);
        impl_->llt.factorize(A);
        analyzed_ = true;
        if (impl_->llt.info() != Eigen::Success)
            throw SolverError("cholesky: the system matrix is not positive definite (degenerate "
                              "facets or a violated assumption (A) of the seed)");
    } else if (!impl_->lu_long) {
        if (!analyzed_) impl_->lu.analyzePattern(A);
        if (impl_->lu.status() == UMFPACK_ERROR_out_of_memory) return factorize_long(A);
        if (impl_->lu.info() != Eigen::Success)
            throw SolverError("lu: symbolic analysis failed: " + umfpack_failure(impl_->lu, A.rows()));
        impl_->lu.factorize(A);
        analyzed_ = true;
        if (impl_->lu.status() == UMFPACK_ERROR_out_of_memory) return factorize_long(A);
        // A pivot that is zero only up to round-off passes UMFPACK's own check; an rcond near
        // machine epsilon catches it (our saddle points have 1e-7 .. 0.3 for tau 1e-6 .. 10).
        if (impl_->lu.info() != Eigen::Success || !(impl_->lu.rcond() > 1e-14))
            throw SolverError("lu: " + umfpack_failure(impl_->lu, A.rows()));
    } else {
        return factorize_long(A);
    }
    factorized_ = true;
}

void SparseDirectSolver::use_long_indices() {
    impl_->lu_long = std::make_unique<UmfPackLULong>();
    configure_umfpack(*impl_->lu_long);
}

void SparseDirectSolver::factorize_long(const SparseMatrix& A) {
    if (!impl_->lu_long) use_long_indices(), analyzed_ = false;
    impl_->A_long = A;
    UmfPackLULong& lu = *impl_->lu_long;
    if (!analyzed_) lu.analyzePattern(impl_->A_long);
    if (lu.info() != Eigen::Success)
        throw SolverError("lu: symbolic analysis failed: " + umfpack_failure(lu, A.rows()));
    lu.factorize(impl_->A_long);
    analyzed_ = true;
    if (lu.info() != Eigen::Success || !(lu.rcond() > 1e-14))
        throw SolverError("lu: " + umfpack_failure(lu, A.rows()));
    factorized_ = true;
}

Eigen::MatrixXd SparseDirectSolver::solve_fresh(const SparseMatrix& A, const Eigen::MatrixXd& B) {
    if (A.rows() == 0) return B; // nothing to solve for (every vertex fixed); CHOLMOD would crash
    factorize(A, false); // the direct method: the exact factor, not a preconditioner
    Eigen::MatrixXd X = apply_factor(B);
    last_iterations_ = kRefactorAfter + 1; // a later solve() must not trust this factor blindly
    if (!X.allFinite()) throw SolverError("solve: the direct solve produced non-finite values");
    return X;
}

Eigen::MatrixXd SparseDirectSolver::solve_with_last_factor(const Eigen::MatrixXd& B) const {
    if (B.rows() == 0) return B;
    if (!factorized_ || impl_->blocks) throw SolverError("solve: no factorisation to reuse");
    Eigen::MatrixXd X = apply_factor(B);
    if (!X.allFinite()) throw SolverError("solve: the direct solve produced non-finite values");
    return X;
}

Eigen::MatrixXd SparseDirectSolver::apply_factor(const Eigen::MatrixXd& B) const {
    if (kind_ == Factorization::Cholesky) return impl_->llt.solve(B);
    if (impl_->blocks) {
        Eigen::MatrixXd X(B.rows(), B.cols());
        for (int j = 0; j < B.cols(); ++j)
            X.col(j) = impl_->block.apply(B.col(j));
        return X;
    }
    if (impl_->lu_long) return impl_->lu_long->solve(B);
    return impl_->lu.solve(B);
}

Eigen::VectorXd SparseDirectSolver::solve(const SparseMatrix& A, const Eigen::VectorXd& b,
                                          SolveStats* stats, double tolerance) {
    if (A.rows() == 0) return b; // every vertex fixed: an empty system, which CHOLMOD would not take
    SolveStats s;
    auto apply_A = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return A * v; };
    auto apply_P = [&](const Eigen::VectorXd& v) -> Eigen::VectorXd { return apply_factor(v); };
    // The backward error, not the relative residual, is what a direct solve guarantees; with
    // tau = 10 the saddle point is too ill-conditioned for a small relative residual.
    const double norm_A = A.norm(); // Frobenius: bounds the 2-norm from above
    auto backward_error = [&](const Eigen::VectorXd& x) {
        return (b - apply_A(x)).norm() / (norm_A * x.norm() + b.norm());
    };
    const double tol = std::max(tolerance, kTolerance);
    auto target = [&](const Eigen::VectorXd& x0) { return tol * (norm_A * x0.norm() + b.norm()); };
    // SPD systems (Cholesky) by conjugate gradients, the others by GMRES; both stop at the
    // same backward error. Measured on MCF of the icosphere (41k and 164k vertices): the same
    // iterations (3-4 a step) and the same time within the noise (+-10%), but CG keeps 4
    // vectors where GMRES keeps 2 x 21: 1 GB at 10^6 vertices.
    auto iterate = [&](const Eigen::VectorXd& rhs, Eigen::VectorXd& x0, double goal, int max) {
        if (kind_ == Factorization::Cholesky)
            return detail::pcg(apply_A, apply_P, rhs, x0, goal, max);
        if (!impl_->blocks) return detail::gmres(apply_A, apply_P, rhs, x0, goal, max);
        // The blocks' first guess may be far from x, so the target (relative to |x|) is
        // renewed at restarts, every kBlockCycle iterations or when a cycle met the target of
        // its start but not that of its end: also 2 x kBlockCycle vectors instead of 2 x max.
        for (int done = 0; done < max;) {
            const int budget = std::min(kBlockCycle, max - done);
            const int k = detail::gmres(apply_A, apply_P, rhs, x0, target(x0), budget);
            done += k >= 0 ? k : budget;
            if (k >= 0 && backward_error(x0) <= tol)
                return done;
        }
        return -1;
    };
    // The block preconditioner needs more iterations than an exact factor (saddle_point.h):
    // it is refreshed once a lagged one needs kBlockSlack more than a fresh one did.
    const bool blocks = uses_blocks(A);
    const int refactor_after = blocks ? fresh_iterations_ + kBlockSlack : kRefactorAfter;
    const int lagged_max = blocks ? kBlockIterations : kLaggedIterations;
    Eigen::VectorXd x;
    bool need_factor = !(reuse_ && factorized_ && last_iterations_ <= refactor_after &&
                         impl_->blocks == blocks);
    if (!need_factor) {
        x = apply_factor(b);
        s.iterations = iterate(b, x, target(x), lagged_max);
        need_factor = s.iterations < 0;
    }
    if (need_factor) {
        factorize(A);
        s.refactorized = true;
        x = apply_factor(b);
        s.iterations = iterate(b, x, target(x), impl_->blocks ? kBlockIterations : kFreshIterations);
        if (s.iterations < 0 && impl_->blocks) { // the blocks did not do: the LU from now on
            blocks_failed_ = true;
            factorize(A);
            x = apply_factor(b);
            s.iterations = iterate(b, x, target(x), kFreshIterations);
        }
        if (s.iterations < 0) s.iterations = kFreshIterations;
        fresh_iterations_ = s.iterations;
        if (!x.allFinite() || !(backward_error(x) <= std::max(tol, kAcceptable)))
            throw SolverError("solve: no accurate solution even with a fresh factorisation "
                              "(the system is numerically singular)");
    }
    last_iterations_ = s.iterations;
    s.residual = backward_error(x);
    s.blocks = impl_->blocks;
    if (stats) *stats = s;
    return x;
}

} // namespace froth
