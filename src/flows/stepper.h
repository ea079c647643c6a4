#pragma once
/// Time stepping: TimeStepper drives the schemes of schemes/ (mean_curvature.h: (3.5)/(3.7)/
/// (3.10) as the SPD system (4.6b) on CHOLMOD; surface_diffusion.h: (3.6)/(3.8)/(3.11) as a
/// symmetric saddle point on UMFPACK, by default in its volume-exact form; r > 1 anisotropies
/// by Newton's method on (3.9), schemes/scheme.h). Around a scheme's solve it does what every
/// step needs: the facet checks before and after, the wall projection, halving of steps whose
/// iteration fails, the update of positions and time, the report, and the target volumes.
/// Each scheme keeps its sparsity pattern and symbolic factorisation for the life of the
/// stepper; a numeric factorisation is reused across steps as long as it preconditions GMRES
/// well (solvers/sparse_solvers.h).

#include "schemes/mean_curvature.h"
#include "schemes/surface_diffusion.h"

#include <memory>
#include <string>

namespace froth {

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

/// A report after one step, plus what the step cost (schemes/scheme.h StepCost).
struct StepReport : Report, StepCost {
    Flow flow = Flow::MeanCurvature;
    double tau = 0;
    double energy_before = 0;
    /// Steps of the scheme this step was made of: 1, or more when an r > 1 or volume-exact
    /// iteration failed to converge and the step was halved (FixedPointOptions::max_halvings).
    int substeps = 1;
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
    /// With tolerance > 0, an order-2 step whose error_estimate (schemes/scheme.h StepCost)
    /// exceeds it is not taken: StepRejected, the cluster unchanged (tau = "auto" in evolve).
    StepReport step(Cluster& c, Flow flow, double tau, bool project_onto_walls = false,
                    double tolerance = 0);
    /// Forgets every cached pattern and factorisation (after the cluster's mesh was replaced).
    void reset();
    /// The schemes' history (Scheme::save_history), for a state file of c; the order-2
    /// history only while c is still in the state the last step left (a loaded copy must not
    /// revive one the original would no longer use).
    std::vector<NamedValues> history(const Cluster& c) const;
    /// Puts a saved history back (on the cluster it was saved with). \throw InvalidInput
    void restore_history(const Cluster& c, const std::vector<NamedValues>& history);
    /// Forgets the factorisations, keeping the history: called where a state is saved, so that
    /// the run that saved and a run restored from the file take the same next step.
    void drop_factorizations();
    /// \throw InvalidInput unless tol > 0, max_iterations >= 2 and max_halvings in 0..20.
    void set_fixed_point(FixedPointOptions o);
    const FixedPointOptions& fixed_point() const { return fixed_point_; }
    /// With exact (the default), surface diffusion keeps every body at its target volume (the
    /// structure-preserving step of assembly/exact_volumes.h, 2-4 solves per step); without,
    /// it runs the seed's linear scheme (3.6)/(3.8), which loses O(tau^2) of volume per step.
    void set_exact_volumes(bool exact) { exact_volumes_ = exact; }
    bool exact_volumes() const { return exact_volumes_; }
    /// How surface diffusion solves its saddle points (SaddleSolver: an LU, the block
    /// preconditioner, or the blocks for large systems); the answer is the same to the solver's
    /// backward error.
    void set_sd_solver(SaddleSolver how) { sd_solver_ = how; }
    SaddleSolver sd_solver() const { return sd_solver_; }
    /// The order in time of the steps: 1 (the seed's schemes) or 2 (BDF2, schemes/bdf2.h).
    /// An order-2 step needs the previous step: the stepper keeps its start while it steps
    /// with order 2, and the first step after any other change of the cluster (a new mesh,
    /// moved or fixed vertices, other materials, another flow) is of order 1.
    /// \throw InvalidInput for another order.
    void set_order(int order);
    int order() const { return order_; }
    /// The line relaxation time of the steps (Scheme::set_line_relaxation; numerics.md "Line
    /// vertices along their lines"): 0, the default, is the seed's schemes, whose triple-line
    /// vertices settle along their lines within each step however short it is.
    /// \throw InvalidInput unless finite and >= 0.
    void set_line_relaxation(double time);
    double line_relaxation() const { return line_relaxation_; }

  private:
    StepReport step_once(Cluster& c, Flow flow, double tau, bool project_onto_walls,
                         double tolerance);
    StepReport step_halving(Cluster& c, Flow flow, double tau, bool project, int halvings,
                            double tolerance);
    /// The scheme of a flow, made on first use.
    Scheme& scheme(Flow flow);
    static void check_no_body_vanishes(const Cluster& c, const std::vector<Vec3>& X, double tau);
    /// The order-2 step's history: the last step's start X^{m-1}, its length and flow, and the
    /// state it ended in (positions X^m and the cluster's materials revision); valid only while
    /// the cluster is still in that state.
    struct Previous {
        std::vector<Vec3> start, end;
        double tau = 0;
        Flow flow = Flow::MeanCurvature;
        int revision = -1;
    };
    bool continues_previous(const Cluster& c, Flow flow) const;
    FixedPointOptions fixed_point_;
    bool exact_volumes_ = true;
    SaddleSolver sd_solver_ = SaddleSolver::Auto;
    int order_ = 1;
    double line_relaxation_ = 0;
    Previous previous_;
    std::unique_ptr<MeanCurvatureScheme> mcf_;
    std::unique_ptr<SurfaceDiffusionScheme> sd_;
};

} // namespace froth
