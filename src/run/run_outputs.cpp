// What an evolution writes as it goes (run_outputs.h).
#include "run/run_outputs.h"

#include "geometry/geometry.h"

#include <cstdio>

namespace froth {
namespace {

void write_history(const std::string& stem, const std::vector<HistoryRow>& rows) {
    write_history_csv(stem + ".csv", rows);
    write_history_svg(stem + ".svg", rows, "froth: energy over time");
}

std::vector<PointField> output_fields(const Cluster& c) {
    return {{"mean_curvature", vertex_mean_curvature(c)}};
}

} // namespace

RunOutputs::RunOutputs(const Cluster& c, TimeStepper& stepper, const EvolveOptions& o,
                       const TransitionMemory* memory)
    : o_(o) {
    if (!o.output.empty()) {
        series_ = std::make_unique<PvdSeries>(o.output);
        series_->add(c.time(), c, output_fields(c));
    }
    if (!o.checkpoint.empty()) save_state(o.checkpoint, c, stepper, memory);
    write_frame(c);
}

void RunOutputs::start_history(HistoryRow row) {
    add_row(std::move(row));
    write_history(o_.history, history_);
}

void RunOutputs::add_row(HistoryRow row) {
    if (keeps_history()) history_.push_back(std::move(row));
}

void RunOutputs::draw_progress(const EvolveResult& r, const StepReport& s, double fraction) {
    const auto now = std::chrono::steady_clock::now();
    if (!o_.progress || std::chrono::duration<double>(now - last_draw_).count() <= 0.25) return;
    std::fprintf(o_.progress,
                 "\r  step %6d  t = %-10.5g  energy = %-12.8g  volume loss = %8.2e  %5.1f%%  ",
                 r.steps, s.t, s.energy, s.volume_loss, 100.0 * fraction);
    std::fflush(o_.progress);
    last_draw_ = now;
}

void RunOutputs::write_state(const Cluster& c, TimeStepper& stepper,
                             const TransitionMemory* memory) {
    if (series_) series_->add(c.time(), c, output_fields(c));
    if (!o_.checkpoint.empty()) save_state(o_.checkpoint, c, stepper, memory);
    write_frame(c);
    written_last_ = true;
}

void RunOutputs::finish(const Cluster& c) {
    if (keeps_history()) {
        while (history_.size() > 1 && history_.back().t > c.time())
            history_.pop_back();
        write_history(o_.history, history_);
    }
    if (o_.progress) std::fprintf(o_.progress, "\r%90s\r", ""), std::fflush(o_.progress);
}

/// The next picture of the snapshots series (none without `snapshots`).
void RunOutputs::write_frame(const Cluster& c) {
    if (o_.snapshots.empty()) return;
    char number[16];
    std::snprintf(number, sizeof number, "_%06d.png", frames_++);
    write_snapshot(c, o_.snapshots + number, o_.snapshot);
}

} // namespace froth
