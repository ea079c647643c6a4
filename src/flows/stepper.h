#pragma once
/// Time stepping of the seed's schemes: mean curvature flow (3.7a,b)/(3.10a,b) solved as the SPD
/// system (4.6b) on CHOLMOD, surface diffusion (3.8a,b)/(3.11a,b) as a symmetric saddle point on
/// UMFPACK (numerics.md §5); r > 1 anisotropies by Newton's method on the nonlinear system of
/// (3.9) (numerics.md "Anisotropic schemes"). Each flow's system keeps its sparsity pattern and symbolic
/// factorisation for the life of the stepper; a numeric factorisation is reused across steps
/// as long as it preconditions GMRES well (solvers/sparse_solvers.h).

#include "assembly/flow_systems.h"
#include "solvers/sparse_solvers.h"

#include <memory>
#include <string>
#include <string_view>

namespace froth {

enum class Flow { MeanCurvature, SurfaceDiffusion };

/// "mcf" or "sd". \throw InvalidInput for anything else.
Flow parse_flow(std::string_view name);
const char* flow_name(Flow flow);

/// The state of a cluster as users see it (c:report()).
struct Report {
    double t = 0, energy = 0;
    std::vector<double> volumes;
    double volume_loss = 0; ///< max relative change of any body volume since the start
    AngleStats angles;            ///< between films at triple lines
    AngleStats quadruple_angles;  ///< between triple lines at quadruple points
    MeshQuality mesh;
    AngleStats contact_angles; ///< between films and walls (count 0 without walls)
    double wall_drift = 0;     ///< max distance of a wall-attached vertex from its wall
};
Report make_report(const Cluster& c);

/// A report after one step, plus what the step cost.
struct StepReport : Report {
    Flow flow = Flow::MeanCurvature;
    double tau = 0;
    double energy_before = 0;
    double assemble_seconds = 0, solve_seconds = 0;
    int unknowns = 0;
    int solver_iterations = 0; ///< GMRES iterations on top of the (possibly lagged) factor
    bool refactorized = false; ///< this step made a new numeric factorisation
    /// r > 1 only (0 otherwise): the linear solves of the nonlinear iteration (one per
    /// Newton step), and the last full Newton update max_v |dX_v|_inf relative to the
    /// cluster's size.
    int fixed_point_iterations = 0;
    double fixed_point_change = 0;
    /// Steps of the scheme this step was made of: 1, or more when an r > 1 iteration failed
    /// to converge and the step was halved (FixedPointOptions::max_halvings).
    int substeps = 1;
    /// Volume-exact surface diffusion only (0 otherwise): the linear solves of the fixed point
    /// for the step's averaged normals (assembly/exact_volumes.h), and the largest relative
    /// deviation |V_b - V*_b| / V*_b of a body from its target volume after the step.
    int volume_iterations = 0;
    double volume_error = 0;
};

/// The nonlinear iteration for r > 1 (Newton's method on (3.9), numerics.md "Anisotropic
/// schemes"): stop when a full Newton update moves no coordinate by more than tol relative to
/// the cluster's size. A step whose iteration needs more than max_iterations solves (or finds
/// no descent) is split into two steps of tau/2, at most max_halvings times in a row; beyond
/// that it is a ConvergenceError. (The name is the seed's: the solution is the fixed point of
/// its lagged iteration, §4.2.)
struct FixedPointOptions {
    double tol = 1e-8;
    int max_iterations = 60;
    int max_halvings = 4;
};

/// Steps one cluster; keep one stepper per cluster (it caches that cluster's patterns).
class TimeStepper {
  public:
    TimeStepper();
    ~TimeStepper();
    /// A copy carries everything the next step depends on (options, patterns, the last
    /// factorisations, the warm start), so it steps bit for bit as the original would.
    TimeStepper(const TimeStepper& other);
    TimeStepper& operator=(const TimeStepper&) = delete;
    /// Takes one step of length tau; with project_onto_walls, wall-attached vertices are then
    /// projected back onto their walls (off by default: it voids the stability bound).
    /// On any throw the cluster is unchanged.
    /// \throw InvalidInput (tau), GeometryError (degenerate facets before or after the step),
    ///        SolverError (singular or non-finite system), ConvergenceError (r > 1 iteration).
    StepReport step(Cluster& c, Flow flow, double tau, bool project_onto_walls = false);
    /// Forgets every cached pattern and factorisation (after the cluster's mesh was replaced).
    void reset();
    /// \throw InvalidInput unless tol > 0, max_iterations >= 2 and max_halvings in 0..20.
    void set_fixed_point(FixedPointOptions o);
    const FixedPointOptions& fixed_point() const { return fixed_point_; }
    /// With exact (the default), surface diffusion keeps every body at its target volume (the
    /// structure-preserving step of assembly/exact_volumes.h, 2-4 solves per step); without,
    /// it runs the seed's linear scheme (3.6)/(3.8), which loses O(tau^2) of volume per step.
    void set_exact_volumes(bool exact) { exact_volumes_ = exact; }
    bool exact_volumes() const { return exact_volumes_; }

  private:
    struct System;
    StepReport step_once(Cluster& c, Flow flow, double tau, bool project_onto_walls);
    StepReport step_halving(Cluster& c, Flow flow, double tau, bool project, int halvings);
    /// Assembles the step's system (matrix and rhs) with the r > 1 weights at `lagged`.
    System& assemble(Cluster& c, Flow flow, double tau, const PositionBasis& P,
                     const FacetNormals* lagged, StepReport& report);
    /// One linear solve of the step's system with the r > 1 weights at `lagged`; returns the
    /// reduced unknowns z (positions X^m + T z first).
    Eigen::VectorXd solve_once(Cluster& c, Flow flow, double tau, const PositionBasis& P,
                               const FacetNormals* lagged, StepReport& report);
    /// Newton's method for the r > 1 system (3.9), from X^m to convergence; returns z.
    Eigen::VectorXd solve_newton(Cluster& c, Flow flow, double tau, const PositionBasis& P,
                                 StepReport& report);
    /// Volume-exact surface diffusion: the fixed point over the averaged normals; returns z.
    Eigen::VectorXd solve_exact_volumes(Cluster& c, double tau, const PositionBasis& P,
                                        StepReport& report);
    static void check_no_body_vanishes(const Cluster& c, const std::vector<Vec3>& X, double tau);
    FixedPointOptions fixed_point_;
    bool exact_volumes_ = true;
    // Set during a volume-exact step: the pair weights and kappa rows assemble() uses.
    const PairGeometry* weights_ = nullptr;
    const Eigen::VectorXd* kappa_rhs_ = nullptr;
    // The last volume-exact step's solution, its tau and the positions it ended at: the next
    // step starts its fixed point from it (positions scaled by the taus) when it starts there.
    Eigen::VectorXd last_z_;
    double last_tau_ = 1;
    std::vector<Vec3> last_end_;
    int revision_ = -1; ///< the cluster's assembly_revision() the patterns were built for
    std::unique_ptr<System> mcf_, sd_;
    std::unique_ptr<KappaBasis> Z_;
};

} // namespace froth
