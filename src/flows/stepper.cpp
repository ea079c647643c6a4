#include "flows/stepper.h"

#include "core/errors.h"
#include "core/format.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace froth {
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

TimeStepper::TimeStepper() = default;
TimeStepper::~TimeStepper() = default;

TimeStepper::TimeStepper(const TimeStepper& o)
    : fixed_point_(o.fixed_point_), exact_volumes_(o.exact_volumes_), sd_solver_(o.sd_solver_),
      order_(o.order_), line_relaxation_(o.line_relaxation_),
      previous_(o.previous_), mcf_(o.mcf_ ? std::make_unique<MeanCurvatureScheme>(*o.mcf_) : nullptr),
      sd_(o.sd_ ? std::make_unique<SurfaceDiffusionScheme>(*o.sd_) : nullptr) {}

void TimeStepper::reset() {
    if (mcf_) mcf_->reset();
    if (sd_) sd_->reset();
    previous_ = Previous();
}

std::vector<NamedValues> TimeStepper::history(const Cluster& c) const {
    std::vector<NamedValues> h;
    if (mcf_) mcf_->save_history(h);
    if (sd_) sd_->save_history(h);
    if (!previous_.end.empty() && previous_.end == c.positions() &&
        previous_.revision == c.materials_revision()) {
        std::vector<double> start;
        start.reserve(3 * previous_.start.size());
        for (const Vec3& x : previous_.start)
            start.insert(start.end(), {x[0], x[1], x[2]});
        h.push_back({"bdf2.start", std::move(start)});
        h.push_back({"bdf2.tau", {previous_.tau}});
        h.push_back({"bdf2.flow", {previous_.flow == Flow::MeanCurvature ? 0.0 : 1.0}});
    }
    return h;
}

void TimeStepper::restore_history(const Cluster& c, const std::vector<NamedValues>& history) {
    reset();
    scheme(Flow::MeanCurvature).restore_history(c, history);
    scheme(Flow::SurfaceDiffusion).restore_history(c, history);
    const auto find = [&](const char* name) { return find_named(history, name); };
    const std::vector<double>*start = find("bdf2.start"), *tau = find("bdf2.tau"),
                           *flow = find("bdf2.flow");
    if (!start && !tau && !flow) return;
    if (!start || !tau || !flow || tau->size() != 1 || !(tau->front() > 0) ||
        flow->size() != 1 || (flow->front() != 0 && flow->front() != 1) ||
        start->size() != 3 * static_cast<std::size_t>(c.n_vertices()))
        throw InvalidInput("order-2 history: bdf2.start, bdf2.tau and bdf2.flow must come "
                           "together, with 3 numbers per vertex, one tau > 0 and a flow 0 or 1");
    previous_.start.resize(c.n_vertices());
    for (int v = 0; v < c.n_vertices(); ++v)
        previous_.start[v] = Vec3((*start)[3 * v], (*start)[3 * v + 1], (*start)[3 * v + 2]);
    previous_.end = c.positions();
    previous_.tau = tau->front();
    previous_.flow = flow->front() == 0 ? Flow::MeanCurvature : Flow::SurfaceDiffusion;
    previous_.revision = c.materials_revision();
}

void TimeStepper::set_order(int order) {
    if (order != 1 && order != 2)
        throw InvalidInput("step: order must be 1 or 2, got " + std::to_string(order));
    order_ = order;
}

void TimeStepper::set_line_relaxation(double time) {
    if (!(std::isfinite(time) && time >= 0))
        throw InvalidInput("step: line_relaxation must be a finite time >= 0, got " + fmt(time));
    line_relaxation_ = time;
}

bool TimeStepper::continues_previous(const Cluster& c, Flow flow) const {
    return order_ == 2 && !previous_.end.empty() && previous_.flow == flow &&
           previous_.revision == c.materials_revision() && previous_.end == c.positions();
}

void TimeStepper::drop_factorizations() {
    if (mcf_) mcf_->drop_factorizations();
    if (sd_) sd_->drop_factorizations();
}

Scheme& TimeStepper::scheme(Flow flow) {
    if (flow == Flow::MeanCurvature) {
        if (!mcf_) mcf_ = std::make_unique<MeanCurvatureScheme>();
        mcf_->set_line_relaxation(line_relaxation_);
        return *mcf_;
    }
    if (!sd_) sd_ = std::make_unique<SurfaceDiffusionScheme>(exact_volumes_);
    sd_->set_exact_volumes(exact_volumes_);
    sd_->set_line_relaxation(line_relaxation_);
    sd_->set_saddle_solver(sd_solver_);
    return *sd_;
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

StepReport TimeStepper::step(Cluster& c, Flow flow, double tau, bool project_onto_walls,
                             double tolerance) {
    if (!(std::isfinite(tau) && tau > 0))
        throw InvalidInput("step: tau must be positive and finite, got " + fmt(tau));
    if (scheme(flow).holds_volumes(c)) check_filled_box_targets(c, "step");
    if (!scheme(flow).iterative(c)) return step_once(c, flow, tau, project_onto_walls, tolerance);
    const std::vector<Vec3> X = c.positions();
    const double t = c.time();
    Previous previous = previous_;
    try {
        return step_halving(c, flow, tau, project_onto_walls, fixed_point_.max_halvings,
                            tolerance);
    } catch (const Error&) { // the first half may have been taken
        c.set_positions(X);
        c.set_time(t);
        previous_ = std::move(previous);
        throw;
    }
}

StepReport TimeStepper::step_halving(Cluster& c, Flow flow, double tau, bool project,
                                     int halvings, double tolerance) {
    try {
        return step_once(c, flow, tau, project, tolerance);
    } catch (const ConvergenceError&) {
        if (halvings == 0) throw;
    }
    // Two converged steps of tau/2 are two steps of the scheme: the bound (3.21) still holds.
    StepReport first = step_halving(c, flow, tau / 2, project, halvings - 1, tolerance);
    StepReport r = step_halving(c, flow, tau / 2, project, halvings - 1, tolerance);
    r.tau = tau;
    r.energy_before = first.energy_before;
    r.substeps += first.substeps;
    r.volume_iterations += first.volume_iterations;
    r.fixed_point_iterations += first.fixed_point_iterations;
    r.assemble_seconds += first.assemble_seconds;
    r.solve_seconds += first.solve_seconds;
    r.solver_iterations += first.solver_iterations;
    r.refactorized = r.refactorized || first.refactorized;
    r.saddle_blocks = r.saddle_blocks || first.saddle_blocks;
    r.error_estimate = std::max(r.error_estimate, first.error_estimate);
    return r;
}

StepReport TimeStepper::step_once(Cluster& c, Flow flow, double tau, bool project_onto_walls,
                                  double tolerance) {
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
    Scheme& chosen = scheme(flow);
    // Every vertex fixed: nothing moves (and SD's kappa block alone is singular on constants).
    Eigen::VectorXd z(0);
    if (P.size() > 0 && continues_previous(c, flow))
        z = chosen.solve_bdf2(c, previous_.start, previous_.tau, tau, P, report);
    else if (P.size() > 0)
        z = chosen.solve(c, tau, P, fixed_point_, report);
    if (tolerance > 0 && report.error_estimate > tolerance)
        throw StepRejected("step: the error estimate " + fmt(report.error_estimate) +
                               " exceeds the tolerance " + fmt(tolerance) + " (tau = " +
                               fmt(tau) + "); the cluster is unchanged",
                           report.error_estimate);
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
    if (!chosen.holds_volumes(c) && c.n_bodies() > 0) {
        const std::vector<double> initial = c.initial_volumes();
        c.set_volume_references(initial, report.volumes);
    }
    if (order_ == 2)
        previous_ = {std::move(X_before), c.positions(), tau, flow, c.materials_revision()};
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

} // namespace froth
