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

StepReport TimeStepper::step(Cluster& c, Flow flow, double tau, bool project_onto_walls) {
    if (!(std::isfinite(tau) && tau > 0))
        throw InvalidInput("step: tau must be positive and finite, got " + fmt(tau));
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

    const auto t0 = Clock::now();
    const PairGeometry g = pair_geometry(c);
    const PositionBasis P(c);
    std::unique_ptr<System>& sys = flow == Flow::MeanCurvature ? mcf_ : sd_;
    if (!sys)
        sys = std::make_unique<System>(flow == Flow::MeanCurvature ? Factorization::Cholesky
                                                                   : Factorization::LU);
    if (flow == Flow::MeanCurvature) {
        assemble_mcf(c, g, P, tau, sys->matrix, sys->rhs);
    } else {
        if (!Z_) Z_ = std::make_unique<KappaBasis>(kappa_basis(c));
        assemble_sd(c, g, *Z_, P, tau, sys->matrix, sys->rhs);
    }
    const SparseMatrix& M = sys->matrix.finish();
    report.assemble_seconds = seconds_since(t0);

    const auto t1 = Clock::now();
    SolveStats stats;
    const Eigen::VectorXd x = sys->solver.solve(M, sys->rhs, &stats);
    report.solver_iterations = stats.iterations;
    report.refactorized = stats.refactorized;
    report.solve_seconds = seconds_since(t1);
    report.unknowns = static_cast<int>(M.rows());
    if (!x.allFinite())
        throw SolverError("step: the linear solve produced non-finite values (tau = " +
                          fmt(tau) + ")");

    std::vector<Vec3> X = c.positions();
    for (int v = 0; v < c.n_vertices(); ++v) X[v] += P.displacement(x, v);
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

} // namespace froth
