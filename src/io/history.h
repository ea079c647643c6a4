#pragma once
/// The history of an evolution (energy and volumes over time) as CSV and as an SVG line plot
/// a user can open in any browser (the seed's Figs. 8 and 13).

#include <string>
#include <vector>

namespace froth {

struct HistoryRow {
    double t = 0, tau = 0, energy = 0, volume_loss = 0; ///< tau: the step that ended at t (0 at the start)
    std::vector<double> volumes;
};

/// Writes "t,tau,energy,volume_loss,V1,V2,..." rows. \throw IoError, InvalidInput (no rows).
void write_history_csv(const std::string& path, const std::vector<HistoryRow>& rows);

/// Writes the energy over time as an SVG plot with axes, ticks and labels.
/// \throw IoError, InvalidInput (no rows).
void write_history_svg(const std::string& path, const std::vector<HistoryRow>& rows,
                       const std::string& title);

} // namespace froth
