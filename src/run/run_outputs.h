#pragma once
/// What an evolution writes as it goes (EvolveOptions): the ParaView series, the history of
/// every step, the checkpoints, the snapshot pictures and the progress line. Part of evolve()
/// (run/evolve.cpp), kept apart from its loop; not used elsewhere.

#include "io/history.h"
#include "io/vtk_writer.h"
#include "run/evolve.h"

#include <chrono>
#include <cstddef>
#include <memory>
#include <vector>

namespace froth {

class RunOutputs {
  public:
    /// Writes the start: the series' first frame, the checkpoint (with `memory`, if given) and
    /// the first picture, each if asked for, so that a bad path fails before any step.
    RunOutputs(const Cluster& c, TimeStepper& stepper, const EvolveOptions& o,
               const TransitionMemory* memory);

    /// True with EvolveOptions::history: only then are rows kept.
    bool keeps_history() const { return !o_.history.empty(); }
    /// The history's first row, written at once (a bad path fails before any step).
    void start_history(HistoryRow row);
    void add_row(HistoryRow row);
    std::size_t rows() const { return history_.size(); }
    /// Drops the rows after the first `rows` (a retried step's).
    void rewind(std::size_t rows) { history_.resize(rows); }

    /// True if the state outputs are due after step `steps` (every `every` steps).
    bool state_due(int steps) const { return o_.every > 0 && steps % o_.every == 0; }
    /// The series' frame, the checkpoint (with `memory`, if given) and the picture of the
    /// state c, each if asked for.
    void write_state(const Cluster& c, TimeStepper& stepper, const TransitionMemory* memory);
    /// The cluster took a step: the state outputs no longer hold its state.
    void state_changed() { written_last_ = false; }
    bool written_last() const { return written_last_; }
    /// The progress line of step s, at most four times a second (`fraction` of the run done).
    void draw_progress(const EvolveResult& r, const StepReport& s, double fraction);

    /// The end, after the last state's outputs: the history (without rows after c's time: a
    /// run that went back to a state before crossings), and the progress line cleared.
    void finish(const Cluster& c);

  private:
    void write_frame(const Cluster& c);

    const EvolveOptions& o_;
    std::unique_ptr<PvdSeries> series_;
    std::vector<HistoryRow> history_;
    bool written_last_ = true; // the state outputs hold the current state
    int frames_ = 0;
    std::chrono::steady_clock::time_point last_draw_ = std::chrono::steady_clock::now();
};

} // namespace froth
