#pragma once
/// The saddle point of a step with linear constraints,
///   K y = f + B p,   B^T y = g     (K: n x n SPD, B: n x m sparse, the constraints' gradients),
/// by the Schur complement: u = K^-1 f, S = B^T K^-1 B (m x m, dense), S p = g - B^T u,
/// y = u + K^-1 B p. K^-1 B is dense (n x m) even when B is sparse, so it is made `block`
/// columns at a time and only S is kept: memory O(n block + m^2), not O(n m), which is what a
/// foam of 1000 cells on 10^5 vertices needs (minimize.h). `solve(R)` returns K^-1 R for a
/// dense R; its first call is the one with f (a caller that factorises on demand does so there).
///
/// LaggedSchurComplement is the same solve for a sequence of nearby systems (the iterations of
/// minimize): S costs m solves with K, which for a foam of 1000 cells is most of a step, while
/// S changes little from one iterate to the next. It keeps the factor of the last S it made and
/// solves S p = g - B^T u by conjugate gradients preconditioned with it (S is SPD when K is and
/// B has full column rank), one solve with K per iteration; only when that does not converge
/// within max_iterations(m) does it make S afresh.

#include "solvers/gmres.h"

#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include <algorithm>

namespace froth {

/// S = B^T K^-1 B, `block` columns of K^-1 B at a time.
template <class Solve>
Eigen::MatrixXd schur_complement_matrix(Solve&& solve, const Eigen::SparseMatrix<double>& B,
                                        Eigen::Index block = 64) {
    const Eigen::Index m = B.cols();
    Eigen::MatrixXd S(m, m);
    for (Eigen::Index j = 0; j < m; j += block) {
        const Eigen::Index k = std::min(block, m - j);
        S.middleCols(j, k) = B.transpose() * solve(Eigen::MatrixXd(B.middleCols(j, k)));
    }
    return S;
}

template <class Solve>
Eigen::VectorXd schur_complement_solve(Solve&& solve, const Eigen::SparseMatrix<double>& B,
                                       const Eigen::VectorXd& f, const Eigen::VectorXd& g,
                                       Eigen::VectorXd& p, Eigen::Index block = 64) {
    const Eigen::VectorXd u = solve(Eigen::MatrixXd(f));
    if (B.cols() == 0) {
        p.resize(0);
        return u;
    }
    p = schur_complement_matrix(solve, B, block).partialPivLu().solve(g - B.transpose() * u);
    return u + solve(Eigen::MatrixXd(B * p)).col(0);
}

class LaggedSchurComplement {
  public:
    /// `definite`: S is SPD (K is), and the iteration is CG; else (Newton's steps of minimize,
    /// whose K is indefinite) GMRES with the same preconditioner.
    explicit LaggedSchurComplement(bool definite = true) : definite_(definite) {}

    /// Below this many constraints S is made afresh every time: its columns are one or two
    /// blocks of a multiple right-hand-side solve, as cheap as a few iterations.
    static constexpr Eigen::Index kMinColumns = 128;
    /// Iterations of the preconditioned CG before S is made afresh: at least kMinIterations,
    /// and up to one per kColumnsPerIteration columns, since S costs m solves (in blocks) and
    /// an iteration one. A 1000-cell foam's CG needs 15-25 iterations on an S of the same
    /// round and 28-41 after a round of transitions; with 25 allowed it made S afresh after
    /// every round, 15 s each on 10^5 vertices.
    static constexpr int kMinIterations = 25;
    static constexpr Eigen::Index kColumnsPerIteration = 8;
    static int max_iterations(Eigen::Index m) {
        return static_cast<int>(std::max<Eigen::Index>(kMinIterations, m / kColumnsPerIteration));
    }
    /// The CG stops at this residual relative to g - B^T u: the direct solve's accuracy.
    static constexpr double kTolerance = 1e-13;
    /// GMRES (indefinite K, such as that of minimize's Newton steps, whose LU solves are less
    /// accurate and whose result is only a proposal a merit test decides on) stops at this one.
    static constexpr double kIndefiniteTolerance = 1e-10;

    /// As schur_complement_solve.
    template <class Solve>
    Eigen::VectorXd solve(Solve&& solve, const Eigen::SparseMatrix<double>& B,
                          const Eigen::VectorXd& f, const Eigen::VectorXd& g, Eigen::VectorXd& p) {
        const Eigen::VectorXd u = solve(Eigen::MatrixXd(f));
        const Eigen::Index m = B.cols();
        if (m == 0) {
            p.resize(0);
            return u;
        }
        const Eigen::VectorXd r0 = g - B.transpose() * u;
        const auto iterate = [&] {
            return definite_ ? conjugate_gradients(solve, B, r0, p) : gmres(solve, B, r0, p);
        };
        if (!(m >= kMinColumns && lagged_.rows() == m && iterate())) {
            ++fresh_;
            lagged_ = schur_complement_matrix(solve, B).partialPivLu();
            p = lagged_.solve(r0);
        }
        return u + solve(Eigen::MatrixXd(B * p)).col(0);
    }

    void reset() { lagged_ = Eigen::PartialPivLU<Eigen::MatrixXd>(); }
    int fresh_matrices() const { return fresh_; }  ///< times S was made
    int iterations() const { return iterations_; } ///< CG (or GMRES) iterations in all

  private:
    /// S p = r0 by CG preconditioned with the lagged S; false if it did not converge.
    template <class Solve>
    bool conjugate_gradients(Solve& solve, const Eigen::SparseMatrix<double>& B,
                             const Eigen::VectorXd& r0, Eigen::VectorXd& p) {
        p = Eigen::VectorXd::Zero(r0.size());
        const double stop = kTolerance * r0.norm();
        if (stop == 0) return true;
        Eigen::VectorXd r = r0, z = lagged_.solve(r), d = z;
        double rz = r.dot(z);
        for (int it = 0, n = max_iterations(r0.size()); it < n; ++it) {
            ++iterations_;
            const Eigen::VectorXd w = B.transpose() * solve(Eigen::MatrixXd(B * d)).col(0);
            const double dw = d.dot(w);
            if (!(dw > 0)) return false; // S not positive definite in this direction
            const double alpha = rz / dw;
            p += alpha * d;
            r -= alpha * w;
            if (r.norm() <= stop) return true;
            z = lagged_.solve(r);
            const double rz_next = r.dot(z);
            d = z + (rz_next / rz) * d;
            rz = rz_next;
        }
        return false;
    }

    /// S p = r0 by GMRES preconditioned with the lagged S; false if it did not converge.
    template <class Solve>
    bool gmres(Solve& solve, const Eigen::SparseMatrix<double>& B, const Eigen::VectorXd& r0,
               Eigen::VectorXd& p) {
        p = Eigen::VectorXd::Zero(r0.size());
        const auto apply_S = [&](const Eigen::VectorXd& d) -> Eigen::VectorXd {
            return B.transpose() * solve(Eigen::MatrixXd(B * d)).col(0);
        };
        const auto apply_P = [&](const Eigen::VectorXd& r) -> Eigen::VectorXd {
            return lagged_.solve(r);
        };
        const int it = detail::gmres(apply_S, apply_P, r0, p, kIndefiniteTolerance * r0.norm(),
                                     max_iterations(r0.size()));
        if (it > 0) iterations_ += it;
        return it >= 0;
    }

    Eigen::PartialPivLU<Eigen::MatrixXd> lagged_;
    bool definite_ = true;
    int fresh_ = 0, iterations_ = 0;
};

} // namespace froth
