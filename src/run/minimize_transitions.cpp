// minimize with topological transitions (minimize_transitions.h).
#include "run/minimize_transitions.h"

#include "mesh/transitions.h"
#include "run/topology_watch.h"

#include <algorithm>
#include <numeric>
#include <optional>
#include <string>

namespace froth {
namespace {

/// Facets with a corner below this (degrees) lose their shortest side in the upkeep between
/// rounds: five times minimize's collapse angle, ten times the watch's.
constexpr double kNeedleAngle = 5;

bool stopped_on_a_facet(const MinimizeResult& r) {
    return r.stop_reason.rfind("topology: a facet angle", 0) == 0;
}

/// The due transitions of one look, inverse T1s first, then T1s, then pinches of closing
/// waists; with `force` every small junction and waist.
int make_transitions(Cluster& c, JunctionTransitions& junctions, bool force, int round,
                     const std::vector<int>& bodies, std::vector<TransitionEvent>& events) {
    constexpr int kMaxPerRound = 64; // a bound, should transitions cycle
    int made = 0;
    while (made < kMaxPerRound) {
        TransitionEvent event;
        std::optional<Cluster> changed = junctions.make(c, true, force, bodies, event);
        if (!changed) changed = junctions.make(c, false, force, bodies, event);
        if (!changed) changed = junctions.pinch(c, junctions.t1_length(c), force, bodies, event);
        if (!changed) break;
        c = std::move(*changed);
        event.step = round;
        events.push_back(std::move(event));
        ++made;
    }
    return made;
}

/// A sliver the upkeep leaves below this corner angle (degrees; a tenth of minimize's collapse
/// limit) is deferred: the next round starts with it (and stops once its angles halve).
constexpr double kSliverAngle = 0.1;
/// Below this (a tenth of kSliverAngle, as evolve's deferred defects) the rounds stop.
constexpr double kHardSliverAngle = 0.01;
/// A round after transitions starts at the tau the last one reached over this.
constexpr double kRoundTauDrop = 64;

/// A facet with a corner angle below `angle` degrees that the transitions and the upkeep
/// left, named; as in evolve with transitions, an angle facing a one-edge line between
/// quadruple points counts ten times (that line's T1 removes the needle).
std::optional<std::string> sliver_left(const Cluster& c, double angle = kSliverAngle) {
    WatchOptions w;
    w.min_volume_fraction = 0;
    w.min_edge_fraction = 0;
    w.lines_to_transitions = true;
    w.min_facet_angle = angle;
    w.self_intersection_every = 0;
    const std::optional<TopologyEvent> e = TopologyWatch(w).check(c, 0);
    if (!e) return std::nullopt;
    return e->message.substr(0, e->message.rfind(" at t = "));
}

/// The shortest side of every facet with a corner below kNeedleAngle collapses.
EdgeCollapseResult collapse_needles(const Cluster& c) {
    EdgeCollapseCriteria needles;
    needles.needle_angle = kNeedleAngle;
    return collapse_edges(c, needles);
}

/// Short edges collapse, film vertices of three neighbours go, the films flip to Delaunay, the
/// flat caps the flips left open and the thin facets' short sides collapse (evolve's upkeep);
/// the number of collapses.
int tidy_mesh(Cluster& c, TransitionMinimizeResult& out) {
    EdgeCollapseCriteria short_or_lone;
    short_or_lone.min_length = 0.05 * mean_edge_length(c);
    short_or_lone.valence_three = true;
    short_or_lone.slits = false; // (EdgeCollapseCriteria::slits)
    EdgeCollapseResult collapsed = collapse_edges(c, short_or_lone);
    if (collapsed.cluster) c = std::move(*collapsed.cluster);
    EquiangulateResult flipped = equiangulate(c);
    if (flipped.cluster) c = std::move(*flipped.cluster);
    out.flipped_edges += flipped.flips;
    VertexRelaxResult relaxed = relax_flat_corners(c, 5);
    if (relaxed.cluster) c = std::move(*relaxed.cluster);
    out.relaxed_vertices += relaxed.moved;
    EdgeCollapseResult thin = collapse_needles(c);
    if (thin.cluster) c = std::move(*thin.cluster);
    out.collapsed_edges += collapsed.collapsed + thin.collapsed;
    return collapsed.collapsed + thin.collapsed;
}

/// True if more passes of the needles' collapse and the flips leave a sliver (sliver_left).
/// A pass collapses only in disjoint neighbourhoods, so a sliver next to one that a pass took
/// can be left for the next: the 1000-cell foam stopped after 16 iterations on a flat cap
/// of 0.06 degrees between two lines, which more passes removed (the smallest angle 0.059 ->
/// 0.16 -> 0.98 degrees in two).
bool sliver_left_after_passes(Cluster& c, TransitionMinimizeResult& out) {
    constexpr int kMorePasses = 4;
    bool sliver = sliver_left(c).has_value();
    for (int pass = 0; sliver && pass < kMorePasses; ++pass) {
        EdgeCollapseResult thin = collapse_needles(c);
        EquiangulateResult flipped = equiangulate(thin.cluster ? *thin.cluster : c);
        if (!thin.cluster && !flipped.cluster) break;
        if (flipped.cluster) c = std::move(*flipped.cluster);
        else c = std::move(*thin.cluster);
        out.collapsed_edges += thin.collapsed;
        out.flipped_edges += flipped.flips;
        sliver = sliver_left(c).has_value();
    }
    return sliver;
}

/// After a round's transitions and upkeep (`forced`: the transitions were forced): the sliver
/// the rounds stop on, if any. One that more passes leave is deferred (counted in
/// out.deferred) above kHardSliverAngle: the next round and its transitions often mend it, as
/// evolve's deferred defects (the 27-cell foams of seeds 1-12, lloyd = 5, to 100 iterations: 6
/// of 12 got there stopping at 0.1 degree, 9 with the deferral and one to 99). Below it, if
/// the round's transitions were not forced, every small junction is forced first, as evolve's
/// upkeep forces them at a collapsing facet.
std::optional<std::string> sliver_to_stop_on(Cluster& c, JunctionTransitions& junctions,
                                             bool forced, const std::vector<int>& bodies,
                                             TransitionMinimizeResult& out) {
    if (!sliver_left_after_passes(c, out)) return std::nullopt;
    if (!forced && sliver_left(c, kHardSliverAngle) &&
        make_transitions(c, junctions, true, out.rounds, bodies, out.events) > 0) {
        tidy_mesh(c, out);
        if (!sliver_left_after_passes(c, out)) return std::nullopt;
    }
    std::optional<std::string> hard = sliver_left(c, kHardSliverAngle);
    if (!hard) ++out.deferred;
    return hard;
}

} // namespace

TransitionMinimizeResult minimize_with_transitions(Cluster& c,
                                                   const TransitionMinimizeOptions& o) {
    TransitionMinimizeResult out;
    std::vector<int> bodies(c.n_bodies());
    std::iota(bodies.begin(), bodies.end(), 0);
    // no corners fitted off slivers: they can leave slivers below 0.1 degrees, on which the
    // rounds stop (the 64-cell foam stopped after 20 iterations instead of running 300)
    JunctionTransitions junctions(o.min_line_fraction, false);
    junctions.remember(c, bodies);
    MinimizeOptions m = o.minimize;
    // the rounds keep the bodies, so one round's Schur complement preconditions the next's,
    // and the energies of the settle window run on through the transitions
    MinimizeCarry carry;
    int iterations = 0, rejected = 0, hessian_steps = 0;
    double seconds = 0;
    for (;;) {
        m.max_iterations = o.minimize.max_iterations - iterations;
        MinimizeResult r = minimize(c, m, &carry);
        ++out.rounds;
        iterations += r.iterations, rejected += r.rejected, seconds += r.wall_seconds;
        hessian_steps += r.hessian_steps;
        r.iterations = iterations, r.rejected = rejected, r.wall_seconds = seconds;
        r.hessian_steps = hessian_steps;
        out.result = std::move(r);
        if (!stopped_on_a_facet(out.result) || out.rounds >= o.max_rounds ||
            iterations >= o.minimize.max_iterations)
            break;
        junctions.new_look();
        int made = make_transitions(c, junctions, false, out.rounds, bodies, out.events);
        const bool forced = made == 0;
        if (forced) made = make_transitions(c, junctions, true, out.rounds, bodies, out.events);
        const int collapsed = tidy_mesh(c, out);
        if (made == 0 && collapsed == 0) {
            if (!junctions.refused().empty())
                out.result.stop_reason += "; " + junctions.refused();
            break;
        }
        if (const auto hard = sliver_to_stop_on(c, junctions, forced, bodies, out)) {
            out.result.stop_reason += "; after the transitions " + *hard +
                                      " (the mesh upkeep did not remove it)";
            break;
        }
        junctions.remember(c, bodies);
        // the next round starts three growths below where this one ended, not at tau_start:
        // the transitions change the mesh locally, and a ramp from tau_start takes ten steps
        // (the 1000-cell foam's rounds were 4-25 iterations long)
        m.tau_start = std::clamp(out.result.tau / kRoundTauDrop, o.minimize.tau_start,
                                 o.minimize.tau_max);
    }
    return out;
}

} // namespace froth
