#pragma once
/// minimize with topological transitions: where the films' equilibrium needs a change of
/// topology (a small triangular film or a short triple line collapsing: minimize stops on a
/// facet angle), the due inverse T1s and T1s are made (run/junction_transitions.h), the mesh
/// is tidied (short edges collapse, films flip to Delaunay), and minimize goes on; as Surface
/// Evolver's users relax a foam with `g`, `t1_edgeswap`, `pop_tri_to_edge`, `t` and `u`.

#include "flows/minimize.h"
#include "run/junction_transitions.h"

#include <vector>

namespace froth {

struct TransitionMinimizeOptions {
    MinimizeOptions minimize;  ///< max_iterations counts over all rounds
    double min_line_fraction = 0.2; ///< WatchOptions::min_line_fraction
    int max_rounds = 100;      ///< minimize runs between transitions, at most
};

struct TransitionMinimizeResult {
    /// The last round's, with iterations, rejected and wall_seconds summed over the rounds
    /// and, where a stop on topology found nothing to make, its stop_reason ending in why.
    MinimizeResult result;
    int rounds = 0;
    std::vector<TransitionEvent> events; ///< step: the round after which it was made
    int collapsed_edges = 0, flipped_edges = 0, relaxed_vertices = 0;
    /// rounds that started with a facet below 0.1 degree that the upkeep left (above 0.01
    /// degree; below, the rounds stop)
    int deferred = 0;
};

/// Minimises c as minimize() does; after each round that stops on a collapsing facet, the
/// junctions that shrank in it are transitioned (or, if none, every small one), then the mesh
/// upkeep, then the next round. Bodies and their targets are kept (no pops).
/// \throw as minimize(); the cluster keeps the transitions made before a throw.
TransitionMinimizeResult minimize_with_transitions(Cluster& c,
                                                   const TransitionMinimizeOptions& options);

} // namespace froth
