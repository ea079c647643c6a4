// The machinery every scheme shares (scheme.h): assembly with the pattern cache, one linear
// solve, and Newton's method for r > 1 anisotropies.
#include "schemes/scheme.h"

#include "core/errors.h"
#include "core/format.h"

#include <chrono>
#include <cmath>
#include <string>

namespace froth {
namespace {

using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

double max_change(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    double d = 0;
    for (std::size_t v = 0; v < a.size(); ++v)
        d = std::max(d, (a[v] - b[v]).cwiseAbs().maxCoeff());
    return d;
}

} // namespace

Flow parse_flow(std::string_view name) {
    if (name == "mcf") return Flow::MeanCurvature;
    if (name == "sd") return Flow::SurfaceDiffusion;
    throw InvalidInput("step: unknown flow '" + std::string(name) +
                       "' (use \"mcf\" for mean curvature flow or \"sd\" for surface diffusion)");
}

const char* flow_name(Flow flow) {
    return flow == Flow::MeanCurvature ? "mcf" : "sd";
}

Eigen::VectorXd solve_checked(SparseDirectSolver& solver, const SparseMatrix& M,
                              const Eigen::VectorXd& b, double tau, StepCost& cost,
                              double tolerance) {
    const auto t1 = Clock::now();
    SolveStats stats;
    Eigen::VectorXd x = solver.solve(M, b, &stats, tolerance);
    cost.solver_iterations += stats.iterations;
    cost.refactorized = cost.refactorized || stats.refactorized;
    cost.saddle_blocks = cost.saddle_blocks || stats.blocks;
    cost.solve_seconds += seconds_since(t1);
    cost.unknowns = static_cast<int>(M.rows());
    if (!x.allFinite())
        throw SolverError("step: the linear solve produced non-finite values (tau = " + fmt(tau) +
                          ")");
    return x;
}

namespace {

/// Calls f(v, k_v t_v t_v^T) at every triple-line vertex v: the line relaxation term's block
/// per unit weight (Scheme::set_line_relaxation).
template <class F> void for_each_line_block(const Cluster& c, const PairGeometry& g, F&& f) {
    if (c.junction_edges().empty()) return;
    const Eigen::VectorXd k = stiffness_diagonal(c);
    for (int v = 0; v < c.n_vertices(); ++v) {
        const Vec3 t = line_direction(c, g, v);
        if (!t.isZero()) f(v, Eigen::Matrix3d(k[v] * t * t.transpose()));
    }
}

} // namespace

void add_line_relaxation(const Cluster& c, const PairGeometry& g, const PositionBasis& P,
                         double weight, SparseBuilder& M) {
    if (weight == 0) return;
    for_each_line_block(c, g, [&](int v, const Eigen::Matrix3d& B) {
        P.add_block(M, v, v, weight * B);
    });
}

void Scheme::add_line_relaxation_memory(const Cluster& c, const PairGeometry& g,
                                        const PositionBasis& P, double tau) {
    if (line_relaxation_ == 0) return;
    Eigen::VectorXd memory = Eigen::VectorXd::Zero(3 * c.n_vertices());
    for_each_line_block(c, g, [&](int v, const Eigen::Matrix3d& B) {
        memory.segment<3>(3 * v) = line_relaxation_ / tau * (B * bdf2_->memory[v]);
    });
    rhs_.head(P.size()) += P.restrict(memory);
}

std::vector<Vec3> displaced(const Cluster& c, const PositionBasis& P, const Eigen::VectorXd& z) {
    std::vector<Vec3> X = c.positions();
    for (int v = 0; v < c.n_vertices(); ++v)
        X[v] += P.displacement(z, v);
    return X;
}

double cluster_size(const std::vector<Vec3>& X) {
    Vec3 lo = X[0], hi = X[0];
    for (const Vec3& x : X)
        lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    return (hi - lo).norm();
}

void Scheme::drop_systems() {
    matrix_ = SparseBuilder(), weight_jacobian_ = SparseBuilder();
    solver_ = SparseDirectSolver(solver_.kind(), true, Ordering::NestedDissection);
    newton_ = SparseDirectSolver(Factorization::LU);
}

void Scheme::reset() {
    drop_systems();
    revision_ = -1;
}

void Scheme::assemble(const Cluster& c, double tau, const PositionBasis& P,
                      const FacetNormals* lagged, StepCost& cost) {
    const auto t0 = Clock::now();
    if (revision_ != c.assembly_revision()) { // isotropic <-> anisotropic changes the pattern
        drop_systems();
        revision_ = c.assembly_revision();
    }
    const PairGeometry own = weights_ ? PairGeometry{} : pair_geometry(c);
    assemble_system(c, weights_ ? *weights_ : own, P, tau, lagged);
    // Order 2 assembles on the predictor X~ = c.positions(): A~ X^{m+1} = A~ X~ + A~ (dX - shift).
    // (The shift is a motion: no lattice offsets at a periodic cluster's box faces.)
    if (bdf2_)
        rhs_.head(P.size()) += P.restrict(apply_stiffness_to_motion(c, bdf2_->shift, lagged));
    cost.assemble_seconds += seconds_since(t0);
}

Eigen::VectorXd Scheme::solve_once(const Cluster& c, double tau, const PositionBasis& P,
                                   const FacetNormals* lagged, StepCost& cost, double tolerance) {
    assemble(c, tau, P, lagged, cost);
    return solve_checked(solver_, matrix_.finish(), rhs_, tau, cost, tolerance);
}

Eigen::VectorXd Scheme::solve(const Cluster& c, double tau, const PositionBasis& P,
                              const FixedPointOptions& fp, StepCost& cost) {
    return c.nonlinear() ? solve_newton(c, tau, P, fp, cost) : solve_once(c, tau, P, nullptr, cost);
}

Eigen::VectorXd Scheme::solve_bdf2(const Cluster& c, const std::vector<Vec3>& previous,
                                   double previous_tau, double tau, const PositionBasis& P,
                                   StepCost& cost) {
    // The predictor: the linear BDF2 system with the geometry of X^m (r > 1 weights at nu^m),
    // O(tau^2) from X^{m+1}. It only places the geometry, so its solve stops at a backward
    // error of 1e-10: about cond * 1e-10 |dX| in X~, far below the O(tau^2) it is off anyway.
    // Its matrix is the corrector's (step tau / a) on a surface O(tau) away, so both solve on
    // one lagged factor. Measured on MCF of the icosphere at 10k vertices, tau = 4e-3, 25
    // steps: one factorisation where the first-order predictor (step tau) and a corrector
    // factor of its own took three, solves 2.36 -> 1.76 s, one factor in memory instead of two.
    const Bdf2Step lagged = make_bdf2_step(c, c.positions(), previous, tau, previous_tau);
    const Eigen::VectorXd z0 = solve_linear_bdf2(lagged, P, cost, 1e-10);
    std::vector<Vec3> predicted = displaced(c, P, z0);
    const Bdf2Step s = make_bdf2_step(c, predicted, previous, tau, previous_tau);
    cost.order = 2;
    Eigen::VectorXd z = solve_corrector(c, s, P, cost);
    cost.error_estimate = shape_difference(c, displaced(c, P, z), predicted);
    return z;
}

Eigen::VectorXd Scheme::solve_corrector(const Cluster&, const Bdf2Step& s, const PositionBasis& P,
                                        StepCost& cost) {
    return solve_linear_bdf2(s, P, cost, 1e-15);
}

Eigen::VectorXd Scheme::solve_linear_bdf2(const Bdf2Step& s, const PositionBasis& P,
                                          StepCost& cost, double tolerance) {
    struct Reset { // the pointer must not outlive this call, whatever it throws
        Scheme& scheme;
        ~Reset() { scheme.bdf2_ = nullptr; }
    } reset{*this};
    bdf2_ = &s;
    // The predictor's normals are explicit r > 1 weights: no Newton iteration (bdf2.h).
    assemble(s.predictor, s.effective_tau(), P, nullptr, cost);
    return solve_checked(solver_, matrix_.finish(), rhs_, s.tau, cost, tolerance);
}

Eigen::VectorXd Scheme::solve_newton(const Cluster& c, double tau, const PositionBasis& P,
                                     const FixedPointOptions& fp, StepCost& cost) {
    // (3.9) weighs term l by [gamma_l(nu^{m+1}) / gamma(nu^{m+1})]^(r-1), so the step's system
    // is F(z) = M(w(nu(X(z)))) z - b(w(nu(X(z)))) = 0 with X(z) = X^m + T z. The lagged
    // (Picard) iteration of §4.2 solves with the weights of the last iterate; for large r the
    // weights switch between terms within a degree of rotation and the BGN tangential motion
    // rotates facets by more than that, so Picard cycles (r = 30 does not converge even at
    // tau = 1e-6 from a half sphere). Newton's method on F, with the weight derivative of
    // assemble_weight_jacobian and a backtracking line search on |F|, solves the same system.
    // It starts at X^m (z = 0), not at the linear solve with the weights at nu^m: that solve
    // can move vertices tangentially by 40% of the cluster's size (r = 10, double bubble),
    // from where Newton does not recover; from X^m the line search keeps the first update sane.
    const double size = cluster_size(c.positions());
    const auto residual = [&](const Eigen::VectorXd& zk, const std::vector<Vec3>& Xk) {
        const FacetNormals nu = facet_normals(c, Xk);
        assemble(c, tau, P, &nu, cost);
        return Eigen::VectorXd(matrix_.finish() * zk - rhs_);
    };
    assemble(c, tau, P, nullptr, cost);
    Eigen::VectorXd F = -rhs_; // F(0): nu(X^m) = nu^m
    Eigen::VectorXd z = Eigen::VectorXd::Zero(F.size());
    std::vector<Vec3> X = c.positions();
    for (;;) {
        assemble_weight_jacobian(c, P, X, static_cast<int>(z.size()), weight_jacobian_);
        const SparseMatrix J = matrix_.finish() + weight_jacobian_.finish();
        const Eigen::VectorXd dz = solve_checked(newton_, J, -F, tau, cost);
        ++cost.fixed_point_iterations;
        // Converged when the full Newton update moves no vertex by more than tol.
        std::vector<Vec3> Xt = displaced(c, P, z + dz);
        cost.fixed_point_change = max_change(Xt, X) / size;
        if (cost.fixed_point_change <= fp.tol) return z + dz;
        if (cost.fixed_point_iterations >= fp.max_iterations)
            throw ConvergenceError(
                "step: Newton's method for the r > 1 system (3.9) did not converge in " +
                std::to_string(cost.fixed_point_iterations) + " solves (last relative change " +
                fmt(cost.fixed_point_change) + ", tol " + fmt(fp.tol) + ", tau = " + fmt(tau) +
                ", after " + std::to_string(fp.max_halvings) +
                " halvings of the step); the cluster is unchanged (try a smaller tau)");
        // Backtracking: halve the update until |F| decreases and no facet degenerates.
        const double norm = F.norm();
        for (double alpha = 1.0;; alpha *= 0.5) {
            if (alpha < 1e-6)
                throw ConvergenceError("step: Newton's method for the r > 1 system (3.9) found "
                                       "no update that decreases its residual (tau = " +
                                       fmt(tau) + "); the cluster is unchanged");
            if (alpha < 1.0) Xt = displaced(c, P, z + alpha * dz);
            if (find_degenerate_facet(c, Xt).first >= 0) continue;
            Eigen::VectorXd Ft = residual(z + alpha * dz, Xt);
            if (!(Ft.norm() < (1 - 1e-4 * alpha) * norm)) continue;
            z += alpha * dz, X = std::move(Xt), F = std::move(Ft);
            break;
        }
    }
}

} // namespace froth
