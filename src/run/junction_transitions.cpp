// Which junctions are due for a T1 or an inverse T1, and making one (junction_transitions.h).
#include "run/junction_transitions.h"

#include "core/errors.h"
#include "geometry/geometry.h"
#include "mesh/transitions.h"

#include <algorithm>

namespace froth {
namespace {

/// The cells of what a T1 or an inverse T1 makes of a junction: a line (A, B, C; D, E)
/// becomes a film (D, E; A, B, C) and back.
std::vector<int> product_cells(const std::vector<int>& cells, bool film) {
    const auto split = cells.begin() + (film ? 2 : 3);
    std::vector<int> out(split, cells.end());
    out.insert(out.end(), cells.begin(), split);
    return out;
}

} // namespace

std::vector<Junction> JunctionTransitions::junctions(const Cluster& c, bool films,
                                                     const std::vector<int>& original_body) const {
    std::vector<Junction> js = films ? triangular_films(c) : quadruple_lines(c);
    for (Junction& j : js)
        for (int& k : j.cells)
            if (k >= 0) k = original_body[k];
    return js;
}

void JunctionTransitions::remember(const Cluster& c, const std::vector<int>& original_body) {
    for (bool films : {false, true}) {
        auto& memory = films ? film_sizes_ : line_sizes_;
        memory.clear();
        for (const Junction& j : junctions(c, films, original_body)) memory[j.cells] = j.size;
    }
}

std::vector<Junction> JunctionTransitions::due(const Cluster& c, bool films, double limit,
                                               bool force,
                                               const std::vector<int>& original_body) const {
    const auto& memory = films ? film_sizes_ : line_sizes_;
    std::vector<Junction> out;
    for (Junction& j : junctions(c, films, original_body)) {
        if (!(j.size < (films ? 3 : 1) * limit)) continue;
        if (made_.count(j.cells)) continue; // a product of this look's transitions
        const auto was = memory.find(j.cells);
        if (force || (was != memory.end() && j.size < was->second)) out.push_back(std::move(j));
    }
    std::sort(out.begin(), out.end(),
              [](const Junction& x, const Junction& y) { return x.size < y.size; });
    return out;
}

std::optional<Cluster> JunctionTransitions::make(const Cluster& c, bool films, bool force,
                                                 const std::vector<int>& original_body,
                                                 TransitionEvent& event) {
    if (c.quadruple_points().size() < (films ? 3u : 2u)) return std::nullopt;
    const double limit = fraction_ * mean_edge_length(c);
    for (const Junction& j : due(c, films, limit, force, original_body)) {
        TransitionRecord record;
        try {
            // the product is at least twice the limit in size where the mesh lets it be
            Cluster changed = films ? t1_film_to_line(c, j.id, &record, 2 * limit)
                                    : t1_line_to_film(c, j.id, &record, 2 * limit);
            event = TransitionEvent{record.kind, record.where, c.time(), 0, -1, 0, energy(c),
                                    energy(changed)};
            (films ? event.film : event.line) = j.id;
            event.cells = record.cells;
            for (int& k : event.cells)
                if (k >= 0) k = original_body[k];
            made_.insert(product_cells(j.cells, films));
            return changed;
        } catch (const TopologyError& x) {
            std::string why = x.what();
            for (const std::string op : {"t1: ", "t1_inverse: "})
                if (why.rfind(op, 0) == 0) why.erase(0, op.size());
            refused_ = std::string(films ? "no inverse T1" : "no T1") + " could be made: " + why;
        }
    }
    return std::nullopt;
}

} // namespace froth
