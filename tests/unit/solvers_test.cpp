// SparseDirectSolver: lagged factorisations must give the answers of fresh ones, and failures
// must be SolverErrors, for both the Cholesky and the LU path.
#include "core/errors.h"
#include "solvers/sparse_solvers.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

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

} // namespace
} // namespace froth
