#include "flows/stepper.h"

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

std::string facet_name(int surface, int facet) {
    return "facet " + std::to_string(facet + 1) + " of surface " + std::to_string(surface + 1);
}

/// The first facet whose area is not positive relative to its edges, or {-1, -1}.
std::pair<int, int> find_degenerate_facet(const Cluster& c, const std::vector<Vec3>& X) {
    for (int i = 0; i < c.n_surfaces(); ++i) {
        const auto& tris = c.surface(i).triangles;
        for (int f = 0; f < static_cast<int>(tris.size()); ++f) {
            const Tri& t = tris[f];
            const double scale = (X[t[1]] - X[t[0]]).squaredNorm() +
                                 (X[t[2]] - X[t[0]]).squaredNorm();
            if (!(area_vector2(X, t).norm() > 1e-12 * scale)) return {i, f};
        }
    }
    return {-1, -1};
}

/// The optional projection of the seed's remark after (3.12): every wall-attached vertex moved
/// back onto its walls (alternating projections for a vertex on two). Loses the stability
/// bound of Theorem 3.4 in general.
void project_vertices(const Cluster& c, std::vector<Vec3>& X) {
    for (int v = 0; v < c.n_vertices(); ++v) {
        const std::vector<int> walls = c.vertex_walls(v);
        for (int pass = 0; pass < (walls.size() > 1 ? 20 : 1); ++pass)
            for (int w : walls) X[v] = c.walls()[w]->project(X[v]);
    }
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
};

TimeStepper::TimeStepper() = default;
TimeStepper::~TimeStepper() = default;

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

std::vector<Vec3> TimeStepper::solve_once(Cluster& c, Flow flow, double tau,
                                          const FacetNormals* lagged, StepReport& report) {
    const auto t0 = Clock::now();
    if (revision_ != c.assembly_revision()) { // isotropic <-> anisotropic changes the pattern
        mcf_.reset(), sd_.reset();
        revision_ = c.assembly_revision();
    }
    const PairGeometry g = pair_geometry(c);
    const PositionBasis P(c);
    std::unique_ptr<System>& sys = flow == Flow::MeanCurvature ? mcf_ : sd_;
    if (!sys)
        sys = std::make_unique<System>(flow == Flow::MeanCurvature ? Factorization::Cholesky
                                                                   : Factorization::LU);
    if (flow == Flow::MeanCurvature) {
        assemble_mcf(c, g, P, tau, lagged, sys->matrix, sys->rhs);
    } else {
        if (!Z_) Z_ = std::make_unique<KappaBasis>(kappa_basis(c));
        assemble_sd(c, g, *Z_, P, tau, lagged, sys->matrix, sys->rhs);
    }
    const SparseMatrix& M = sys->matrix.finish();
    report.assemble_seconds += seconds_since(t0);

    const auto t1 = Clock::now();
    SolveStats stats;
    const Eigen::VectorXd x = sys->solver.solve(M, sys->rhs, &stats);
    report.solver_iterations += stats.iterations;
    report.refactorized = report.refactorized || stats.refactorized;
    report.solve_seconds += seconds_since(t1);
    report.unknowns = static_cast<int>(M.rows());
    if (!x.allFinite())
        throw SolverError("step: the linear solve produced non-finite values (tau = " +
                          fmt(tau) + ")");
    std::vector<Vec3> X = c.positions();
    for (int v = 0; v < c.n_vertices(); ++v) X[v] += P.displacement(x, v);
    return X;
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

} // namespace

StepReport TimeStepper::step(Cluster& c, Flow flow, double tau, bool project_onto_walls) {
    if (!(std::isfinite(tau) && tau > 0))
        throw InvalidInput("step: tau must be positive and finite, got " + fmt(tau));
    if (!c.nonlinear()) return step_once(c, flow, tau, project_onto_walls);
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

    std::vector<Vec3> X = solve_once(c, flow, tau, nullptr, report);
    if (c.nonlinear()) iterate_lagged(c, flow, tau, X, report);
    if (project_onto_walls) project_vertices(c, X);
    if (auto [s, f] = find_degenerate_facet(c, X); s >= 0)
        throw GeometryError("step: with tau = " + fmt(tau) + " the step would collapse " +
                            facet_name(s, f) + "; the cluster is unchanged (try a smaller tau)");
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
    return report;
}

namespace {

Eigen::VectorXd flatten(const std::vector<Vec3>& X) {
    Eigen::VectorXd x(3 * X.size());
    for (std::size_t v = 0; v < X.size(); ++v) x.segment<3>(3 * v) = X[v];
    return x;
}

std::vector<Vec3> unflatten(const Eigen::VectorXd& x) {
    std::vector<Vec3> X(x.size() / 3);
    for (std::size_t v = 0; v < X.size(); ++v) X[v] = x.segment<3>(3 * v);
    return X;
}

/// Anderson acceleration (type II, depth m) of a fixed-point map G: from the residuals
/// f_k = G(x_k) - x_k of the last m + 1 iterates, x_{k+1} = G(x_k) - dG gamma with gamma the
/// least-squares minimiser of |f_k - dF gamma|. Plain Picard (x_{k+1} = G(x_k)) on the lagged
/// weights of (3.9) contracts slowly or cycles for large r; this needs a handful of solves.
class Anderson {
  public:
    explicit Anderson(int depth) : depth_(depth) {}
    Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& gx) {
        const Eigen::VectorXd f = gx - x;
        if (has_last_) {
            dF_.push_back(f - f_last_), dG_.push_back(gx - g_last_);
            if (static_cast<int>(dF_.size()) > depth_) dF_.erase(dF_.begin()), dG_.erase(dG_.begin());
        }
        f_last_ = f, g_last_ = gx, has_last_ = true;
        if (dF_.empty()) return gx;
        Eigen::MatrixXd F(f.size(), dF_.size()), Gm(f.size(), dG_.size());
        for (std::size_t j = 0; j < dF_.size(); ++j) F.col(j) = dF_[j], Gm.col(j) = dG_[j];
        const Eigen::VectorXd gamma = F.colPivHouseholderQr().solve(f);
        if (!gamma.allFinite()) return gx;
        return gx - Gm * gamma;
    }

  private:
    int depth_;
    bool has_last_ = false;
    Eigen::VectorXd f_last_, g_last_;
    std::vector<Eigen::VectorXd> dF_, dG_;
};

} // namespace

void TimeStepper::iterate_lagged(Cluster& c, Flow flow, double tau, std::vector<Vec3>& X,
                                 StepReport& report) {
    // (3.9) weighs term l by [gamma_l(nu^{m+1}) / gamma(nu^{m+1})]^(r-1): X^{m+1} is a fixed
    // point of "solve with the weights at the normals of X". The first solve (weights at nu^m)
    // gave X; iterate, accelerated, until a solve no longer moves the positions.
    const double size = cluster_size(c.positions());
    Anderson accel(8); // depth 8: r = 10 at tau = 1e-2 on a coarse sphere in ~30 solves, not 100+
    Eigen::VectorXd x = flatten(X);
    report.fixed_point_iterations = 1;
    for (;;) {
        const std::vector<Vec3> Xk = unflatten(x);
        if (auto [s, f] = find_degenerate_facet(c, Xk); s >= 0)
            throw GeometryError("step: the fixed-point iterate " +
                                std::to_string(report.fixed_point_iterations) + " collapses " +
                                facet_name(s, f) + " (tau = " + fmt(tau) + ")");
        const FacetNormals lagged = facet_normals(c, Xk);
        std::vector<Vec3> G = solve_once(c, flow, tau, &lagged, report);
        ++report.fixed_point_iterations;
        report.fixed_point_change = max_change(G, Xk) / size;
        if (report.fixed_point_change <= fixed_point_.tol) {
            X = std::move(G);
            return;
        }
        if (report.fixed_point_iterations >= fixed_point_.max_iterations)
            throw ConvergenceError(
                "step: the lagged fixed-point iteration for r > 1 did not converge in " +
                std::to_string(report.fixed_point_iterations) + " solves (last relative change " +
                fmt(report.fixed_point_change) + ", tol " + fmt(fixed_point_.tol) +
                ", tau = " + fmt(tau) + ", after " + std::to_string(fixed_point_.max_halvings) +
                " halvings of the step); the cluster is unchanged (try a smaller tau)");
        x = accel.next(x, flatten(G));
    }
}

} // namespace froth
