#pragma once
/// Preconditioned conjugate gradients for the symmetric positive definite systems (the MCF
/// step, (4.6b)) with the last Cholesky factor as preconditioner, for the few iterations a
/// lagged factorisation needs (Saad, Iterative Methods for Sparse Linear Systems, 2nd ed.,
/// Alg. 9.1). Four vectors of storage against GMRES's 2m; the same stopping rule.

#include <Eigen/Core>

namespace froth::detail {

/// Improves x for A x = b until |b - A x| <= target or max_iterations; returns the number of
/// iterations, or -1 if the target was not met (or the preconditioned operator was found not
/// positive definite). apply_A(v) and apply_P(v) return vectors; P must be SPD.
template <class ApplyA, class ApplyP>
int pcg(const ApplyA& apply_A, const ApplyP& apply_P, const Eigen::VectorXd& b,
        Eigen::VectorXd& x, double target, int max_iterations) {
    Eigen::VectorXd r = b - apply_A(x);
    if (r.norm() <= target) return 0;
    Eigen::VectorXd z = apply_P(r), p = z;
    double rz = r.dot(z);
    for (int k = 1; k <= max_iterations; ++k) {
        const Eigen::VectorXd Ap = apply_A(p);
        const double pAp = p.dot(Ap);
        if (!(pAp > 0) || !(rz > 0)) return -1; // not SPD in floating point: let the caller refactorise
        const double alpha = rz / pAp;
        x += alpha * p;
        r -= alpha * Ap;
        if (r.norm() <= target) return (b - apply_A(x)).norm() <= target ? k : -1;
        z = apply_P(r);
        const double rz_next = r.dot(z);
        p = z + (rz_next / rz) * p;
        rz = rz_next;
    }
    return -1;
}

} // namespace froth::detail
