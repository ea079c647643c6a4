#pragma once
/// The saddle point of a step with linear constraints,
///   K y = f + B p,   B^T y = g     (K: n x n SPD, B: n x m sparse, the constraints' gradients),
/// by the Schur complement: u = K^-1 f, S = B^T K^-1 B (m x m, dense), S p = g - B^T u,
/// y = u + K^-1 B p. K^-1 B is dense (n x m) even when B is sparse, so it is made `block`
/// columns at a time and only S is kept: memory O(n block + m^2), not O(n m), which is what a
/// foam of 1000 cells on 10^5 vertices needs (minimize.h). `solve(R)` returns K^-1 R for a
/// dense R; its first call is the one with f (a caller that factorises on demand does so there).

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <algorithm>

namespace froth {

template <class Solve>
Eigen::VectorXd schur_complement_solve(Solve&& solve, const Eigen::SparseMatrix<double>& B,
                                       const Eigen::VectorXd& f, const Eigen::VectorXd& g,
                                       Eigen::VectorXd& p, Eigen::Index block = 64) {
    const Eigen::VectorXd u = solve(Eigen::MatrixXd(f));
    const Eigen::Index m = B.cols();
    if (m == 0) {
        p.resize(0);
        return u;
    }
    Eigen::MatrixXd S(m, m);
    for (Eigen::Index j = 0; j < m; j += block) {
        const Eigen::Index k = std::min(block, m - j);
        S.middleCols(j, k) = B.transpose() * solve(Eigen::MatrixXd(B.middleCols(j, k)));
    }
    p = S.partialPivLu().solve(g - B.transpose() * u);
    return u + solve(Eigen::MatrixXd(B * p)).col(0);
}

} // namespace froth
