#include "flows/stepper.h"

#include "assembly/exact_volumes.h"
#include "flows/anderson.h"

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

} // namespace

Flow parse_flow(std::string_view name) {
    if (name == "mcf") return Flow::MeanCurvature;
    if (name == "sd") return Flow::SurfaceDiffusion;
    throw InvalidInput("step: unknown flow '" + std::string(name) +
                       "' (use \"mcf\" for mean curvature flow or \"sd\" for surface diffusion)");
}

const char* flow_name(Flow flow) { return flow == Flow::MeanCurvature ? "mcf" : "sd"; }

Report make_report(const Cluster& c) {
    Report r;
    r.t = c.time();
    r.energy = energy(c);
    r.volumes = body_volumes(c);
    r.volume_loss = max_volume_loss(c, r.volumes);
    r.angles = triple_line_angles(c);
    r.quadruple_angles = quadruple_point_angles(c);
    r.mesh = mesh_quality(c);
    if (c.has_walls()) {
        r.contact_angles = contact_angles(c);
        r.wall_drift = wall_drift(c);
    }
    return r;
}

struct TimeStepper::System {
    explicit System(Factorization kind) : solver(kind) {}
    SparseBuilder matrix;
    Eigen::VectorXd rhs;
    SparseDirectSolver solver;
    // r > 1: the weight derivative of Newton's method and the (unsymmetric) Jacobian's solver.
    SparseBuilder weight_jacobian;
    SparseDirectSolver newton{Factorization::LU};
    // Volume-exact SD: the averaged normals' derivative and the corrected system's solver.
    SparseBuilder volume_jacobian;
    SparseDirectSolver exact{Factorization::LU};
};

TimeStepper::TimeStepper() = default;
TimeStepper::~TimeStepper() = default;

namespace {
template <class T> std::unique_ptr<T> copy_of(const std::unique_ptr<T>& p) {
    return p ? std::make_unique<T>(*p) : nullptr;
}
} // namespace

TimeStepper::TimeStepper(const TimeStepper& o)
    : fixed_point_(o.fixed_point_), exact_volumes_(o.exact_volumes_), last_z_(o.last_z_),
      last_tau_(o.last_tau_), last_end_(o.last_end_), revision_(o.revision_),
      mcf_(copy_of(o.mcf_)), sd_(copy_of(o.sd_)), Z_(copy_of(o.Z_)) {}

void TimeStepper::reset() {
    revision_ = -1;
    mcf_.reset(), sd_.reset(), Z_.reset();
    last_z_.resize(0), last_end_.clear();
}

void TimeStepper::set_fixed_point(FixedPointOptions o) {
    if (!(std::isfinite(o.tol) && o.tol > 0))
        throw InvalidInput("fixed_point: tol must be positive and finite, got " + fmt(o.tol));
    if (o.max_iterations < 2)
        throw InvalidInput("fixed_point: max_iterations must be at least 2, got " +
                           std::to_string(o.max_iterations));
    if (o.max_halvings < 0 || o.max_halvings > 20)
        throw InvalidInput("fixed_point: max_halvings must be in 0..20, got " +
                           std::to_string(o.max_halvings));
    fixed_point_ = o;
}

TimeStepper::System& TimeStepper::assemble(Cluster& c, Flow flow, double tau,
                                            const PositionBasis& P, const FacetNormals* lagged,
                                            StepReport& report) {
    const auto t0 = Clock::now();
    if (revision_ != c.assembly_revision()) { // isotropic <-> anisotropic changes the pattern
        mcf_.reset(), sd_.reset();
        revision_ = c.assembly_revision();
    }
    const PairGeometry own = weights_ ? PairGeometry{} : pair_geometry(c);
    const PairGeometry& g = weights_ ? *weights_ : own;
    std::unique_ptr<System>& sys = flow == Flow::MeanCurvature ? mcf_ : sd_;
    if (!sys)
        sys = std::make_unique<System>(flow == Flow::MeanCurvature ? Factorization::Cholesky
                                                                   : Factorization::LU);
    if (flow == Flow::MeanCurvature) {
        assemble_mcf(c, g, P, tau, lagged, sys->matrix, sys->rhs);
    } else {
        if (!Z_) Z_ = std::make_unique<KappaBasis>(kappa_basis(c));
        assemble_sd(c, g, *Z_, P, tau, lagged, sys->matrix, sys->rhs);
        if (kappa_rhs_) add_kappa_rhs(*Z_, *kappa_rhs_, P.size(), sys->rhs);
    }
    report.assemble_seconds += seconds_since(t0);
    return *sys;
}

namespace {

/// Solves M x = b, adding the cost to the report; non-finite results are a SolverError.
Eigen::VectorXd solve_checked(SparseDirectSolver& solver, const SparseMatrix& M,
                              const Eigen::VectorXd& b, double tau, StepReport& report) {
    const auto t1 = Clock::now();
    SolveStats stats;
    Eigen::VectorXd x = solver.solve(M, b, &stats);
    report.solver_iterations += stats.iterations;
    report.refactorized = report.refactorized || stats.refactorized;
    report.solve_seconds += seconds_since(t1);
    report.unknowns = static_cast<int>(M.rows());
    if (!x.allFinite())
        throw SolverError("step: the linear solve produced non-finite values (tau = " +
                          fmt(tau) + ")");
    return x;
}

/// X^m + T z: the positions of a solution z of the step's system.
std::vector<Vec3> displaced(const Cluster& c, const PositionBasis& P, const Eigen::VectorXd& z) {
    std::vector<Vec3> X = c.positions();
    for (int v = 0; v < c.n_vertices(); ++v) X[v] += P.displacement(z, v);
    return X;
}

} // namespace

Eigen::VectorXd TimeStepper::solve_once(Cluster& c, Flow flow, double tau,
                                        const PositionBasis& P, const FacetNormals* lagged,
                                        StepReport& report) {
    System& sys = assemble(c, flow, tau, P, lagged, report);
    return solve_checked(sys.solver, sys.matrix.finish(), sys.rhs, tau, report);
}

namespace {

double max_change(const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    double d = 0;
    for (std::size_t v = 0; v < a.size(); ++v) d = std::max(d, (a[v] - b[v]).cwiseAbs().maxCoeff());
    return d;
}

/// The diagonal of the bounding box: the scale of the relative fixed-point change.
double cluster_size(const std::vector<Vec3>& X) {
    Vec3 lo = X[0], hi = X[0];
    for (const Vec3& x : X) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    return (hi - lo).norm();
}

/// A volume-exact step ends when every body is within this of its target (relative).
constexpr double kVolumeTolerance = 1e-13;
constexpr int kMaxVolumeIterations = 30;

} // namespace

StepReport TimeStepper::step(Cluster& c, Flow flow, double tau, bool project_onto_walls) {
    if (!(std::isfinite(tau) && tau > 0))
        throw InvalidInput("step: tau must be positive and finite, got " + fmt(tau));
    const bool exact_sd = exact_volumes_ && flow == Flow::SurfaceDiffusion && c.n_bodies() > 0;
    if (!c.nonlinear() && !exact_sd) return step_once(c, flow, tau, project_onto_walls);
    const std::vector<Vec3> X = c.positions();
    const double t = c.time();
    try {
        return step_halving(c, flow, tau, project_onto_walls, fixed_point_.max_halvings);
    } catch (const Error&) { // the first half may have been taken
        c.set_positions(X);
        c.set_time(t);
        throw;
    }
}

StepReport TimeStepper::step_halving(Cluster& c, Flow flow, double tau, bool project,
                                     int halvings) {
    try {
        return step_once(c, flow, tau, project);
    } catch (const ConvergenceError&) {
        if (halvings == 0) throw;
    }
    // Two converged steps of tau/2 are two steps of the scheme: the bound (3.21) still holds.
    StepReport first = step_halving(c, flow, tau / 2, project, halvings - 1);
    StepReport r = step_halving(c, flow, tau / 2, project, halvings - 1);
    r.tau = tau;
    r.energy_before = first.energy_before;
    r.substeps += first.substeps;
    r.volume_iterations += first.volume_iterations;
    r.fixed_point_iterations += first.fixed_point_iterations;
    r.assemble_seconds += first.assemble_seconds;
    r.solve_seconds += first.solve_seconds;
    r.solver_iterations += first.solver_iterations;
    r.refactorized = r.refactorized || first.refactorized;
    return r;
}

StepReport TimeStepper::step_once(Cluster& c, Flow flow, double tau, bool project_onto_walls) {
    if (auto [s, f] = find_degenerate_facet(c, c.positions()); s >= 0)
        throw GeometryError("step: " + facet_name(s, f) + " has zero area; the scheme needs "
                            "non-degenerate facets (assumption (A) of the seed)");
    double area = 0;
    for (double a : surface_areas(c)) area += a;
    if (area < 1e-10 * c.initial_area())
        throw GeometryError("step: the cluster has collapsed to a point (total area " +
                            fmt(area) + ", initially " +
                            fmt(c.initial_area()) + "); nothing is left to evolve");
    StepReport report;
    report.flow = flow;
    report.tau = tau;
    report.energy_before = energy(c);

    const PositionBasis P(c);
    const bool exact_sd = exact_volumes_ && flow == Flow::SurfaceDiffusion && c.n_bodies() > 0;
    const Eigen::VectorXd z = exact_sd       ? solve_exact_volumes(c, tau, P, report)
                              : c.nonlinear() ? solve_newton(c, flow, tau, P, report)
                                              : solve_once(c, flow, tau, P, nullptr, report);
    std::vector<Vec3> X = displaced(c, P, z);
    if (project_onto_walls) project_onto_walls_of(c, X);
    if (auto [s, f] = find_degenerate_facet(c, X); s >= 0)
        throw GeometryError("step: with tau = " + fmt(tau) + " the step would collapse " +
                            facet_name(s, f) + "; the cluster is unchanged (try a smaller tau)");
    check_no_body_vanishes(c, X, tau);
    // The report evaluates the walls (lids, drift, contact angles); a user's wall function may
    // fail there, and then the step must not have happened either.
    std::vector<Vec3> X_before = c.positions();
    const double t_before = c.time();
    c.set_positions(std::move(X));
    c.set_time(t_before + tau);
    try {
        static_cast<Report&>(report) = make_report(c);
    } catch (const std::exception&) {
        c.set_positions(std::move(X_before));
        c.set_time(t_before);
        throw;
    }
    // A scheme that does not hold the volumes (mean curvature flow, the seed's linear surface
    // diffusion) moves the targets with them: the targets are the volumes the cluster is meant
    // to have now, so a later volume-exact step or minimize keeps these volumes instead of
    // undoing the flow (an explicit c:set_volume target is kept only by the volume-exact steps).
    if (!exact_sd && c.n_bodies() > 0) {
        const std::vector<double> initial = c.initial_volumes();
        c.set_volume_references(initial, report.volumes);
    }
    return report;
}

// An implicit step of any size has a solution, also one past a body's extinction (MCF shrinks a
// sphere of radius R to nothing at t = R^2/4): the scheme then returns a flat or inverted body
// with facets of nonzero area. Such a step is not taken: the body's volume may shrink, but not
// to (almost) nothing or below in one step.
void TimeStepper::check_no_body_vanishes(const Cluster& c, const std::vector<Vec3>& X, double tau) {
    if (c.n_bodies() == 0) return;
    const std::vector<double> before = body_volumes(c), after = body_volumes(c, X);
    for (int b = 0; b < c.n_bodies(); ++b)
        if (!(after[b] > 1e-9 * std::abs(before[b])))
            throw GeometryError("step: with tau = " + fmt(tau) + " body " + std::to_string(b + 1) +
                                " would vanish (volume " + fmt(before[b]) + " -> " +
                                fmt(after[b]) + "): the flow reaches its extinction within the "
                                "step; the cluster is unchanged (take a smaller tau)");
}

Eigen::VectorXd TimeStepper::solve_exact_volumes(Cluster& c, double tau, const PositionBasis& P,
                                                 StepReport& report) {
    // The fixed point of exact_volumes.h over the weights w(dX): the first solve has the
    // weights of the start (m omega at X^m, or those of the last step's velocity when this step
    // continues it), the next ones add the weights' derivative C to the matrix (a Newton step in
    // dX): 2-4 solves, each on one factorisation reused through GMRES.
    const PairGeometry g = pair_geometry(c);
    const double size = cluster_size(c.positions());
    const int n = c.n_vertices(), nb = c.n_bodies();
    std::vector<Vec3> dX(n, Vec3::Zero());
    Eigen::VectorXd z_last;
    if (last_end_ == c.positions() && last_z_.size() > 0) { // this step continues the last one
        z_last = last_z_;
        z_last.head(P.size()) *= tau / last_tau_;
        for (int v = 0; v < n; ++v) dX[v] = P.displacement(z_last, v);
    }
    Anderson anderson(6); // r > 1 only, where Newton's method on (3.9) runs inside each solve
    const std::vector<double> V0 = body_volumes(c);
    Eigen::VectorXd change_needed(nb), swept(nb); // V* - V0; what the pairs' motion must sweep
    for (int b = 0; b < nb; ++b) change_needed[b] = c.target_volumes()[b] - V0[b];
    swept = change_needed;
    struct Reset { // the pointers must not outlive this call, whatever it throws
        TimeStepper& s;
        ~Reset() { s.weights_ = nullptr, s.kappa_rhs_ = nullptr; }
    } reset{*this};
    for (;;) {
        const std::vector<Vec3> w = simpson_pair_weights(c, dX);
        const PairGeometry weighted = with_pair_weights(g, w);
        const Eigen::VectorXd r = volume_rhs(c, g, swept);
        weights_ = &weighted, kappa_rhs_ = &r;
        Eigen::VectorXd z;
        if (c.nonlinear()) {
            z = solve_newton(c, Flow::SurfaceDiffusion, tau, P, report);
        } else if (z_last.size() == 0) {
            z = solve_once(c, Flow::SurfaceDiffusion, tau, P, nullptr, report);
        } else { // (M(w) + C) z = rhs + C z_last: the fixed point of M(w(dX)) z = rhs
            System& sys = assemble(c, Flow::SurfaceDiffusion, tau, P, nullptr, report);
            assemble_weight_derivative(c, P, dX, pair_kappa(*Z_, z_last, P.size()),
                                       static_cast<int>(z_last.size()), sys.volume_jacobian);
            const SparseMatrix& C = sys.volume_jacobian.finish();
            const SparseMatrix J = sys.matrix.finish() + C;
            z = solve_checked(sys.exact, J, sys.rhs + C * z_last, tau, report);
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
        if (report.volume_error <= kVolumeTolerance || change <= 1e-15 * size) {
            last_end_ = X, last_z_ = z, last_tau_ = tau;
            return z;
        }
        if (report.volume_iterations >= kMaxVolumeIterations)
            throw ConvergenceError("step: the volume-exact surface diffusion step did not converge in " +
                                   std::to_string(report.volume_iterations) + " solves (volume error " +
                                   fmt(report.volume_error) + ", tau = " + fmt(tau) +
                                   "); the cluster is unchanged (try a smaller tau, or exact_volumes = false)");
        // The next solve, with the weights w(dz), must sweep what the films must carry: the
        // needed change less what the lids add beyond the films (curved walls), plus what this
        // solve missed of its own target (round-off of an ill-conditioned solve).
        const Eigen::VectorXd missed = swept - pair_sweep(c, w, dz);
        swept = change_needed - (Eigen::Map<const Eigen::VectorXd>(V.data(), nb) -
                                 Eigen::Map<const Eigen::VectorXd>(V0.data(), nb) -
                                 pair_sweep(c, simpson_pair_weights(c, dz), dz)) + missed;
        if (c.nonlinear()) { // Anderson on (dX, swept): Newton's C is not used there
            Eigen::VectorXd x(3 * n + nb), f(3 * n + nb);
            for (int v = 0; v < n; ++v) x.segment<3>(3 * v) = dX[v], f.segment<3>(3 * v) = dz[v] - dX[v];
            x.tail(nb).setZero(), f.tail(nb) = swept;
            const Eigen::VectorXd next = anderson.next(x, f);
            for (int v = 0; v < n; ++v) dz[v] = next.segment<3>(3 * v);
            swept = next.tail(nb);
        }
        dX = std::move(dz), z_last = std::move(z);
    }
}

Eigen::VectorXd TimeStepper::solve_newton(Cluster& c, Flow flow, double tau,
                                          const PositionBasis& P, StepReport& report) {
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
        System& sys = assemble(c, flow, tau, P, &nu, report);
        return Eigen::VectorXd(sys.matrix.finish() * zk - sys.rhs);
    };
    Eigen::VectorXd F = -assemble(c, flow, tau, P, nullptr, report).rhs; // F(0): nu(X^m) = nu^m
    Eigen::VectorXd z = Eigen::VectorXd::Zero(F.size());
    std::vector<Vec3> X = c.positions();
    for (;;) {
        System& sys = flow == Flow::MeanCurvature ? *mcf_ : *sd_;
        assemble_weight_jacobian(c, P, X, static_cast<int>(z.size()), sys.weight_jacobian);
        const SparseMatrix J = sys.matrix.finish() + sys.weight_jacobian.finish();
        const Eigen::VectorXd dz = solve_checked(sys.newton, J, -F, tau, report);
        ++report.fixed_point_iterations;
        // Converged when the full Newton update moves no vertex by more than tol.
        std::vector<Vec3> Xt = displaced(c, P, z + dz);
        report.fixed_point_change = max_change(Xt, X) / size;
        if (report.fixed_point_change <= fixed_point_.tol) return z + dz;
        if (report.fixed_point_iterations >= fixed_point_.max_iterations)
            throw ConvergenceError(
                "step: Newton's method for the r > 1 system (3.9) did not converge in " +
                std::to_string(report.fixed_point_iterations) + " solves (last relative change " +
                fmt(report.fixed_point_change) + ", tol " + fmt(fixed_point_.tol) +
                ", tau = " + fmt(tau) + ", after " + std::to_string(fixed_point_.max_halvings) +
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
