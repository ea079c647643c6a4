#pragma once
/// One interface for the time-discrete schemes the stepper drives (flows/stepper.h). A scheme
/// owns the linear system of its step in the reduced unknowns z (positions first,
/// X^{m+1} = X^m + T z with T the wall tangent bases of assembly/position_basis.h, then the
/// scheme's own unknowns), says which factorisation that system takes, and solves a step:
///   mean_curvature.h     (3.5)/(3.7)/(3.10) eliminated to (4.6b), SPD: CHOLMOD
///   surface_diffusion.h  (3.6)/(3.8)/(3.11), a symmetric saddle point: UMFPACK; and its
///                        volume-exact form (volume_exact_sd.cpp, assembly/exact_volumes.h)
/// Each has a second-order form (bdf2.h: the same system on a predictor surface, plus two
/// right-hand sides), taken when the stepper has the previous step's positions.
/// Shared here: one linear solve of the assembled system (a factorisation reused across steps
/// as a GMRES preconditioner, solvers/sparse_solvers.h) and, for r > 1 anisotropies, Newton's
/// method on the nonlinear system of (3.9) (numerics.md "Anisotropic schemes"). The stepper
/// does what every scheme needs around that: the checks before and after, step halving, the
/// update of the cluster and its report.

#include "assembly/stiffness.h"
#include "schemes/bdf2.h"
#include "solvers/sparse_solvers.h"

#include <memory>
#include <string_view>

namespace froth {

enum class Flow { MeanCurvature, SurfaceDiffusion };

/// "mcf" or "sd". \throw InvalidInput for anything else.
Flow parse_flow(std::string_view name);
const char* flow_name(Flow flow);

/// What one step cost and how its iterations went (part of flows/stepper.h StepReport).
struct StepCost {
    double assemble_seconds = 0, solve_seconds = 0;
    int unknowns = 0;
    int solver_iterations = 0; ///< GMRES iterations on top of the (possibly lagged) factor
    bool refactorized = false; ///< this step made a new numeric factorisation
    /// r > 1 only (0 otherwise): the linear solves of the nonlinear iteration (one per
    /// Newton step), and the last full Newton update max_v |dX_v|_inf relative to the
    /// cluster's size.
    int fixed_point_iterations = 0;
    double fixed_point_change = 0;
    /// Volume-exact surface diffusion only (0 otherwise): the linear solves of the fixed point
    /// for the step's averaged normals (assembly/exact_volumes.h), and the largest relative
    /// deviation |V_b - V*_b| / V*_b of a body from its target volume after the step.
    int volume_iterations = 0;
    double volume_error = 0;
    /// The order in time of the step's scheme: 2 for a BDF2 step (bdf2.h), 1 otherwise
    /// (also the first step of an order-2 run, which has no history yet).
    int order = 1;
    /// Surface diffusion: a solve of the step used the saddle point's block preconditioner
    /// (solvers/saddle_point.h) rather than an LU.
    bool saddle_blocks = false;
    /// Order 2 only (0 otherwise): the shape's difference between the step and its predictor
    /// (the BDF2 step with the geometry of X^m), max_v |Q_v^T (X_v - X~_v)| over the cluster's
    /// size (Q_v the unit normals of the vertex's surfaces; schemes/bdf2.h shape_difference):
    /// the predictor's local error, O(tau^2), an upper estimate of this step's.
    double error_estimate = 0;
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

class Scheme {
  public:
    explicit Scheme(Factorization kind) : solver_(kind, true, Ordering::NestedDissection) {}
    virtual ~Scheme() = default;
    /// A copy with the same patterns, factorisations and history: it steps bit for bit as this.
    virtual std::unique_ptr<Scheme> clone() const = 0;
    /// True when a step keeps every body at its target volume (then the stepper leaves the
    /// targets alone; otherwise it moves them to the volumes the step left).
    virtual bool holds_volumes(const Cluster& c) const = 0;
    /// Whether steps that fail to converge are halved (the nonlinear solves).
    virtual bool iterative(const Cluster& c) const { return c.nonlinear(); }
    /// The reduced unknowns z of one step of length tau from the cluster's positions.
    /// \throw SolverError (singular or non-finite system), ConvergenceError (iterations).
    virtual Eigen::VectorXd solve(const Cluster& c, double tau, const PositionBasis& P,
                                  const FixedPointOptions& fp, StepCost& cost);
    /// The order-2 step (bdf2.h) of length tau from the cluster c at X^m, whose previous step,
    /// of length previous_tau, started at `previous`: the linear BDF2 system on X^m as the
    /// predictor, then the same system on the predictor (solve_corrector), on one solver.
    /// \throw SolverError (singular or non-finite system)
    Eigen::VectorXd solve_bdf2(const Cluster& c, const std::vector<Vec3>& previous,
                               double previous_tau, double tau, const PositionBasis& P,
                               StepCost& cost);
    /// The line relaxation time t_r >= 0 of every step (0: the seed's schemes; numerics.md
    /// "Line vertices along their lines"): each system gains t_r / tau k_v t_v t_v^T in the
    /// position rows of every triple-line vertex v, t_v the line's direction there (geometry.h
    /// line_direction) and k_v the stiffness diagonal (assembly/stiffness.h). A line vertex
    /// then moves along its line at the velocity -t_v . (A X)_v / (t_r k_v) where the seed's
    /// schemes let it settle anew within every step, however short.
    /// Switching it on or off changes the systems' patterns, so their factorisations go.
    void set_line_relaxation(double time) {
        if ((time > 0) != (line_relaxation_ > 0)) drop_systems();
        line_relaxation_ = time;
    }
    /// Forgets the patterns, factorisations and history (the cluster's mesh was replaced).
    virtual void reset();
    /// Forgets the factorisations and patterns, not the history: the next step factorises
    /// afresh, as a scheme restored from a state file does, so both continue bit for bit alike
    /// (a lagged factor changes a GMRES solve's round-off, not its tolerance).
    void drop_factorizations() { drop_systems(); }
    /// What the next step depends on beyond the cluster (the volume-exact step's warm start),
    /// as named arrays for a state file.
    virtual void save_history(std::vector<NamedValues>&) const {}
    /// Puts back what save_history gave, on the cluster it was saved with; arrays of other
    /// schemes are ignored. \throw InvalidInput for an array of the wrong size.
    virtual void restore_history(const Cluster&, const std::vector<NamedValues>&) {}

  protected:
    /// Drops the assembled patterns and factorisations (not the history): when the cluster's
    /// assembly revision changes, every system of the scheme starts afresh.
    virtual void drop_systems();
    Scheme(const Scheme&) = default;
    /// Assembles the step's matrix and right-hand side into matrix_ and rhs_, with the pair
    /// geometry g and the r > 1 weights at `lagged` (null: each facet's normal on X^m).
    virtual void assemble_system(const Cluster& c, const PairGeometry& g, const PositionBasis& P,
                                 double tau, const FacetNormals* lagged) = 0;
    /// assemble_system with the cluster's pair geometry (or weights_ when set), timed; the
    /// patterns are rebuilt when the cluster's assembly revision changed.
    void assemble(const Cluster& c, double tau, const PositionBasis& P, const FacetNormals* lagged,
                  StepCost& cost);
    /// One linear solve of the step's system with the r > 1 weights at `lagged`, to the
    /// backward error `tolerance`.
    Eigen::VectorXd solve_once(const Cluster& c, double tau, const PositionBasis& P,
                               const FacetNormals* lagged, StepCost& cost,
                               double tolerance = 1e-15);
    /// The order-2 corrector: one solve of the first-order system of step s.effective_tau()
    /// on s.predictor with the BDF2 right-hand sides, on the predictor's lagged factorisation.
    virtual Eigen::VectorXd solve_corrector(const Cluster& c, const Bdf2Step& s,
                                            const PositionBasis& P, StepCost& cost);
    /// The linear BDF2 system of s on s.predictor, solved to the backward error `tolerance`.
    Eigen::VectorXd solve_linear_bdf2(const Bdf2Step& s, const PositionBasis& P, StepCost& cost,
                                      double tolerance);
    /// Newton's method for the r > 1 system (3.9), from X^m to convergence.
    Eigen::VectorXd solve_newton(const Cluster& c, double tau, const PositionBasis& P,
                                 const FixedPointOptions& fp, StepCost& cost);

    SparseBuilder matrix_;
    Eigen::VectorXd rhs_;
    /// The step's solver; an order-2 step's predictor and corrector share it (Scheme::solve_bdf2).
    SparseDirectSolver solver_;
    /// Set by a scheme that assembles with other pair weights than the cluster's own (the
    /// volume-exact step's averaged normals); null otherwise.
    const PairGeometry* weights_ = nullptr;
    /// Set during an order-2 corrector (solve_corrector): assemble adds its shift term, and each
    /// scheme's assemble_system its memory term; null otherwise.
    const Bdf2Step* bdf2_ = nullptr;
    /// The line relaxation time (set_line_relaxation).
    double line_relaxation_ = 0;
    /// Order 2 with line_relaxation_ > 0: its memory term t_r / tau k_v t_v t_v^T E_v (bdf2.h)
    /// added to rhs_'s position rows; tau is the corrector's tau' = tau / a.
    void add_line_relaxation_memory(const Cluster& c, const PairGeometry& g, const PositionBasis& P,
                                    double tau);

  private:
    // r > 1: the weight derivative of Newton's method and the (unsymmetric) Jacobian's solver.
    SparseBuilder weight_jacobian_;
    SparseDirectSolver newton_{Factorization::LU};
    int revision_ = -1; ///< the cluster's assembly_revision() the patterns were built for
};

/// Solves M x = b, adding the cost; non-finite results are a SolverError. `tolerance`: the
/// backward error to reach (SparseDirectSolver::solve).
Eigen::VectorXd solve_checked(SparseDirectSolver& solver, const SparseMatrix& M,
                              const Eigen::VectorXd& b, double tau, StepCost& cost,
                              double tolerance = 1e-15);

/// Adds `weight` k_v t_v t_v^T to the position block of every triple-line vertex v (t_v
/// geometry.h line_direction, k_v assembly/stiffness.h stiffness_diagonal): the term of
/// Scheme::set_line_relaxation, weight = t_r / tau. Nothing for weight 0.
void add_line_relaxation(const Cluster& c, const PairGeometry& g, const PositionBasis& P,
                         double weight, SparseBuilder& M);

/// X^m + T z: the positions of a solution z of a step's system.
std::vector<Vec3> displaced(const Cluster& c, const PositionBasis& P, const Eigen::VectorXd& z);

/// The diagonal of the bounding box: the scale of the relative fixed-point changes.
double cluster_size(const std::vector<Vec3>& X);

} // namespace froth
