// Volume-exact surface diffusion (structure-preserving, after Bao and Zhao's SP-PFEM and Bao,
// Garcke, Nürnberg and Zhao 2022; the equations are in assembly/exact_volumes.h, numerics.md
// "Volume-exact surface diffusion"): the seed's (3.6a) tests the velocity against the normals
// of Gamma^m, so the volume changes by O(tau^2) a step; with the Simpson average of the area
// vectors over the step,
//   w_iv = (1/6) sum_sigma [ e_1 x e_2 + (e_1 x d_2 + d_1 x e_2) / 2 + d_1 x d_2 / 3 ],
// in both off-diagonal blocks of the saddle point of surface_diffusion.h,
//   sum_{pairs k of body b} chi_bk w_k . dX_v = V_b(X^{m+1}) - V_b(X^m)
// exactly, and the symmetric structure keeps E(X^{m+1}) <= E(X^m) for every tau. The weights
// depend on dX: the step is the fixed point dX = S(w(dX)), solved here.
// Order 2 (schemes/bdf2.h) holds the volumes another way, since the BDF2 derivative mixes two
// steps' motions: the linear BDF2 step plus the uniform normal velocity per body that the
// first-order step's kappa rows also carry (volume_rhs), sized so that every body ends at its
// target: z = z0 + sum_b c_b y_b with y_b the system's response to body b's kappa-row term and
// c the root of V_b(X^m + T z(c)) = V*_b (cubic in c, found by Newton's method). The linear
// BDF2 step misses the volumes by O(tau^3), so the correction is O(tau^2) in velocity and the
// step stays second order; it costs one more back-substitution per body.
#include "schemes/surface_diffusion.h"

#include "assembly/exact_volumes.h"
#include "core/errors.h"
#include "core/format.h"
#include "solvers/anderson.h"

#include <Eigen/QR>

#include <limits>
#include <string>

namespace froth {
namespace {

/// A volume-exact step ends when every body is within this of its target (relative).
constexpr double kVolumeTolerance = 1e-13;
/// ... or within this once the error no longer halves from one solve to the next: the round-off
/// of the volumes themselves (a 64-cell periodic foam, coordinates up to 4, stalls at 1.4e-12
/// on some machines and below 1e-13 on others).
constexpr double kVolumeRoundoff = 1e-10;
constexpr int kMaxVolumeIterations = 30;

} // namespace

Eigen::VectorXd SurfaceDiffusionScheme::solve_exact_volumes(const Cluster& c, double tau,
                                                            const PositionBasis& P,
                                                            const FixedPointOptions& fp,
                                                            StepCost& report) {
    // The fixed point of exact_volumes.h over the weights w(dX): the first solve has the
    // weights of the start (m omega at X^m, or those of the last step's velocity when this step
    // continues it), the next ones add the weights' derivative C to the matrix (a Newton step in
    // dX): 2-4 solves, each on one factorisation reused through GMRES.
    const PairGeometry g = pair_geometry(c);
    const double size = cluster_size(c.positions());
    const int n = c.n_vertices(), nb = c.n_bodies();
    std::vector<Vec3> dX(n, Vec3::Zero());
    Eigen::VectorXd z_last;
    // This step continues the last one (the same positions and unknowns: fixing vertices
    // changes the unknowns, not the positions) with a step of similar length: the velocity
    // scales with tau only while the motion is smooth in time; a step of 1e-7 is mostly BGN's
    // tangential relaxation, which scaled up to a step 6000x longer predicts a wild dX whose
    // weights made the first system singular.
    const double ratio = tau / last_tau_;
    if (last_end_ == c.positions() && last_z_.size() > 0 && Z_ &&
        last_z_.size() == P.size() + Z_->n_reduced && ratio >= 0.25 && ratio <= 4) {
        z_last = last_z_;
        z_last.head(P.size()) *= ratio;
        for (int v = 0; v < n; ++v)
            dX[v] = P.displacement(z_last, v);
    }
    // With the block preconditioner every solve, the first too (with C = 0), is one of J on
    // one solver: two solvers would hold two pairs of Cholesky factors (3.9 against 3.1 GB at
    // 164k vertices).
    if (!Z_) Z_ = std::make_shared<const KappaBasis>(kappa_basis(c));
    const bool one_solver = prefers_blocks(saddle_solver_, P.size() + Z_->n_reduced);
    Anderson anderson(6); // r > 1 only, where Newton's method on (3.9) runs inside each solve
    const std::vector<double> V0 = body_volumes(c);
    Eigen::VectorXd change_needed(nb), swept(nb); // V* - V0; what the pairs' motion must sweep
    for (int b = 0; b < nb; ++b)
        change_needed[b] = c.target_volumes()[b] - V0[b];
    swept = change_needed;
    struct Reset { // the pointers must not outlive this call, whatever it throws
        SurfaceDiffusionScheme& s;
        ~Reset() { s.weights_ = nullptr, s.kappa_rhs_ = nullptr; }
    } reset{*this};
    double last_error = std::numeric_limits<double>::infinity();
    for (;;) {
        const std::vector<Vec3> w = simpson_pair_weights(c, dX);
        const PairGeometry weighted = with_pair_weights(g, w);
        const Eigen::VectorXd r = volume_rhs(c, g, swept);
        weights_ = &weighted, kappa_rhs_ = &r;
        Eigen::VectorXd z;
        if (c.nonlinear()) {
            z = solve_newton(c, tau, P, fp, report);
        } else if (z_last.size() == 0 && !one_solver) {
            z = solve_once(c, tau, P, nullptr, report);
        } else { // (M(w) + C) z = rhs + C z_last: the fixed point of M(w(dX)) z = rhs
            assemble(c, tau, P, nullptr, report);
            const Eigen::VectorXd z_prev =
                z_last.size() > 0 ? z_last : Eigen::VectorXd::Zero(rhs_.size());
            assemble_weight_derivative(c, P, dX, pair_kappa(*Z_, z_prev, P.size()),
                                       static_cast<int>(z_prev.size()), volume_jacobian_);
            const SparseMatrix& C = volume_jacobian_.finish();
            const SparseMatrix J = matrix_.finish() + C;
            z = solve_checked(exact_solver_, J, rhs_ + C * z_prev, tau, report);
            // C = 0 in a first solve (J's pattern, zero values); the next J has C at kappa,
            // which blocks made without it serve poorly (measured at 164k vertices: 21 GMRES
            // iterations a step against 12, 1.6x the step's time).
            if (z_last.size() == 0) exact_solver_.refresh_next();
        }
        ++report.volume_iterations;
        const std::vector<Vec3> X = displaced(c, P, z);
        std::vector<Vec3> dz(n);
        double change = 0;
        for (int v = 0; v < n; ++v) {
            dz[v] = X[v] - c.position(v);
            change = std::max(change, (dz[v] - dX[v]).cwiseAbs().maxCoeff());
        }
        const std::vector<double> V = body_volumes(c, X);
        report.volume_error = max_target_deviation(c, V);
        const bool stalled =
            report.volume_error <= kVolumeRoundoff && report.volume_error > 0.5 * last_error;
        last_error = report.volume_error;
        if (report.volume_error <= kVolumeTolerance || change <= 1e-15 * size || stalled) {
            last_end_ = X, last_z_ = z, last_tau_ = tau;
            return z;
        }
        if (report.volume_iterations >= kMaxVolumeIterations)
            throw ConvergenceError(
                "step: the volume-exact surface diffusion step did not converge in " +
                std::to_string(report.volume_iterations) + " solves (volume error " +
                fmt(report.volume_error) + ", tau = " + fmt(tau) +
                "); the cluster is unchanged (try a smaller tau, or exact_volumes = false)");
        // The next solve, with the weights w(dz), must sweep what the films must carry: the
        // needed change less what the lids add beyond the films (curved walls), plus what this
        // solve missed of its own target (round-off of an ill-conditioned solve).
        const Eigen::VectorXd missed = swept - pair_sweep(c, w, dz);
        swept = change_needed -
                (Eigen::Map<const Eigen::VectorXd>(V.data(), nb) -
                 Eigen::Map<const Eigen::VectorXd>(V0.data(), nb) -
                 pair_sweep(c, simpson_pair_weights(c, dz), dz)) +
                missed;
        if (c.nonlinear()) { // Anderson on (dX, swept): Newton's C is not used there
            Eigen::VectorXd x(3 * n + nb), f(3 * n + nb);
            for (int v = 0; v < n; ++v)
                x.segment<3>(3 * v) = dX[v], f.segment<3>(3 * v) = dz[v] - dX[v];
            x.tail(nb).setZero(), f.tail(nb) = swept;
            const Eigen::VectorXd next = anderson.next(x, f);
            for (int v = 0; v < n; ++v)
                dz[v] = next.segment<3>(3 * v);
            swept = next.tail(nb);
        }
        dX = std::move(dz), z_last = std::move(z);
    }
}

Eigen::VectorXd SurfaceDiffusionScheme::solve_corrector_exact_volumes(const Cluster& c,
                                                                     const Bdf2Step& s,
                                                                     const PositionBasis& P,
                                                                     StepCost& cost) {
    const Eigen::VectorXd z0 = Scheme::solve_corrector(c, s, P, cost);
    const int nb = c.n_bodies(), n = c.n_vertices();
    const SparseMatrix& M = matrix_.finish(); // the order-2 system just solved
    const PairGeometry g = pair_geometry(s.predictor);
    Eigen::MatrixXd Y(z0.size(), nb), U(3 * n, nb); // responses; their full displacements
    for (int b = 0; b < nb; ++b) {
        Eigen::VectorXd rhs = Eigen::VectorXd::Zero(z0.size());
        add_kappa_rhs(*Z_, volume_rhs(s.predictor, g, Eigen::VectorXd::Unit(nb, b)), P.size(),
                      rhs);
        Y.col(b) = solve_checked(solver_, M, rhs, s.tau, cost);
        for (int v = 0; v < n; ++v)
            U.block<3, 1>(3 * v, b) = P.displacement(Y.col(b), v);
    }
    cost.volume_iterations = 2 + nb; // predictor, corrector, one response per body
    const Eigen::Map<const Eigen::VectorXd> target(c.target_volumes().data(), nb);
    Eigen::VectorXd coef = Eigen::VectorXd::Zero(nb), z, best;
    double best_error = std::numeric_limits<double>::infinity();
    for (int it = 0; it <= 10; ++it) {
        z = z0 + Y * coef;
        const std::vector<Vec3> X = displaced(c, P, z);
        const std::vector<double> V = body_volumes(c, X);
        const double error = max_target_deviation(c, V);
        // Newton's method on a cubic: done at the tolerance, or once round-off stops it.
        const bool stalled = error > 0.5 * best_error;
        if (error < best_error) best = z, best_error = error;
        if (error <= kVolumeTolerance || stalled) break;
        const Eigen::MatrixXd J = body_volume_gradients(c, X).transpose() * U;
        // Minimum-norm: in a periodic box filled by its cells the volumes sum to the box's,
        // so J is singular (a uniform c moves no volume) and an LU's update would be garbage.
        coef -= J.completeOrthogonalDecomposition().solve(
            Eigen::Map<const Eigen::VectorXd>(V.data(), nb) - target);
    }
    z = std::move(best);
    cost.volume_error = best_error;
    if (!(cost.volume_error <= 1e3 * kVolumeTolerance))
        throw ConvergenceError("step: the order-2 surface diffusion step could not hold the "
                               "volumes (volume error " + fmt(cost.volume_error) + ", tau = " +
                               fmt(s.tau) + "); the cluster is unchanged (try a smaller tau)");
    return z;
}

} // namespace froth
