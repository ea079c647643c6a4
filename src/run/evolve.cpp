#include "run/evolve.h"

#include "core/errors.h"
#include "core/format.h"
#include "core/interrupt.h"
#include "io/history.h"
#include "io/vtk_writer.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

namespace froth {
namespace {

using Clock = std::chrono::steady_clock;

void check_options(const EvolveOptions& o) {
    if (!(std::isfinite(o.tau) && o.tau > 0))
        throw InvalidInput("evolve: tau must be positive and finite, got " + fmt(o.tau));
    const bool has_T = o.duration >= 0, has_steps = o.steps >= 0;
    if (has_T == has_steps) throw InvalidInput("evolve: give exactly one of T and steps");
    if (has_T && !(std::isfinite(o.duration) && o.duration > 0))
        throw InvalidInput("evolve: T must be positive and finite");
    if (o.every < 0) throw InvalidInput("evolve: every must be >= 0");
    const WatchOptions& w = o.watch;
    if (!(w.min_volume_fraction >= 0 && w.min_volume_fraction < 1) ||
        !(w.min_edge_fraction >= 0 && w.min_edge_fraction < 1) ||
        !(w.min_facet_angle >= 0 && w.min_facet_angle < 60) || w.self_intersection_every < 0)
        throw InvalidInput("evolve: watch thresholds must be fractions in [0, 1), an angle in "
                           "[0, 60) degrees and a step count >= 0");
}

HistoryRow history_row(const Report& r) { return {r.t, r.energy, r.volume_loss, r.volumes}; }

void write_history(const std::string& stem, const std::vector<HistoryRow>& rows) {
    write_history_csv(stem + ".csv", rows);
    write_history_svg(stem + ".svg", rows, "froth: energy over time");
}

std::vector<PointField> output_fields(const Cluster& c) {
    return {{"mean_curvature", vertex_mean_curvature(c)}};
}

void draw_progress(std::FILE* out, const EvolveResult& r, const StepReport& s, double fraction) {
    std::fprintf(out, "\r  step %6d  t = %-10.5g  energy = %-12.8g  volume loss = %8.2e  %5.1f%%  ",
                 r.steps, s.t, s.energy, s.volume_loss, 100.0 * fraction);
    std::fflush(out);
}

} // namespace

EvolveResult evolve(Cluster& c, TimeStepper& stepper, const EvolveOptions& o) {
    check_options(o);
    const EngineLoopScope polling; // Ctrl-C is served between steps, also inside on_step
    const auto start = Clock::now();
    const double t_end = c.time() + o.duration;
    const int total = o.steps >= 0 ? o.steps : static_cast<int>(std::ceil(o.duration / o.tau - 1e-9));
    std::unique_ptr<PvdSeries> series;
    if (!o.output.empty()) {
        series = std::make_unique<PvdSeries>(o.output);
        series->add(c.time(), c, output_fields(c));
    }
    EvolveResult r;
    r.stop_reason = o.steps >= 0 ? "steps done" : "T reached";
    auto last_draw = Clock::now();
    bool written_last = true;
    const TopologyWatch watch(o.watch);
    std::vector<HistoryRow> history;
    if (!o.history.empty()) history.push_back(history_row(make_report(c)));
    // The state at the last passed crossing test: a crossing state is not valid, so a run that
    // finds one returns here.
    std::vector<Vec3> checkpoint = c.positions();
    double checkpoint_t = c.time();
    while (r.steps < total) {
        if (consume_interrupt()) {
            r.stop_reason = "interrupted";
            break;
        }
        // The last step of a T-run ends exactly at t_end, whatever the summed round-off.
        const bool last = o.steps < 0 && r.steps == total - 1;
        const double tau = last ? t_end - c.time() : o.tau;
        if (tau <= 1e-12 * o.tau) break; // T reached up to round-off
        StepReport s;
        try {
            s = stepper.step(c, o.flow, tau);
        } catch (const InvalidInput&) {
            throw;
        } catch (const Error& e) { // geometric breakdown; the step left the cluster as it was
            r.event = TopologyEvent{"step failed",
                                    std::string(e.what()) + " at t = " + fmt(c.time()), c.time()};
        }
        if (r.event) break;
        if (last) c.set_time(t_end), s.t = t_end;
        ++r.steps;
        r.solve_seconds += s.solve_seconds;
        r.factorizations += s.refactorized;
        r.max_energy_increase = std::max(r.max_energy_increase,
                                         (s.energy - s.energy_before) / s.energy_before);
        written_last = false;
        if (!o.history.empty()) history.push_back(history_row(s));
        if (auto e = watch.check(c, r.steps)) {
            if (e->kind == "self-intersection") {
                c.set_positions(checkpoint);
                c.set_time(checkpoint_t);
                e->message += "; the state at t = " + fmt(checkpoint_t) +
                              ", the last one without crossings, is kept";
                e->t = checkpoint_t;
            }
            r.event = std::move(e);
            break;
        }
        if (watch.tests_crossings(r.steps)) checkpoint = c.positions(), checkpoint_t = c.time();
        if (series && o.every > 0 && r.steps % o.every == 0) {
            series->add(c.time(), c, output_fields(c));
            written_last = true;
        }
        if (o.progress && std::chrono::duration<double>(Clock::now() - last_draw).count() > 0.25) {
            draw_progress(o.progress, r, s, static_cast<double>(r.steps) / total);
            last_draw = Clock::now();
        }
        if (o.on_step && !o.on_step(s)) {
            r.stop_reason = "on_step";
            break;
        }
    }
    if (r.event) r.stop_reason = "topology: " + r.event->message;
    if (series && !written_last) series->add(c.time(), c, output_fields(c));
    if (!o.history.empty()) {
        if (r.event && r.event->kind == "self-intersection") // the kept state is earlier
            while (history.size() > 1 && history.back().t > c.time()) history.pop_back();
        write_history(o.history, history);
    }
    if (o.progress) std::fprintf(o.progress, "\r%90s\r", ""), std::fflush(o.progress);
    r.last = make_report(c);
    r.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
    return r;
}

} // namespace froth
