// Which junctions are due for a T1 or an inverse T1, and making one (junction_transitions.h).
#include "run/junction_transitions.h"

#include "core/errors.h"
#include "geometry/geometry.h"
#include "mesh/transitions.h"

#include <algorithm>
#include <type_traits>

namespace froth {
namespace {

/// A product of a transition is due again once it is below this fraction of its size right
/// after the transition (junction_transitions.h).
constexpr double kProductShrink = 0.5;

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
    std::vector<Junction> js = films ? collapsible_films(c) : quadruple_lines(c);
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
    for (bool films : {false, true}) {
        const auto& memory = films ? film_sizes_ : line_sizes_;
        auto& products = products_[films];
        for (auto it = products.begin(); it != products.end();) {
            const auto now = memory.find(it->first);
            if (now == memory.end() || (it->second >= 0 && now->second > it->second)) {
                it = products.erase(it); // gone, or grown: a junction like any other now
                continue;
            }
            if (it->second < 0) it->second = now->second;
            ++it;
        }
    }
}

void JunctionTransitions::carry_over(const std::vector<int>& original_body) {
    std::map<int, int> now{{-1, -1}};
    for (std::size_t b = 0; b < original_body.size(); ++b) now[original_body[b]] = static_cast<int>(b);
    // original ids grow with the ids now (pops only remove), so renumbered keys stay sorted
    const auto renumber = [&](auto& memory) {
        std::remove_reference_t<decltype(memory)> out;
        for (const auto& [cells, size] : memory) {
            std::vector<int> key = cells;
            bool gone = false;
            for (int& k : key) {
                const auto it = now.find(k);
                gone = gone || it == now.end();
                if (!gone) k = it->second;
            }
            if (!gone) out.emplace(std::move(key), size);
        }
        memory = std::move(out);
    };
    renumber(line_sizes_), renumber(film_sizes_), renumber(products_[0]), renumber(products_[1]);
    new_look();
    bodies_ = static_cast<int>(original_body.size());
}

bool JunctionTransitions::protected_product(const Junction& j, bool film) const {
    const auto product = products_[film].find(j.cells);
    return product != products_[film].end() && !(j.size < kProductShrink * product->second);
}

std::vector<Junction> JunctionTransitions::due(const Cluster& c, bool films, double limit,
                                               bool force,
                                               const std::vector<int>& original_body) const {
    const auto& memory = films ? film_sizes_ : line_sizes_;
    std::vector<Junction> out;
    for (Junction& j : junctions(c, films, original_body)) {
        if (!(j.size < (films ? j.sides() : 1) * limit)) continue;
        if (made_[films].count(j.cells)) continue; // a product of this look's transitions
        if (protected_product(j, films)) continue;
        const auto was = memory.find(j.cells);
        if (force || (was != memory.end() && j.size < was->second)) out.push_back(std::move(j));
    }
    std::sort(out.begin(), out.end(),
              [](const Junction& x, const Junction& y) { return x.size < y.size; });
    return out;
}

namespace {

/// The triangular film that has triple line `line` on its border, or null. A T1 there would
/// leave a two-sided film whose collapse then takes the film: the triangle's inverse T1 in
/// two steps (the same cells meet in the end), which on a film of one facet (a T1's) the T1
/// cannot even make.
const Junction* triangle_beside(const Cluster& c, int line, const std::vector<Junction>& films) {
    for (const Junction& f : films)
        if (f.sides() == 3)
            for (int s : c.triple_lines()[line].surfaces)
                if (s == f.id) return &f;
    return nullptr;
}

} // namespace

std::optional<Cluster> JunctionTransitions::make(const Cluster& c, bool films, bool force,
                                                 const std::vector<int>& original_body,
                                                 TransitionEvent& event) {
    if (c.quadruple_points().size() < 2u) return std::nullopt;
    const double limit = fraction_ * mean_edge_length(c);
    const std::vector<Junction> small_films = films ? std::vector<Junction>{}
                                                    : junctions(c, true, original_body);
    for (const Junction& j : due(c, films, limit, force, original_body)) {
        TransitionRecord record;
        const Junction* triangle = films ? nullptr : triangle_beside(c, j.id, small_films);
        if (triangle && protected_product(*triangle, true)) continue; // its side relaxes with it
        const Junction& acted = triangle ? *triangle : j; // the junction that changes
        const bool film = films || triangle;
        try {
            // the product is at least twice the limit in size where the mesh lets it be
            const int id = acted.id;
            Cluster changed = !film                ? t1_line_to_film(c, id, &record, 2 * limit)
                              : acted.sides() == 3 ? t1_film_to_line(c, id, &record, 2 * limit)
                                                   : collapse_two_sided_film(c, id, &record);
            event = TransitionEvent{record.kind, record.where, c.time(), 0, -1, 0, energy(c),
                                    energy(changed)};
            (film ? event.film : event.line) = id;
            event.cells = record.cells;
            for (int& k : event.cells)
                if (k >= 0) k = original_body[k];
            if (!film || acted.sides() == 3) { // the product: a film of a T1, a line of an inverse T1
                made_[!film].insert(product_cells(acted.cells, film));
                products_[!film][product_cells(acted.cells, film)] = -1;
            }
            return changed;
        } catch (const TopologyError& x) {
            std::string why = x.what();
            for (const std::string op : {"t1: ", "t1_inverse: ", "collapse_two_sided_film: "})
                if (why.rfind(op, 0) == 0) why.erase(0, op.size());
            const char* what = !film                ? "no T1"
                               : acted.sides() == 3 ? "no inverse T1"
                                                    : "no collapse of a two-sided film";
            refused_ = std::string(what) + " could be made: " + why;
        }
    }
    return std::nullopt;
}

} // namespace froth
