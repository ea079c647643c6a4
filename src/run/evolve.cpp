#include "run/evolve.h"

#include "checks/self_intersection.h"
#include "core/errors.h"
#include "core/format.h"
#include "core/interrupt.h"
#include "mesh/transitions.h"
#include "run/junction_transitions.h"
#include "run/run_outputs.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <optional>

namespace froth {
namespace {

/// A transition's error message without the operation's name in front ("pop_body: ").
std::string without_operation(std::string text) {
    for (const std::string op : {"pop_body: ", "absorb_body: "})
        if (text.rfind(op, 0) == 0) text.erase(0, op.size());
    return text;
}

/// sum sigma |face| over the films of body b (isotropic tensions).
double film_tension(const Cluster& c, int b) {
    const std::vector<double> areas = surface_areas(c);
    double sum = 0;
    for (const BodyFace& f : c.bodies()[b].faces)
        sum += c.surface(f.surface).sigma * areas[f.surface];
    return sum;
}

using Clock = std::chrono::steady_clock;

void check_options(const EvolveOptions& o) {
    if (!(std::isfinite(o.tau) && o.tau > 0))
        throw InvalidInput("evolve: tau must be positive and finite, got " + fmt(o.tau));
    const bool has_T = o.duration >= 0, has_steps = o.steps >= 0;
    if (has_T == has_steps) throw InvalidInput("evolve: give exactly one of T and steps");
    if (has_T && !(std::isfinite(o.duration) && o.duration > 0))
        throw InvalidInput("evolve: T must be positive and finite");
    if (o.every < 0) throw InvalidInput("evolve: every must be >= 0");
    if (has_T && o.duration / o.tau > 1e9)
        throw InvalidInput("evolve: T / tau = " + fmt(o.duration / o.tau) + " steps is too many");
    if (o.adaptive && !(std::isfinite(o.tol) && o.tol > 0 && o.tol < 1))
        throw InvalidInput("evolve: tol must be in (0, 1), got " + fmt(o.tol));
    if (o.adaptive && !(o.tau_max >= 0 && std::isfinite(o.tau_max)))
        throw InvalidInput("evolve: tau_max must be positive and finite (0: none), got " +
                           fmt(o.tau_max));
    if (!o.adaptive && o.tau_start != 0 && !(o.tau_start > 0 && o.tau_start <= o.tau))
        throw InvalidInput("evolve: tau_start must be in (0, tau], got " + fmt(o.tau_start));
    if (!(o.tau_growth > 1 && o.tau_growth <= 10))
        throw InvalidInput("evolve: tau_growth must be in (1, 10], got " + fmt(o.tau_growth));
    const WatchOptions& w = o.watch;
    if (!(w.min_volume_fraction >= 0 && w.min_volume_fraction < 1) ||
        !(w.min_edge_fraction >= 0 && w.min_edge_fraction < 1) ||
        !(w.min_facet_angle >= 0 && w.min_facet_angle < 60) || w.self_intersection_every < 0 ||
        !(w.min_line_fraction >= 0 && w.min_line_fraction < 1))
        throw InvalidInput("evolve: watch thresholds must be fractions in [0, 1), an angle in "
                           "[0, 60) degrees and a step count >= 0");
}

/// The watch of a run: with transitions, lines between quadruple points are left to the T1s.
WatchOptions watch_options(const EvolveOptions& o) {
    WatchOptions w = o.watch;
    w.lines_to_transitions = o.transitions;
    return w;
}

/// The watch for a mesh defect the upkeep could not mend (Run::defer): a tenth of the
/// edge and angle limits; bodies are the first watch's.
WatchOptions hard_watch_options(const EvolveOptions& o) {
    WatchOptions w = watch_options(o);
    w.min_volume_fraction = 0;
    w.min_edge_fraction *= 0.1;
    w.min_facet_angle *= 0.1;
    return w;
}

/// One evolution: the loop of evolve() split into its parts.
class Run {
  public:
    Run(Cluster& c, TimeStepper& stepper, const EvolveOptions& o, TransitionMemory* memory)
        : c_(c), stepper_(stepper), o_(o), watch_(watch_options(o)),
          hard_watch_(hard_watch_options(o)), t_start_(c.time()), t_end_(c.time() + o.duration),
          uncrossed_(c.positions()), uncrossed_t_(c.time()), outputs_(c, stepper, o, memory),
          memory_(o.transitions ? memory : nullptr) {
        for (int b = 0; b < c.n_bodies(); ++b) original_body_.push_back(b);
        r_.stop_reason = o.steps >= 0 ? "steps done" : "T reached";
        if (outputs_.keeps_history()) outputs_.start_history(history_row(make_report(c), 0));
        if (!o.transitions) return;
        if (memory_ && memory_->junctions &&
            memory_->junctions->fits(c.n_bodies(), o.watch.min_line_fraction)) {
            junctions_ = *memory_->junctions;
            longest_edge_ = memory_->longest_edge;
            made_before_ = memory_->transitions_made;
            tau_scale_ = memory_->tau_scale;
        } else {
            junctions_.remember(c_, original_body_);
        }
    }

    /// Takes one step and everything that follows it; false ends the run.
    bool advance() {
        if (done()) return false;
        if (consume_interrupt()) {
            r_.stop_reason = "interrupted";
            return false;
        }
        bool last = false;
        std::optional<Before> before;
        if (retries_allowed()) before.emplace(keep_before());
        std::optional<StepReport> s =
            o_.adaptive ? try_adaptive_step(last) : try_step(planned_tau(), last);
        if (!s) return before && retry(*before);
        if (last) c_.set_time(t_end_), s->t = t_end_;
        record(*s);
        if (watch_for_topology(before.has_value())) return before && retry(*before);
        tau_scale_ = std::min(1.0, 2 * tau_scale_);
        memory_forgotten_ = false, forgotten_from_ = 1;
        write_output(*s);
        if (o_.on_step && !o_.on_step(*s)) {
            r_.stop_reason = "on_step";
            return false;
        }
        return true;
    }

    EvolveResult finish(Clock::time_point start) {
        if (r_.event) r_.stop_reason = "topology: " + r_.event->message;
        if (!outputs_.written_last()) write_state_outputs();
        outputs_.finish(c_);
        r_.last = make_report(c_);
        if (memory_) *memory_ = memory_now();
        r_.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
        return std::move(r_);
    }

  private:
    /// The memory the next call would start from, were the run to end now.
    TransitionMemory memory_now() const {
        JunctionTransitions junctions = junctions_;
        junctions.carry_over(original_body_);
        return {std::move(junctions), longest_edge_, transitions_made(), tau_scale_};
    }

    bool done() const {
        if (o_.steps >= 0) return r_.steps >= o_.steps;
        return c_.time() >= t_end_ - 1e-12 * o_.tau; // T reached up to round-off
    }

    /// tau, or during a start ramp tau_start * growth^k (k = steps taken), whichever is less;
    /// times tau_scale_ after a retry.
    double planned_tau() const {
        if (!(o_.tau_start > 0)) return tau_scale_ * o_.tau;
        return tau_scale_ * std::min(o_.tau, o_.tau_start * std::pow(o_.tau_growth, r_.steps));
    }

    /// What a retry restores: the run as it was before a step.
    struct Before {
        Cluster c;
        JunctionTransitions junctions;
        std::vector<int> original_body;
        EvolveResult r;
        std::size_t history_rows;
        std::vector<Vec3> uncrossed;
        double uncrossed_t;
    };

    /// In a network (facet_upkeep_allowed, with fixed steps), a step after which the run would
    /// stop on a collapsing edge or facet or on crossing facets, or that fails, is retried from
    /// the state before it at a quarter of its tau: junctions that a step of tau moves past
    /// each other (a line of a few thousandths passing a film's corner) are often seen in time
    /// at a shorter step, where their transitions can still be made. A pinch-off scene stops
    /// as before.
    bool retries_allowed() const {
        return o_.transitions && !o_.adaptive && facet_upkeep_allowed();
    }

    Before keep_before() const {
        return {c_, junctions_, original_body_, r_, outputs_.rows(), uncrossed_, uncrossed_t_};
    }

    /// Returns the run to `b` with the next tau a quarter of the last (true), unless tau is
    /// down to kMinTauScale of the option's or the stop is not one a shorter step may avoid
    /// (false: the run stops, the message saying at which tau; after crossing facets the
    /// state before the step is kept).
    bool retry(Before& b) {
        const std::string kind = r_.event ? r_.event->kind : "";
        const bool retried_kind = kind == "collapsing edge" || kind == "collapsing facet" ||
                                  kind == "step failed" || kind == "self-intersection";
        if (retried_kind && tau_scale_ / 4 >= kMinTauScale) {
            const int retried = r_.rejected_steps + 1;
            restore(b);
            r_.rejected_steps = retried;
            tau_scale_ /= 4;
            return true;
        }
        // Last, the same retries with the junctions' memory forgotten, as a run loaded from a
        // state file without one has it: its rules (products not due until they shrink, no
        // undoing a contact for 10 looks) keep transitions from cycling, but they can also
        // hold back the one transition a tangle needs. The 200-grain network stopped at
        // t = 1.1716 on a one-edge line of 2.4e-5 between two quadruple points whose T1 was
        // not made; loaded from the state before, with a fresh memory, it made that T1 in its
        // first step and ran on to T = 2.
        if (retried_kind && !memory_forgotten_) { // retries come with transitions only
            const int retried = r_.rejected_steps + 1;
            const double shortest = tau_scale_;
            restore(b);
            r_.rejected_steps = retried;
            junctions_ = JunctionTransitions(o_.watch.min_line_fraction);
            junctions_.remember(c_, original_body_);
            memory_forgotten_ = true, forgotten_from_ = shortest;
            tau_scale_ = 1;
            return true;
        }
        if (r_.event && tau_scale_ < 1)
            r_.event->message +=
                "; the step was retried down to tau = " +
                fmt(std::min(tau_scale_, forgotten_from_) * o_.tau) +
                (memory_forgotten_ ? ", and again with the junctions' memory forgotten" : "");
        if (kind == "self-intersection") {
            TopologyEvent e = std::move(*r_.event);
            const int retried = r_.rejected_steps;
            restore(b);
            if (self_intersection_available() && find_self_intersections(c_, 1).empty()) {
                e.message +=
                    "; the state before the step, at t = " + fmt(c_.time()) + ", is kept";
                e.t = c_.time();
            } else {
                keep_uncrossed(e); // the crossing came before the step
            }
            r_.event = std::move(e), r_.rejected_steps = retried;
        }
        return false;
    }

    /// After crossing facets: the cluster goes back to the last state that passed the
    /// crossing test, and e says so.
    void keep_uncrossed(TopologyEvent& e) {
        c_.set_positions(uncrossed_);
        c_.set_time(uncrossed_t_);
        e.message += "; the state at t = " + fmt(uncrossed_t_) +
                     ", the last one without crossings, is kept";
        e.t = uncrossed_t_;
    }

    /// The run as it was before a step (Before).
    void restore(Before& b) {
        c_ = std::move(b.c);
        junctions_ = std::move(b.junctions);
        original_body_ = std::move(b.original_body);
        r_ = std::move(b.r);
        outputs_.rewind(b.history_rows);
        uncrossed_ = std::move(b.uncrossed), uncrossed_t_ = b.uncrossed_t;
        stepper_.reset();
    }

    double progress() const {
        if (o_.steps >= 0) return o_.steps ? static_cast<double>(r_.steps) / o_.steps : 1.0;
        return (c_.time() - t_start_) / (t_end_ - t_start_);
    }

    /// tau, shortened if it would pass T: the last step of a T-run ends exactly at t_end,
    /// whatever the summed round-off.
    double clipped(double tau, bool& last) const {
        last = o_.steps < 0 && c_.time() + tau * (1 + 1e-9) >= t_end_;
        return last ? t_end_ - c_.time() : tau;
    }

    /// A step that fails geometrically ends the run as a topology event; the step has left
    /// the cluster as it was. Bad input still throws.
    std::optional<StepReport> try_step(double planned, bool& last) {
        const double tau = clipped(planned, last);
        try {
            stepper_.set_exact_volumes(o_.exact_volumes);
            stepper_.set_sd_solver(o_.sd_solver);
            return stepper_.step(c_, o_.flow, tau, o_.project_onto_walls);
        } catch (const InvalidInput&) {
            throw;
        } catch (const Error& e) {
            stop_on(e);
            return std::nullopt;
        }
    }

    void stop_on(const Error& e) {
        if (dynamic_cast<const ConvergenceError*>(&e)) { // not a topology event: say what it was
            r_.stop_reason = std::string("no convergence: ") + e.what() + " at t = " +
                             fmt(c_.time());
            return;
        }
        r_.event = TopologyEvent{"step failed", std::string(e.what()) + " at t = " + fmt(c_.time()),
                                 c_.time()};
    }

    /// tau = "auto": the step at tau_next_, retried shorter while it misses the tolerance
    /// (by the estimate's square root: the first-order local error is O(tau^2)) or fails
    /// (a quarter: a collapsing facet or a vanishing body ahead), down to 1e-6 of the first
    /// step; the next tau from the accepted step's estimate, 0.2x to 2x.
    std::optional<StepReport> try_adaptive_step(bool& last) {
        const double tau_min = 1e-6 * o_.tau;
        stepper_.set_exact_volumes(o_.exact_volumes);
        for (;;) {
            const double tau = clipped(tau_next_, last);
            try {
                StepReport s = stepper_.step(c_, o_.flow, tau, o_.project_onto_walls, o_.tol);
                const double grow =
                    s.error_estimate > 0 ? 0.9 * std::sqrt(o_.tol / s.error_estimate) : 2.0;
                if (!last) tau_next_ = tau * std::clamp(grow, 0.2, 2.0);
                if (o_.tau_max > 0) tau_next_ = std::min(tau_next_, o_.tau_max);
                return s;
            } catch (const InvalidInput&) {
                throw;
            } catch (const StepRejected& e) {
                ++r_.rejected_steps;
                tau_next_ = tau * std::clamp(0.9 * std::sqrt(o_.tol / e.estimate), 0.1, 0.5);
            } catch (const Error& e) {
                ++r_.rejected_steps;
                tau_next_ = tau / 4;
                if (tau_next_ < tau_min) {
                    stop_on(e);
                    return std::nullopt;
                }
            }
            if (tau_next_ < tau_min) {
                r_.stop_reason = "no convergence: the step needed to meet tol = " + fmt(o_.tol) +
                                 " fell below " + fmt(tau_min) + " at t = " + fmt(c_.time());
                return std::nullopt;
            }
        }
    }

    void record(const StepReport& s) {
        ++r_.steps;
        r_.solve_seconds += s.solve_seconds;
        r_.factorizations += s.refactorized;
        r_.max_energy_increase =
            std::max(r_.max_energy_increase, (s.energy - s.energy_before) / s.energy_before);
        outputs_.state_changed();
        outputs_.add_row(history_row(s, s.tau));
    }

    /// A history row with the volumes in the columns of the bodies at the start of the run
    /// (0 for the popped ones).
    HistoryRow history_row(const Report& r, double tau) const {
        std::vector<double> volumes(n_start_bodies_, 0.0);
        for (std::size_t b = 0; b < r.volumes.size(); ++b) volumes[original_body_[b]] = r.volumes[b];
        return {r.t, tau, r.energy, r.volume_loss, std::move(volumes)};
    }

    /// True if the watch saw a topology change coming that it could not get past; a crossing
    /// state is not a valid one, so then the cluster returns to the last state that passed the
    /// crossing test (unless the step is `undoable`: retry() decides what is kept). With
    /// EvolveOptions::transitions the due T1s, pops and mesh upkeep are made first, each
    /// followed by a new look.
    bool watch_for_topology(bool undoable) {
        std::optional<TopologyEvent> e;
        junctions_.new_look();
        caps_relaxed_ = false;
        unresolved_refused_.clear();
        UpkeepTurns turns;
        // A transition may leave the next one due; a bound keeps a cycle from running forever.
        for (int made = 0;; ++made) {
            if (o_.transitions && made < kMaxTransitionsPerStep &&
                (split_edges() || transition_junction(true) || transition_junction(false) ||
                 pinch_film(true)))
                continue;
            e = watch_.check(c_, r_.steps);
            if (!e || !o_.transitions) break;
            if (made >= kMaxTransitionsPerStep) {
                // transitions that cycle at a defect often circle a cell the mesh no longer
                // resolves: that cell may still go, once
                if (made == kMaxTransitionsPerStep && absorb_unresolved_grain(*e)) continue;
                break;
            }
            if (e->kind == "vanishing body" && pop(*e)) continue;
            if (!mend(*e, turns) && !absorb_unresolved_grain(*e)) break;
        }
        if (e && defer(*e)) e.reset();
        if (e && !junctions_.refused().empty()) e->message += "; " + junctions_.refused();
        if (e && !unresolved_refused_.empty()) e->message += "; " + unresolved_refused_;
        if (!e && o_.transitions) junctions_.remember(c_, original_body_);
        if (!e) {
            if (watch_.tests_crossings(r_.steps)) uncrossed_ = c_.positions(), uncrossed_t_ = c_.time();
            return false;
        }
        if (e->kind == "self-intersection" && !undoable) keep_uncrossed(*e); // else retry()
        r_.event = std::move(e);
        return true;
    }

    using Upkeep = bool (Run::*)();
    /// Where the upkeeps stand for the defect the watch last named.
    struct UpkeepTurns {
        std::string defect; ///< its place: the watch's message up to " is collapsing"
        std::size_t next = 0;
        int passes = 0;
        bool acted_in_pass = false;
    };

    /// One upkeep for a collapsing edge or facet e: the next in its list that changes the
    /// mesh; false if none does. The upkeeps act on the whole cluster, so in a network one of
    /// them may always find something to do elsewhere: while the watch names the same defect,
    /// they take their turns down the list, which is gone through at most
    /// kPassesAtOneDefect times (again only if one of them acted).
    bool mend(const TopologyEvent& e, UpkeepTurns& t) {
        // the facet's upkeeps come last for an edge too: the watch names a collapsing facet
        // only when no edge is collapsing
        static constexpr std::array<Upkeep, 10> for_edge = {
            &Run::collapse_edges,        &Run::pinch_films,           &Run::flip_edges,
            &Run::remesh_thin,           &Run::relax_short_edges,     &Run::force_film_transition,
            &Run::force_line_transition, &Run::remove_valence_three,  &Run::relax_caps_once,
            &Run::collapse_needles};
        // a film vertex of three neighbours beside a line (joined to both its ends) folds
        // the film in the line's T1: where the forced T1s fail, such vertices go and the T1s
        // are forced again
        static constexpr std::array<Upkeep, 8> for_facet = {
            &Run::zip_slits,            &Run::flip_edges,
            &Run::relax_caps_once,      &Run::collapse_needles,
            &Run::remesh_thin,          &Run::force_line_transition, &Run::remove_valence_three,
            &Run::force_line_transition};
        const bool edge = e.kind == "collapsing edge";
        if (!edge && e.kind != "collapsing facet") return false;
        const Upkeep* list = edge ? for_edge.data() : for_facet.data();
        const std::size_t size = edge ? for_edge.size() : for_facet.size();
        // the defect by its place (the message goes on with sizes that the upkeep changes)
        const std::string defect = e.message.substr(0, e.message.find(" is collapsing"));
        if (defect != t.defect) t = UpkeepTurns{defect};
        for (;;) {
            if (t.next == size) {
                if (!t.acted_in_pass || ++t.passes >= kPassesAtOneDefect) return false;
                t.next = 0, t.acted_in_pass = false;
            }
            if ((this->*list[t.next++])()) return t.acted_in_pass = true;
        }
    }

    bool force_film_transition() { return transition_junction(true, true); }
    bool force_line_transition() { return transition_junction(false, true); }
    /// The caps' moves once a look at the step (watch_for_topology): moved again, a cap next
    /// to a line can stay a cap, and the needles' collapse after them must get its turn.
    bool relax_caps_once() { return !caps_relaxed_ && (caps_relaxed_ = relax_caps()); }

    /// A collapsing edge or facet that no upkeep mended, beside a cell the mesh no longer
    /// resolves (unresolved_cell_near: smaller than a ball whose radius is the mean edge, and
    /// than a tenth of the mean cell, so that the cells of a coarse mesh are not all such),
    /// whose junctions tangle (a grain of 11 faces and 3 mean edges cubed, lines of
    /// 0.0002-0.02 against a mean edge of 0.19, stopped the 200-grain network at t = 1.540
    /// whatever surgery was tried on them): that cell pops or joins a neighbour (pop(),
    /// recorded as such) before the defect is deferred or ends the run. False if there is no
    /// such cell, or neither can be made.
    bool absorb_unresolved_grain(TopologyEvent& e) {
        if (!o_.transitions || !facet_upkeep_allowed() || e.surface < 0 ||
            (e.kind != "collapsing edge" && e.kind != "collapsing facet"))
            return false;
        const int cell = unresolved_cell_near(c_, e.surface, e.facet);
        if (cell < 0) return false;
        TopologyEvent vanishing{"vanishing body", "body " + std::to_string(cell + 1) +
                                    ", below the mesh's resolution beside the defect"};
        vanishing.body = cell;
        if (pop(vanishing)) {
            r_.events.back().where += " (below the mesh's resolution, beside a defect the "
                                      "upkeep could not mend)";
            return true;
        }
        unresolved_refused_ = vanishing.message; // the stop's message will say why
        return false;
    }

    /// True if the run goes on past event e: a collapsing edge or facet in a foam
    /// (facet_upkeep_allowed) that no upkeep mended is left to the next steps, where the flow
    /// and the upkeep often open it, or the junctions around it come due for a transition.
    /// Above a tenth of the watch's limits it is left as it is. Below, only while the mesh
    /// stays embedded (embedded_past): a state whose facets cross turns e into a
    /// "self-intersection", which keeps the last state without crossings.
    bool defer(TopologyEvent& e) {
        if (!o_.transitions || !facet_upkeep_allowed() ||
            (e.kind != "collapsing edge" && e.kind != "collapsing facet"))
            return false;
        if (std::optional<TopologyEvent> hard = hard_watch_.check(c_, r_.steps)) {
            if (!embedded_past(*hard)) {
                e = std::move(*hard);
                return false;
            }
        }
        ++r_.deferred;
        return true;
    }

    /// True if no two facets of the cluster cross, tested now; false where the test is not
    /// available (without CGAL: e stands, as the hard limit it was until 2026-12-07), or
    /// with e made the crossing's event, its message after e's. The 27-grain network of seed 3
    /// stopped at t = 0.748 on a needle below the hard limit; from the state before that step
    /// it went on to t = 1.98 with this test in the limit's place.
    bool embedded_past(TopologyEvent& e) const {
        if (!self_intersection_available()) return false;
        const std::vector<FacetCrossing> crossings = find_self_intersections(c_, 1);
        if (crossings.empty()) return true;
        e.kind = "self-intersection";
        e.message += "; below a tenth of the limits, and " + crossing_text(crossings.front());
        return false;
    }

    /// The first due junction whose transition can be made (run/junction_transitions.h):
    /// triangular films with `films`, else lines; false if none can.
    bool transition_junction(bool films, bool force = false) {
        TransitionEvent event;
        return take_transition(junctions_.make(c_, films, force, original_body_, event), event);
    }

    /// A film whose waist, an edge between two of its lines, is shorter than a T1's line
    /// (`due`), or the collapse limit (forced: the upkeep for a collapsing edge), pinches
    /// there (JunctionTransitions::pinch); false if none can.
    bool pinch_film(bool due) {
        TransitionEvent event;
        const double below = due ? junctions_.t1_length(c_) : collapse_limit();
        return take_transition(junctions_.pinch(c_, below, !due, original_body_, event), event);
    }
    bool pinch_films() { return pinch_film(false); }

    /// A transition's cluster (none: false) replaces the run's, with its event recorded.
    bool take_transition(std::optional<Cluster> changed, TransitionEvent& event) {
        if (!changed) return false;
        event.step = r_.steps;
        r_.events.push_back(std::move(event));
        replace_cluster(std::move(*changed));
        return true;
    }

    /// The upkeep's edge limit: 2.5 min_edge_fraction of the mean edge.
    double collapse_limit() const {
        return 2.5 * o_.watch.min_edge_fraction * mean_edge_length(c_);
    }

    /// Mesh upkeep for a collapsing edge: the edges shorter than collapse_limit() collapse
    /// (mesh/transitions.h); false if none could.
    bool collapse_edges() {
        EdgeCollapseResult collapsed = collapse_short_edges(c_, collapse_limit());
        return take_upkeep(collapsed.cluster, collapsed.collapsed, r_.collapsed_edges);
    }

    /// Mesh upkeep for a film's corner closed to a slit (a sliver along two lines of one
    /// film): the quadruple point moves up the slit (zip_slit), for slits narrower than
    /// collapse_edges' limit (which zips them too, where no edge collapses).
    bool zip_slits() {
        EdgeCollapseResult zipped = zip_slit(c_, collapse_limit());
        return take_upkeep(zipped.cluster, zipped.collapsed, r_.collapsed_edges);
    }

    /// Mesh upkeep for the films a transition makes grow: once the run (or a call before it,
    /// TransitionMemory) has made one, edges longer than the longest edge at the start of the
    /// (first) run are split, and the films then flipped to Delaunay (the splits of a stretched
    /// facet leave fans of slivers). A run without transitions keeps its mesh as it is.
    bool split_edges() {
        if (!transitions_made()) return false;
        EdgeSplitResult split = split_long_edges(c_, longest_edge_);
        if (!split.cluster) return false;
        r_.split_edges += split.split;
        replace_cluster(std::move(*split.cluster), false);
        flip_edges();
        return true;
    }

    /// True if the collapsing-facet upkeep may change the mesh: after a transition of this run,
    /// or in a cluster with quadruple points (a foam or grain network, which a driver may step
    /// one evolve call at a time). A pinch-off scene keeps its mesh, so that its watch stops.
    bool facet_upkeep_allowed() const {
        return transitions_made() || !c_.quadruple_points().empty();
    }

    /// True once this run, or a call before it on the same memory, made a transition.
    bool transitions_made() const { return made_before_ || !r_.events.empty(); }

    /// Mesh upkeep for a collapsing facet (facet_upkeep_allowed): Delaunay flips (Evolver's
    /// `u`) inside the films, which turn a flat sliver into two good facets.
    bool flip_edges() {
        if (!facet_upkeep_allowed()) return false;
        EquiangulateResult flipped = equiangulate(c_);
        if (!flipped.cluster) return false;
        r_.flipped_edges += flipped.flips;
        replace_cluster(std::move(*flipped.cluster), false);
        return true;
    }

    /// Mesh upkeep for a collapsing edge that neither collapses nor transitions cleared: film
    /// vertices of three neighbours go (one beside a line, joined to both its ends, keeps the
    /// line from collapsing in a T1).
    bool remove_valence_three() {
        EdgeCollapseCriteria lone;
        lone.valence_three = true;
        EdgeCollapseResult collapsed = froth::collapse_edges(c_, lone);
        return take_upkeep(collapsed.cluster, collapsed.collapsed, r_.collapsed_edges);
    }

    /// Mesh upkeep for a collapsing facet that the flips left (facet_upkeep_allowed): flat caps
    /// (corners below ten times the watch's angle) open by moving their flat corner's film
    /// vertex in its tangent plane.
    bool relax_caps() {
        if (!facet_upkeep_allowed()) return false;
        VertexRelaxResult relaxed = relax_flat_corners(c_, 10 * o_.watch.min_facet_angle);
        return take_upkeep(relaxed.cluster, relaxed.moved, r_.relaxed_vertices);
    }

    /// Mesh upkeep for a collapsing edge or facet that neither collapses nor flips away (with
    /// facet_upkeep_allowed): films narrower than a tenth of the mean edge lose their inner
    /// vertices (remesh_thin_films).
    bool remesh_thin() {
        if (!facet_upkeep_allowed()) return false;
        EdgeCollapseResult r = remesh_thin_films(c_, 0.1 * mean_edge_length(c_));
        return take_upkeep(r.cluster, r.collapsed, r_.collapsed_edges);
    }

    /// Mesh upkeep for a collapsing edge that neither collapses nor flips away (with
    /// facet_upkeep_allowed): its film vertices move to their neighbours' mean in their
    /// tangent planes.
    bool relax_short_edges() {
        if (!facet_upkeep_allowed()) return false;
        VertexRelaxResult relaxed = relax_short_edge_ends(c_, collapse_limit());
        return take_upkeep(relaxed.cluster, relaxed.moved, r_.relaxed_vertices);
    }

    /// Mesh upkeep for a collapsing facet that the flips and the caps' moves left
    /// (facet_upkeep_allowed): the shortest side of every facet with a corner below ten times the watch's
    /// angle collapses (a needle's short side, or a cap's by a triple line).
    bool collapse_needles() {
        if (!facet_upkeep_allowed()) return false;
        EdgeCollapseCriteria needles;
        needles.needle_angle = 10 * o_.watch.min_facet_angle;
        EdgeCollapseResult collapsed = froth::collapse_edges(c_, needles);
        return take_upkeep(collapsed.cluster, collapsed.collapsed, r_.collapsed_edges);
    }

    /// An upkeep's result: the cluster it made (none: nothing done, false) replaces the run's,
    /// and its count goes to `counter`.
    bool take_upkeep(std::optional<Cluster>& changed, int count, int& counter) {
        if (!changed) return false;
        counter += count;
        replace_cluster(std::move(*changed), false);
        return true;
    }

    /// The cluster after a transition or upkeep: the stepper starts afresh, the state is the
    /// last one without crossings, and for a transition (history_row_after) the history gets a
    /// row for it (tau = 0), so that the energy's jump shows.
    void replace_cluster(Cluster changed, bool history_row_after = true) {
        c_ = std::move(changed);
        stepper_.reset();
        uncrossed_ = c_.positions(), uncrossed_t_ = c_.time();
        if (outputs_.keeps_history() && history_row_after)
            outputs_.add_row(history_row(make_report(c_), 0));
    }

    /// Pops the vanishing body of event e; one with more than four neighbours, or whose pop
    /// the mesh refuses or would raise the energy, joins its largest neighbour instead
    /// (absorb_body). False (and the reasons added to e's message) if neither can be made.
    /// The stepper starts afresh on the new mesh.
    bool pop(TopologyEvent& e) {
        std::string why_not[2]; // why it cannot pop, why it cannot join a neighbour
        for (const bool absorb : {false, true}) {
            TransitionRecord record;
            std::optional<Cluster> changed;
            try {
                if (absorb) {
                    changed.emplace(absorb_body(c_, e.body, -1, &record));
                } else if (const std::size_t n = neighbour_cells(c_, e.body).size(); n > 4) {
                    why_not[0] = std::to_string(n) + " neighbouring cells";
                } else {
                    changed.emplace(pop_body(c_, e.body, &record));
                }
            } catch (const TopologyError& x) {
                why_not[absorb] = without_operation(x.what());
            }
            if (!changed) continue;
            // the surgery around a cell at the mesh's scale moves its neighbours' films a
            // little: a rise within a hundredth of the cell's own films' tension is round-off,
            // not a cell too large to pop
            const double before = energy(c_), after = energy(*changed);
            if (after > before + 0.01 * film_tension(c_, e.body)) {
                why_not[absorb] =
                    "it would raise the energy from " + fmt(before) + " to " + fmt(after);
                continue;
            }
            const int original = original_body_[e.body];
            TransitionEvent event{record.kind, record.where, c_.time(), r_.steps, original,
                                  record.neighbours, before, after};
            if (absorb) event.cells = {original, original_body_[record.cells[1]]};
            r_.events.push_back(std::move(event));
            original_body_.erase(original_body_.begin() + e.body);
            replace_cluster(std::move(*changed));
            return true;
        }
        e.message +=
            "; it cannot pop (" + why_not[0] + ") nor join a neighbour (" + why_not[1] + ")";
        return false;
    }

    void write_output(const StepReport& s) {
        if (outputs_.state_due(r_.steps)) write_state_outputs();
        outputs_.draw_progress(r_, s, progress());
    }

    /// The state outputs, the checkpoint with the memory the next call would start from.
    void write_state_outputs() {
        std::optional<TransitionMemory> memory;
        if (o_.transitions && !o_.checkpoint.empty()) memory = memory_now();
        outputs_.write_state(c_, stepper_, memory ? &*memory : nullptr);
    }

    Cluster& c_;
    TimeStepper& stepper_;
    const EvolveOptions& o_;
    const TopologyWatch watch_, hard_watch_;
    const double t_start_, t_end_;
    // adaptive: the next step to try (the first: tau_start, at most tau_max)
    double tau_next_ = o_.tau_max > 0 ? std::min(o_.tau, o_.tau_max) : o_.tau;
    EvolveResult r_;
    std::vector<Vec3> uncrossed_; // the last state that passed the crossing test
    double uncrossed_t_;
    RunOutputs outputs_;
    const int n_start_bodies_ = c_.n_bodies();
    std::vector<int> original_body_; // the bodies' ids at the start of the run
    JunctionTransitions junctions_{o_.watch.min_line_fraction};
    TransitionMemory* memory_; // the calls' memory, with transitions
    double longest_edge_ = edge_lengths(c_).longest; // the mesh size the upkeep keeps
    bool made_before_ = false; // a call before this one made a transition
    static constexpr int kMaxTransitionsPerStep = 64;
    /// The shortest retried step, relative to the option's tau (three retries).
    static constexpr double kMinTauScale = 1.0 / 64;
    double tau_scale_ = 1; // the planned step over the option's tau (below 1 after a retry)
    // the retries of this step went on with a fresh junction memory (retry), after going down
    // to forgotten_from_ with the run's own
    bool memory_forgotten_ = false;
    double forgotten_from_ = 1;
    /// Times the upkeeps are gone through for one defect that none of them mends.
    static constexpr int kPassesAtOneDefect = 2;
    bool caps_relaxed_ = false; // relax_caps_once made its move in this step's look
    std::string unresolved_refused_; // why a cell below the mesh's resolution could not go
};

} // namespace

EvolveResult evolve(Cluster& c, TimeStepper& stepper, const EvolveOptions& o,
                    TransitionMemory* memory) {
    check_options(o);
    stepper.set_fixed_point(o.fixed_point); // throws InvalidInput for bad values
    stepper.set_order(o.adaptive ? 2 : o.order); // the estimate is that of the order-2 step
    stepper.set_line_relaxation(o.line_relaxation); // throws InvalidInput for bad values
    const EngineLoopScope polling; // Ctrl-C is served between steps, also inside on_step
    const auto start = Clock::now();
    Run run(c, stepper, o, memory);
    while (run.advance()) {
    }
    return run.finish(start);
}

} // namespace froth
