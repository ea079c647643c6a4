#pragma once
/// Right-preconditioned GMRES without restarts, for the few iterations a lagged factorisation
/// needs (Saad, Iterative Methods for Sparse Linear Systems, 2nd ed., Alg. 9.5).

#include <Eigen/Core>

#include <cmath>
#include <vector>

namespace froth::detail {

/// Improves x for A x = b until |b - A x| <= target or max_iterations; returns the number of
/// iterations, or -1 if the target was not met. apply_A(v) and apply_P(v) return vectors.
template <class ApplyA, class ApplyP>
int gmres(const ApplyA& apply_A, const ApplyP& apply_P, const Eigen::VectorXd& b,
          Eigen::VectorXd& x, double target, int max_iterations) {
    const Eigen::VectorXd r = b - apply_A(x);
    const double beta = r.norm();
    if (beta <= target) return 0;
    const int n = static_cast<int>(b.size()), m = max_iterations;
    Eigen::MatrixXd V(n, m + 1), Zk(n, m), H = Eigen::MatrixXd::Zero(m + 1, m);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(m + 1);
    std::vector<double> cs(m), sn(m);
    V.col(0) = r / beta;
    g[0] = beta;
    int k = 0;
    while (k < m) {
        Zk.col(k) = apply_P(V.col(k));
        Eigen::VectorXd w = apply_A(Zk.col(k));
        for (int i = 0; i <= k; ++i) { // modified Gram-Schmidt
            H(i, k) = w.dot(V.col(i));
            w -= H(i, k) * V.col(i);
        }
        const double h_next = w.norm(); // 0: the Krylov space is invariant, x is exact
        H(k + 1, k) = h_next;
        if (h_next > 0) V.col(k + 1) = w / h_next;
        for (int i = 0; i < k; ++i) { // apply the previous Givens rotations
            const double t = cs[i] * H(i, k) + sn[i] * H(i + 1, k);
            H(i + 1, k) = -sn[i] * H(i, k) + cs[i] * H(i + 1, k);
            H(i, k) = t;
        }
        const double d = std::hypot(H(k, k), H(k + 1, k));
        cs[k] = H(k, k) / d, sn[k] = H(k + 1, k) / d;
        H(k, k) = d, H(k + 1, k) = 0;
        g[k + 1] = -sn[k] * g[k], g[k] *= cs[k];
        ++k;
        if (std::abs(g[k]) <= target || h_next == 0) break;
    }
    const Eigen::VectorXd y =
        H.topLeftCorner(k, k).triangularView<Eigen::Upper>().solve(g.head(k));
    x += Zk.leftCols(k) * y;
    return (b - apply_A(x)).norm() <= target ? k : -1;
}

} // namespace froth::detail
