#pragma once
/// Time stepping of the isotropic schemes of the seed: mean curvature flow (3.5a,b) solved as
/// the SPD system (4.6b) on CHOLMOD, surface diffusion (3.6a,b) as a symmetric saddle point on
/// UMFPACK (numerics.md §5). Each flow's system keeps its sparsity pattern and symbolic
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
};

/// Steps one cluster; keep one stepper per cluster (it caches that cluster's patterns).
class TimeStepper {
  public:
    TimeStepper();
    ~TimeStepper();
    /// Takes one step of length tau; with project_onto_walls, wall-attached vertices are then
    /// projected back onto their walls (off by default: it voids the stability bound).
    /// On any throw the cluster is unchanged.
    /// \throw InvalidInput (tau), GeometryError (degenerate facets before or after the step),
    ///        SolverError (singular or non-finite system).
    StepReport step(Cluster& c, Flow flow, double tau, bool project_onto_walls = false);

  private:
    struct System;
    std::unique_ptr<System> mcf_, sd_;
    std::unique_ptr<KappaBasis> Z_;
};

} // namespace froth
