#pragma once
/// Evolutions: many steps of one flow with output, progress and a user callback. This is the
/// driver layer above the schemes (flows/) and the writers (io/); it never sees Lua.

#include "flows/stepper.h"
#include "render/snapshot.h"
#include "run/junction_transitions.h"
#include "run/topology_watch.h"

#include <array>
#include <cstdio>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace froth {

struct EvolveOptions {
    Flow flow = Flow::SurfaceDiffusion;
    double tau = 0; ///< the step; with adaptive, the first step
    /// Error-controlled steps (tau = "auto"): order-2 steps whose error estimate
    /// (StepCost::error_estimate, the predictor's local error in the shape,
    /// relative to the cluster's size) must stay below tol; a step that misses it is retried
    /// shorter, and each next tau is chosen from the last estimate, 0.2x to 2x, at most
    /// tau_max (0: no bound). A failing step (collapsing facet, singular system) is retried at
    /// a quarter of its length down to 1e-6 of the first step before it ends the run.
    bool adaptive = false;
    double tol = 1e-4;
    double tau_max = 0;
    /// If > 0, start with steps of tau_start, growing by tau_growth per step up to tau: large
    /// first steps from a non-smooth start (box edges, 90-degree junctions) lose volume.
    double tau_start = 0;
    double tau_growth = 1.1;
    double duration = -1;  ///< evolve for this model time (T); the last step is shortened to hit it
    int steps = -1;        ///< or for this many steps (exactly one of duration/steps is set)
    int every = 0;         ///< write a snapshot every `every` steps (0: first and last only)
    std::string output;    ///< ".pvd" path of a ParaView series; empty: no output
    /// Record t, energy and volumes of every step and write them to <history>.csv and an
    /// energy plot to <history>.svg at the end; empty: no history.
    std::string history;
    /// A state file (io/state_file.h) saved at the start, every `every` steps (when every > 0)
    /// and at the end, each replacing the last: the run can be resumed from it with
    /// froth.load. Empty: none.
    std::string checkpoint;
    /// A path stem: PNG pictures <stem>_000000.png, <stem>_000001.png, ... of the start, every
    /// `every` steps and the end (render/snapshot.h), drawn as `snapshot` says. Empty: none.
    std::string snapshots;
    SnapshotOptions snapshot;
    std::FILE* progress = nullptr; ///< a terminal to draw a progress line on, or nullptr
    /// Called after every step; returning false stops the evolution.
    std::function<bool(const StepReport&)> on_step;
    /// Project wall-attached vertices back onto their walls after every step (off: the
    /// seed's linearised constraint, which keeps the stability bound; see TimeStepper::step).
    bool project_onto_walls = false;
    /// What counts as the approach of a topology change (run/topology_watch.h).
    WatchOptions watch;
    /// Topological transitions (mesh/transitions.h): a body the watch sees vanishing pops
    /// (Evolver's `pop`), a triple line between two quadruple points shorter than
    /// watch.min_line_fraction of the mean edge becomes a film (T1), and the run goes on; false
    /// stops the run there instead. A T1 that cannot be made is noted in the message of the
    /// event that follows. A pop that
    /// cannot be made (the body has more than four neighbouring cells, is all the cluster
    /// has, meets a wall; or the pop would raise the energy) ends the run as without it, the
    /// reason added to the message. With it evolve also keeps the mesh up (collapses, splits,
    /// flips: EvolveResult::collapsed_edges), and in a cluster with quadruple points a
    /// collapsing edge or facet that the upkeep leaves ends the run only below a tenth of the
    /// watch's limits (EvolveResult::deferred).
    bool transitions = true;
    /// The r > 1 iteration of every step (flows/stepper.h).
    FixedPointOptions fixed_point;
    /// Surface diffusion holds the bodies at their target volumes exactly (the default;
    /// TimeStepper::set_exact_volumes); false runs the seed's linear scheme.
    bool exact_volumes = true;
    /// How surface diffusion solves its saddle points (TimeStepper::set_sd_solver).
    SaddleSolver sd_solver = SaddleSolver::Auto;
    /// The order in time of the steps, 1 or 2 (TimeStepper::set_order; the first step of
    /// order 2 is of order 1).
    int order = 1;
    /// The line relaxation time of the steps (TimeStepper::set_line_relaxation; 0: the
    /// seed's schemes).
    double line_relaxation = 0;
};

struct EvolveResult {
    int steps = 0;
    Report last;                     ///< the state at the end
    double wall_seconds = 0;
    double solve_seconds = 0;        ///< summed over the steps
    int factorizations = 0;          ///< numeric factorisations made (the rest reused one)
    double max_energy_increase = 0;  ///< largest relative energy increase of any step (0 if none)
    /// steps retried shorter: adaptive (error or failure), or with transitions (Run::retry)
    int rejected_steps = 0;
    /// "T reached", "steps done", "on_step", "interrupted", "topology: <what, where, when>", or
    /// "no convergence: <...>" (the r > 1 fixed-point iteration of a step failed)
    std::string stop_reason;
    std::optional<TopologyEvent> event; ///< set when the watch or a failing step stopped the run
    std::vector<TransitionEvent> events; ///< the transitions made, in order
    /// Mesh upkeep with transitions: short edges collapsed (at a "collapsing edge"; at a
    /// "collapsing facet" the thin facets' short sides); after a transition long ones split
    /// (longer than the longest edge at the start), edges flipped (after the splits and at a
    /// "collapsing facet") and flat caps' corners moved (at a "collapsing facet")
    int collapsed_edges = 0, split_edges = 0, flipped_edges = 0, relaxed_vertices = 0;
    /// Steps that went on past a collapsing edge or facet no upkeep mended (Run::defer)
    int deferred = 0;
};

/// What an evolve with transitions leaves for the next call on the same cluster, so that calls
/// one after the other (a driver that measures between steps) behave as one long call: the
/// junctions' sizes at the last look and the products of transitions, the mesh size the
/// upkeep keeps (the longest edge at the start of the first call) and whether any call made a
/// transition (which turns the splits of long edges on).
struct TransitionMemory {
    std::optional<JunctionTransitions> junctions; ///< none: no call with transitions yet
    double longest_edge = 0;
    bool transitions_made = false;
    double tau_scale = 1; ///< the next step over tau, below 1 after a retried step
};

/// A step that fails geometrically (GeometryError, SolverError: a collapsing facet, a singular
/// system) or a watch event ends the run with stop_reason "topology: ..." and the last valid
/// state in place. \throw InvalidInput for bad options; other errors propagate, and the
/// cluster then holds the state after the last successful step.
/// `memory` (with EvolveOptions::transitions): the TransitionMemory of the last call on c, used
/// if it fits c (the same bodies and min_line_fraction), and updated for the next.
EvolveResult evolve(Cluster& c, TimeStepper& stepper, const EvolveOptions& options,
                    TransitionMemory* memory = nullptr);

/// The memory as named arrays for a state file ("junctions.*" and "transitions.run"); empty
/// before any call with transitions.
std::vector<NamedValues> save_transition_memory(const TransitionMemory& memory);
/// The memory save_transition_memory wrote, for cluster c (none saved: a fresh memory).
/// \throw InvalidInput for arrays it does not write
TransitionMemory restore_transition_memory(const std::vector<NamedValues>& arrays, const Cluster& c);

/// Saves c, the stepper's history and the transitions' memory (if given) to a state file
/// (c:save, evolve's checkpoints). The stepper then forgets its factorisations, so that this
/// run and one restored from the file take the same next steps bit for bit.
/// \throw IoError, InvalidInput (io/state_file.h)
void save_state(const std::string& path, const Cluster& c, TimeStepper& stepper,
                const TransitionMemory* memory = nullptr);

} // namespace froth
