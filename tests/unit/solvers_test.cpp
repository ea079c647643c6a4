// SparseDirectSolver: lagged factorisations must give the answers of fresh ones, and failures
// must be SolverErrors, for both the Cholesky and the LU path.
// The saddle-point block preconditioner and the blocked Schur complement give a direct
// solve's answers.
#include "core/errors.h"
#include "solvers/schur_complement.h"
#include "solvers/sparse_solvers.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <utility>

namespace froth {
namespace {

/// 1D Laplacian plus shift s on the diagonal: SPD for s > 0, indefinite for s < -4.
SparseMatrix shifted_laplacian(int n, double s, double wobble = 0) {
    std::vector<Eigen::Triplet<double>> t;
    for (int i = 0; i < n; ++i) {
        t.emplace_back(i, i, 2.0 + s + wobble * std::sin(i));
        if (i > 0) t.emplace_back(i, i - 1, -1.0), t.emplace_back(i - 1, i, -1.0);
    }
    SparseMatrix A(n, n);
    A.setFromTriplets(t.begin(), t.end());
    return A;
}

class BothKinds : public ::testing::TestWithParam<Factorization> {};

TEST_P(BothKinds, LaggedSolvesMatchDenseSolves) {
    const int n = 200;
    const double shift = GetParam() == Factorization::Cholesky ? 0.1 : -5.3;
    SparseDirectSolver solver(GetParam());
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
    int reused = 0;
    for (int step = 0; step < 6; ++step) {
        const SparseMatrix A = shifted_laplacian(n, shift, 0.01 * step); // slowly changing
        SolveStats stats;
        const Eigen::VectorXd x = solver.solve(A, b, &stats);
        const Eigen::VectorXd exact = Eigen::MatrixXd(A).fullPivLu().solve(b);
        EXPECT_LT((x - exact).norm() / exact.norm(), 1e-11) << "step " << step;
        EXPECT_LE(stats.residual, 1e-15);
        if (step == 0) EXPECT_TRUE(stats.refactorized) << "the first solve must factorise";
        reused += !stats.refactorized;
    }
    EXPECT_GT(reused, 0) << "the factorisation was never reused";
}

TEST_P(BothKinds, WithoutReuseEverySolveFactorises) {
    SparseDirectSolver solver(GetParam(), /*reuse=*/false);
    const double shift = GetParam() == Factorization::Cholesky ? 0.1 : -5.3;
    for (int step = 0; step < 3; ++step) {
        SolveStats stats;
        solver.solve(shifted_laplacian(50, shift), Eigen::VectorXd::Ones(50), &stats);
        EXPECT_TRUE(stats.refactorized);
    }
}

TEST_P(BothKinds, NonFiniteMatrixIsASolverError) {
    SparseMatrix A = shifted_laplacian(20, 1.0);
    A.coeffRef(3, 3) = NAN;
    SparseDirectSolver solver(GetParam());
    EXPECT_THROW(solver.solve(A, Eigen::VectorXd::Ones(20)), SolverError);
}

INSTANTIATE_TEST_SUITE_P(Solvers, BothKinds,
                         ::testing::Values(Factorization::Cholesky, Factorization::LU));

TEST(Solvers, CholeskyRejectsIndefiniteMatrices) {
    SparseDirectSolver solver(Factorization::Cholesky);
    EXPECT_THROW(solver.solve(shifted_laplacian(20, -5.3), Eigen::VectorXd::Ones(20)),
                 SolverError);
}

TEST(Solvers, LuRejectsSingularMatricesSayingWhy) {
    for (bool long_indices : {false, true}) {
        SparseDirectSolver solver(Factorization::LU);
        if (long_indices) solver.use_long_indices();
        // the pure Laplacian with Neumann-like ends: constants are in its kernel
        SparseMatrix A = shifted_laplacian(20, 0.0);
        A.coeffRef(0, 0) = 1.0, A.coeffRef(19, 19) = 1.0;
        try {
            solver.solve(A, Eigen::VectorXd::LinSpaced(20, 0.0, 1.0));
            ADD_FAILURE() << "no SolverError";
        } catch (const SolverError& e) {
            const std::string m = e.what();
            EXPECT_NE(m.find("singular"), std::string::npos) << m;
            EXPECT_NE(m.find("(20 unknowns)"), std::string::npos) << m;
        }
    }
}

// The 64-bit UMFPACK (what systems beyond the int version's index space switch to) gives the
// int version's answers, reused across steps, and copies keep it.
TEST(Solvers, LuWithLongIndicesMatchesTheIntVersion) {
    const int n = 300;
    SparseDirectSolver narrow(Factorization::LU), wide(Factorization::LU);
    wide.use_long_indices();
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0);
    for (int step = 0; step < 4; ++step) {
        const SparseMatrix A = shifted_laplacian(n, -5.3, 0.01 * step);
        const Eigen::VectorXd x = narrow.solve(A, b), y = wide.solve(A, b);
        EXPECT_LT((x - y).norm() / x.norm(), 1e-12) << "step " << step;
    }
    SparseDirectSolver copy = wide;
    const SparseMatrix A = shifted_laplacian(n, -5.3, 0.5);
    const Eigen::MatrixXd X = copy.solve_fresh(A, Eigen::MatrixXd(b));
    EXPECT_LT((X.col(0) - Eigen::MatrixXd(A).fullPivLu().solve(b)).norm() / X.norm(), 1e-11);
}


/// The saddle point [H B; B^T -C] of a 1D model of surface diffusion on n P1 nodes of [0, 1]
/// (spacing h = 1/n): H the Neumann stiffness (positive semidefinite, constants in its kernel),
/// B the lumped mass h I, C tau times the stiffness; nonsingular (I + tau H C / h^2 is).
/// `flip` negates H.
SparseMatrix model_saddle_point(int n, double tau, bool flip = false) {
    std::vector<Eigen::Triplet<double>> t;
    const double h = 1.0 / n, a = (flip ? -1.0 : 1.0) / h, c = tau / h;
    for (int i = 0; i < n; ++i) {
        const double d = (i == 0 || i == n - 1) ? 1.0 : 2.0;
        t.emplace_back(i, i, a * d), t.emplace_back(n + i, n + i, -c * d);
        t.emplace_back(i, n + i, h), t.emplace_back(n + i, i, h);
        if (i > 0) {
            t.emplace_back(i, i - 1, -a), t.emplace_back(i - 1, i, -a);
            t.emplace_back(n + i, n + i - 1, c), t.emplace_back(n + i - 1, n + i, c);
        }
    }
    SparseMatrix K(2 * n, 2 * n);
    K.setFromTriplets(t.begin(), t.end());
    return K;
}

// The blocks (saddle_point.h) give the LU's answers, lagged across steps too, for tau from
// 1e-6 to 10 (the backward error is 1e-15 for both; the condition number scales the rest).
TEST(Solvers, BlocksSolveSaddlePointsAsTheLuDoes) {
    const int n = 300;
    SparseDirectSolver blocks(Factorization::LU), lu(Factorization::LU);
    blocks.set_saddle_point(n, SaddleSolver::Blocks);
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(2 * n, -1.0, 2.0).array().sin();
    for (double tau : {1e-6, 1e-3, 1.1e-3, 1.0, 10.0}) {
        const SparseMatrix K = model_saddle_point(n, tau);
        SolveStats s;
        const Eigen::VectorXd x = blocks.solve(K, b, &s), y = lu.solve(K, b);
        EXPECT_TRUE(s.blocks) << "tau " << tau;
        EXPECT_LE(s.residual, 1e-15) << "tau " << tau;
        EXPECT_LT((x - y).norm() / y.norm(), 1e-7) << "tau " << tau; // cond(K) up to ~1e8
    }
}

// The preconditioner's quality does not depend on the mesh: 16x the nodes (h 16x smaller)
// takes about the iterations of the coarsest; sigma = 1 instead of sqrt(mean diag C / mean
// diag H) fails the bound of 20 (59 iterations at tau = 1e-4, measured).
TEST(Solvers, BlockIterationsDoNotGrowWithTheSize) {
    auto iterations = [](int n, double tau) {
        SparseDirectSolver blocks(Factorization::LU);
        blocks.set_saddle_point(n, SaddleSolver::Blocks);
        SolveStats s;
        const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(2 * n, 0.0, 40.0).array().sin();
        blocks.solve(model_saddle_point(n, tau), b, &s);
        return s.iterations;
    };
    for (double tau : {1e-4, 1e-2, 1.0}) {
        const int coarse = iterations(100, tau), fine = iterations(1600, tau);
        EXPECT_LE(fine, coarse + 4) << "tau " << tau << ": " << coarse << " -> " << fine;
        EXPECT_LE(std::max(coarse, fine), 20) << "tau " << tau; // sigma = 1 needs 59 at 1e-4
    }
}

// Auto is the LU below kBlockThreshold unknowns; blocks that are not positive definite (here
// H negated) leave the system to the LU, with its answer.
TEST(Solvers, BlocksGiveWayToTheLu) {
    const int n = 50;
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(2 * n, 0.0, 1.0);
    SparseDirectSolver automatic(Factorization::LU);
    automatic.set_saddle_point(n, SaddleSolver::Auto);
    SolveStats s;
    automatic.solve(model_saddle_point(n, 1e-3), b, &s);
    EXPECT_FALSE(s.blocks);
    SparseDirectSolver blocks(Factorization::LU);
    blocks.set_saddle_point(n, SaddleSolver::Blocks);
    const SparseMatrix K = model_saddle_point(n, 1e-3, true);
    const Eigen::VectorXd x = blocks.solve(K, b, &s);
    EXPECT_FALSE(s.blocks);
    EXPECT_LT((x - Eigen::MatrixXd(K).fullPivLu().solve(b)).norm() / x.norm(), 1e-11);
    EXPECT_THROW(parse_saddle_solver("cg"), InvalidInput);
}

// The blocked Schur complement (schur_complement.h) solves [K -B; B^T 0] as a dense LU does,
// whether the m = 7 constraint columns come in one block, in blocks of 3 (the last one short)
// or one by one; K is factorised once, in the first solve, and reused for the rest.
TEST(Solvers, SchurComplementInBlocksMatchesTheDenseSaddlePoint) {
    const int n = 40, m = 7;
    const SparseMatrix K = shifted_laplacian(n, 0.3, 0.2);
    std::vector<Eigen::Triplet<double>> t; // each column a few rows, like a cell's films
    for (int j = 0; j < m; ++j)
        for (int i = 5 * j; i < 5 * j + 8; ++i) t.emplace_back(i, j, std::cos(i + 3.0 * j));
    Eigen::SparseMatrix<double> B(n, m);
    B.setFromTriplets(t.begin(), t.end());
    const Eigen::VectorXd f = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0).array().sin();
    const Eigen::VectorXd g = Eigen::VectorXd::LinSpaced(m, 0.5, -0.5);
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n + m, n + m);
    A.topLeftCorner(n, n) = Eigen::MatrixXd(K);
    A.topRightCorner(n, m) = -Eigen::MatrixXd(B);
    A.bottomLeftCorner(m, n) = Eigen::MatrixXd(B).transpose();
    Eigen::VectorXd rhs(n + m);
    rhs << f, g;
    const Eigen::VectorXd exact = A.fullPivLu().solve(rhs);
    for (Eigen::Index block : {64, 3, 1}) {
        SparseDirectSolver solver(Factorization::Cholesky);
        int solves = 0;
        const auto solve = [&](const Eigen::MatrixXd& R) {
            return solves++ == 0 ? solver.solve_fresh(K, R) : solver.solve_with_last_factor(R);
        };
        Eigen::VectorXd p;
        const Eigen::VectorXd y = schur_complement_solve(solve, B, f, g, p, block);
        EXPECT_LT((y - exact.head(n)).norm(), 1e-12 * exact.norm()) << "block " << block;
        EXPECT_LT((p - exact.tail(m)).norm(), 1e-12 * exact.norm()) << "block " << block;
        EXPECT_LT((Eigen::MatrixXd(B).transpose() * y - g).norm(), 1e-13) << "block " << block;
        EXPECT_EQ(solves, 2 + (m + block - 1) / block) << "block " << block;
    }
    Eigen::VectorXd p; // no constraints: y = K^-1 f
    SparseDirectSolver solver(Factorization::Cholesky);
    const Eigen::VectorXd y = schur_complement_solve(
        [&](const Eigen::MatrixXd& R) { return solver.solve_fresh(K, R); },
        Eigen::SparseMatrix<double>(n, 0), f, g.head(0), p);
    EXPECT_EQ(p.size(), 0);
    EXPECT_LT((y - Eigen::MatrixXd(K).llt().solve(f)).norm(), 1e-12 * y.norm());
}

// The lagged Schur complement (schur_complement.h) gives the direct solve's y and p on a
// sequence of nearby systems (the constraint columns moving a little, as a minimize iterate's
// volume gradients do) while it makes S only once; with few constraints it makes S every time.
/// m overlapping columns of n rows, like the volume gradients of neighbouring cells.
Eigen::SparseMatrix<double> overlapping_columns(int n, int m, double shift) {
    std::vector<Eigen::Triplet<double>> t;
    for (int j = 0; j < m; ++j)
        for (int i = 9 * j; i < 9 * j + 12 && i < n; ++i)
            t.emplace_back(i, j, std::cos(i + 3.0 * j + shift) + 0.1 * shift);
    Eigen::SparseMatrix<double> B(n, m);
    B.setFromTriplets(t.begin(), t.end());
    return B;
}

/// K^-1 R with one factorisation of K, made at the first call.
auto factor_once(SparseDirectSolver& solver, const SparseMatrix& K) {
    return [&solver, &K, first = true](const Eigen::MatrixXd& R) mutable {
        const bool fresh = std::exchange(first, false);
        return fresh ? solver.solve_fresh(K, R) : solver.solve_with_last_factor(R);
    };
}

/// The lagged solve of the step-th of a sequence of nearby saddle points with K and m
/// constraints against the direct Schur complement, to `tol`.
void expect_lagged_matches_direct(LaggedSchurComplement& lagged, const SparseMatrix& K,
                                  Factorization kind, int m, int step, double tol) {
    const int n = static_cast<int>(K.rows());
    const Eigen::VectorXd f = Eigen::VectorXd::LinSpaced(n, -1.0, 2.0).array().sin();
    const Eigen::SparseMatrix<double> B = overlapping_columns(n, m, 0.01 * step);
    const Eigen::VectorXd g = Eigen::VectorXd::LinSpaced(m, 0.5 + step, -0.5);
    SparseDirectSolver solver(kind);
    auto solve = factor_once(solver, K);
    Eigen::VectorXd p, p_direct;
    const Eigen::VectorXd y = lagged.solve(solve, B, f, g, p);
    const Eigen::VectorXd y_direct = schur_complement_solve(solve, B, f, g, p_direct);
    EXPECT_LT((y - y_direct).norm(), tol * y_direct.norm()) << m << " step " << step;
    EXPECT_LT((p - p_direct).norm(), tol * p_direct.norm()) << m << " step " << step;
    EXPECT_LT((B.transpose() * y - g).norm(), tol * g.norm()) << m << " step " << step;
}

TEST(Solvers, LaggedSchurComplementMatchesTheDirectSolveAndMakesSOnce) {
    const SparseMatrix K = shifted_laplacian(1200, 0.05, 0.02);
    for (int m : {130, 20}) {
        LaggedSchurComplement lagged;
        for (int step = 0; step < 4; ++step)
            expect_lagged_matches_direct(lagged, K, Factorization::Cholesky, m, step, 1e-10);
        EXPECT_EQ(lagged.fresh_matrices(), m >= LaggedSchurComplement::kMinColumns ? 1 : 4) << m;
        EXPECT_EQ(lagged.iterations() > 0, m >= LaggedSchurComplement::kMinColumns) << m;
    }
}

// Indefinite K (Newton's steps of minimize): the lagged S preconditions GMRES instead of CG,
// made once for nearby systems, and the solves match the direct Schur complement.
TEST(Solvers, IndefiniteLaggedSchurComplementIteratesWithGmres) {
    const SparseMatrix K = shifted_laplacian(1200, -0.3, 0.02); // eigenvalues of both signs
    LaggedSchurComplement lagged(false);
    for (int step = 0; step < 3; ++step)
        expect_lagged_matches_direct(lagged, K, Factorization::LU, 130, step, 1e-7);
    EXPECT_EQ(lagged.fresh_matrices(), 1);
    EXPECT_GT(lagged.iterations(), 0);
}

} // namespace
} // namespace froth
