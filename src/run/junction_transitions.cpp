// Which junctions are due for a T1 or an inverse T1, and making one (junction_transitions.h).
#include "run/junction_transitions.h"

#include "checks/self_intersection.h"
#include "core/errors.h"
#include "geometry/geometry.h"
#include "mesh/transitions.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>

namespace froth {
namespace {

/// A product of a transition is due again once it is below this fraction of its size right
/// after the transition (junction_transitions.h).
constexpr double kProductShrink = 0.5;

/// For this many looks after a transition, one that undoes it at the same two cells is made
/// only when forced (junction_transitions.h).
constexpr int kContactLooks = 10;

/// A film whose mean width (2 area / perimeter) is below this fraction of the T1 length is
/// squeezed flat whatever its perimeter, and due: an equilateral triangle at the perimeter
/// limit is 0.29 of it wide.
constexpr double kThinFilm = 0.1;

/// A film's waist is remembered below this many T1 lengths, so that one that comes below the
/// T1 length is known to be shrinking.
constexpr double kWaistMemory = 4;

std::string cell_name(int k) {
    return k < 0 ? std::string("the outside") : "body " + std::to_string(k + 1);
}

/// The two cells a transition of `j` (a film's with `film`, else a line's T1) separates or
/// joins by a film.
std::vector<int> contact_of(const Junction& j, bool film) {
    return film ? std::vector<int>{j.cells[0], j.cells[1]}
                : std::vector<int>{j.cells[3], j.cells[4]};
}

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

std::vector<FilmWaist> JunctionTransitions::waists(const Cluster& c, double below,
                                                   const std::vector<int>& original_body) const {
    std::vector<FilmWaist> out = film_waists(c, below);
    for (FilmWaist& w : out)
        for (int& k : w.cells)
            if (k >= 0) k = original_body[k];
    return out;
}

void JunctionTransitions::remember(const Cluster& c, const std::vector<int>& original_body) {
    for (bool films : {false, true}) {
        auto& memory = films ? film_sizes_ : line_sizes_;
        memory.clear();
        for (const Junction& j : junctions(c, films, original_body)) memory[j.cells] = j.size;
    }
    waist_sizes_.clear();
    for (const FilmWaist& w : waists(c, kWaistMemory * fraction_ * mean_edge_length(c), original_body)) {
        const std::vector<int> key(w.cells.begin(), w.cells.end());
        if (!waist_sizes_.count(key)) waist_sizes_[key] = w.length; // the shortest edge
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
    renumber(contacts_), renumber(waist_sizes_);
    made_[0].clear(), made_[1].clear(), refused_.clear(), forced_refused_.clear();
    refusals_.clear();
    bodies_ = static_cast<int>(original_body.size());
}

namespace {

/// The arrays of a memory's maps: per entry the number of cells, the cells (1-based body
/// ids, 0 the outside) and the value.
template <class Map> NamedValues map_array(const char* name, const Map& memory) {
    NamedValues a{name, {}};
    for (const auto& [cells, value] : memory) {
        a.values.push_back(static_cast<double>(cells.size()));
        for (int k : cells) a.values.push_back(k + 1);
        a.values.push_back(static_cast<double>(value));
    }
    return a;
}

/// The map of map_array's array `name` (empty if there is none), checked.
/// \throw InvalidInput
template <class Value>
std::map<std::vector<int>, Value> array_map(const std::vector<NamedValues>& in, const char* name,
                                            int n_bodies, double least, double most) {
    std::map<std::vector<int>, Value> out;
    const std::vector<double>* a = find_named(in, name);
    if (!a) return out;
    const auto bad = [&](const std::string& what) {
        return InvalidInput(std::string("transition memory: ") + name + ": " + what);
    };
    for (std::size_t i = 0; i < a->size();) {
        const double n = (*a)[i++];
        // n cells and the value after them
        if (!(n >= 1 && n <= 5 && n == std::floor(n)) || i + static_cast<std::size_t>(n) >= a->size())
            throw bad("an entry's length does not fit the array");
        std::vector<int> cells;
        for (int k = 0; k < static_cast<int>(n); ++k) {
            const double id = (*a)[i++];
            if (!(id >= 0 && id <= n_bodies && id == std::floor(id)))
                throw bad("a body id out of range [0, " + std::to_string(n_bodies) + "]");
            cells.push_back(static_cast<int>(id) - 1);
        }
        const double value = (*a)[i++];
        if (!(value >= least && value <= most)) throw bad("a value out of range");
        if (std::is_integral_v<Value> && value != std::floor(value))
            throw bad("a look that is not a whole number");
        out.emplace(std::move(cells), static_cast<Value>(value));
    }
    return out;
}

} // namespace

void JunctionTransitions::save(std::vector<NamedValues>& out) const {
    out.push_back({"junctions.scalars",
                   {fraction_, fit_corners_ ? 1.0 : 0.0, static_cast<double>(bodies_),
                    static_cast<double>(look_)}});
    out.push_back(map_array("junctions.line_sizes", line_sizes_));
    out.push_back(map_array("junctions.film_sizes", film_sizes_));
    out.push_back(map_array("junctions.line_products", products_[0]));
    out.push_back(map_array("junctions.film_products", products_[1]));
    out.push_back(map_array("junctions.contacts", contacts_));
    out.push_back(map_array("junctions.waist_sizes", waist_sizes_));
}

std::optional<JunctionTransitions> JunctionTransitions::restore(const std::vector<NamedValues>& in,
                                                                int n_bodies) {
    const std::vector<double>* scalars = find_named(in, "junctions.scalars");
    if (!scalars) return std::nullopt;
    const auto& v = *scalars;
    if (v.size() != 4 || !(v[0] > 0 && v[0] < 1) || (v[1] != 0 && v[1] != 1) ||
        v[2] != n_bodies || !(v[3] >= 0 && v[3] < 1e9 && v[3] == std::floor(v[3])))
        throw InvalidInput("transition memory: junctions.scalars must be a line fraction in "
                           "(0, 1), 0 or 1, the number of bodies (" +
                           std::to_string(n_bodies) + ") and a look count");
    JunctionTransitions m(v[0], v[1] == 1);
    m.bodies_ = n_bodies;
    m.look_ = static_cast<int>(v[3]);
    constexpr double kMost = 1e300;
    m.line_sizes_ = array_map<double>(in, "junctions.line_sizes", n_bodies, 0, kMost);
    m.film_sizes_ = array_map<double>(in, "junctions.film_sizes", n_bodies, 0, kMost);
    m.products_[0] = array_map<double>(in, "junctions.line_products", n_bodies, -1, kMost);
    m.products_[1] = array_map<double>(in, "junctions.film_products", n_bodies, -1, kMost);
    m.contacts_ = array_map<int>(in, "junctions.contacts", n_bodies, m.look_ - kContactLooks,
                                 m.look_);
    m.waist_sizes_ = array_map<double>(in, "junctions.waist_sizes", n_bodies, 0, kMost);
    return m;
}

void JunctionTransitions::new_look() {
    ++look_;
    for (auto it = contacts_.begin(); it != contacts_.end();)
        it = look_ - it->second >= kContactLooks ? contacts_.erase(it) : std::next(it);
    made_[0].clear(), made_[1].clear(), refused_.clear(), forced_refused_.clear();
    refusals_.clear();
}

namespace {

/// A hash of c's mesh (its vertices' positions and every surface's facets): the refusals hold
/// only for the mesh they were met on, or one that a transition of this memory made from it.
std::uint64_t mesh_fingerprint(const Cluster& c) {
    std::uint64_t h = 1469598103934665603ull; // FNV-1a
    const auto mix = [&](std::uint64_t x) { h = (h ^ x) * 1099511628211ull; };
    for (const Vec3& x : c.positions())
        for (int k = 0; k < 3; ++k) {
            std::uint64_t bits;
            std::memcpy(&bits, &x[k], sizeof bits);
            mix(bits);
        }
    for (const Surface& s : c.surfaces()) {
        mix(s.triangles.size());
        for (const Tri& t : s.triangles)
            for (int v : t) mix(static_cast<std::uint64_t>(v));
    }
    return h;
}

} // namespace

void JunctionTransitions::forget_refusals_near(const std::vector<int>& cells) {
    const auto near = [&](const std::vector<int>& other) {
        int common = 0;
        for (int k : other) common += std::count(cells.begin(), cells.end(), k) > 0;
        return common >= 2;
    };
    for (auto it = refusals_.begin(); it != refusals_.end();)
        it = near(std::get<2>(it->first)) ? refusals_.erase(it) : std::next(it);
}

std::string JunctionTransitions::undoes_recent(const std::vector<int>& pair, bool force) const {
    const auto it = contacts_.find(pair);
    if (it == contacts_.end() || force) return {};
    const int ago = look_ - it->second;
    const std::string when = ago == 0 ? "just made"
                             : "made " + std::to_string(ago) + (ago == 1 ? " look" : " looks") +
                                   " before (a step of evolve, a round of minimize)";
    return "it would undo the transition between " + cell_name(pair[0]) + " and " +
           cell_name(pair[1]) + " " + when;
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
        const bool flat = films && j.width < kThinFilm * limit; // due shrinking or not
        // a disc's perimeter against a triangle's: both are due about a limit across
        const int sides = !films ? 1 : j.sides() == 1 ? 3 : j.sides();
        if (!(j.size < sides * limit) && !flat) continue;
        // a product of this look's or an earlier transition, unless forced (an edge is
        // collapsing: the run stops if nothing clears it)
        if (!force && (made_[films].count(j.cells) || protected_product(j, films))) continue;
        const auto was = memory.find(j.cells);
        if (force || flat || (was != memory.end() && j.size < was->second))
            out.push_back(std::move(j));
    }
    std::sort(out.begin(), out.end(),
              [](const Junction& x, const Junction& y) { return x.size < y.size; });
    return out;
}

namespace {

bool on_border(const Cluster& c, int line, int film) {
    const auto& s = c.triple_lines()[line].surfaces;
    return std::find(s.begin(), s.end(), film) != s.end();
}

/// The triangular film that has triple line `line` on its border, or null. A T1 there would
/// leave a two-sided film whose collapse then takes the film: the triangle's inverse T1 in
/// two steps (the same cells meet in the end), which is tried first.
const Junction* triangle_beside(const Cluster& c, int line, const std::vector<Junction>& films) {
    for (const Junction& f : films)
        if (f.sides() == 3 && on_border(c, line, f.id)) return &f;
    return nullptr;
}

/// The lines on the border of triangular film `film`, shortest first.
std::vector<Junction> sides_of(const Cluster& c, int film, const std::vector<Junction>& lines) {
    std::vector<Junction> out;
    for (const Junction& l : lines)
        if (on_border(c, l.id, film)) out.push_back(l);
    std::sort(out.begin(), out.end(),
              [](const Junction& x, const Junction& y) { return x.size < y.size; });
    return out;
}

} // namespace

std::optional<Cluster> JunctionTransitions::make(const Cluster& c, bool films, bool force,
                                                 const std::vector<int>& original_body,
                                                 TransitionEvent& event) {
    if (c.quadruple_points().size() < 2u) return std::nullopt;
    if (const std::uint64_t now = mesh_fingerprint(c); now != mesh_) refusals_.clear(), mesh_ = now;
    const double limit = fraction_ * mean_edge_length(c);
    const std::vector<Junction> small_films = films ? std::vector<Junction>{}
                                                    : junctions(c, true, original_body);
    for (const Junction& j : due(c, films, limit, force, original_body)) {
        const Junction* triangle = films ? nullptr : triangle_beside(c, j.id, small_films);
        // its side relaxes with it, unless forced
        if (triangle && !force && protected_product(*triangle, true)) continue;
        // the triangle's inverse T1 first; should the mesh refuse it, the line's own T1 (the
        // two-sided film it leaves collapses in a later look)
        if (triangle)
            if (auto changed = try_make(c, *triangle, true, force, limit, original_body, event))
                return changed;
        if (auto changed = try_make(c, j, films, force, limit, original_body, event))
            return changed;
        if (!films || j.sides() != 3) continue;
        // a triangle the mesh will not collapse: a T1 on a side makes it a lens, which the
        // collapse of two-sided films takes in a later look
        for (const Junction& side : sides_of(c, j.id, junctions(c, false, original_body)))
            if (auto changed = try_make(c, side, false, force, limit, original_body, event))
                return changed;
    }
    return std::nullopt;
}

namespace {

/// Throws where the transition's record says its new vertices may cross another film (moved
/// off slivers, or caps) and they do: the facets around the transition, out to a few edges
/// beyond what it moved.
void check_crossings(const Cluster& c, const Cluster& changed, const TransitionRecord& record) {
    if (!record.fitted && !record.capped) return;
    const Region around{record.point, 4 * record.size + 3 * mean_edge_length(c)};
    if (!find_self_intersections(changed, 1, &around).empty())
        throw TopologyError(record.capped ? "its caps would cross a film"
                                          : "its new corners, moved off the slivers beside it, "
                                            "would cross a film");
}

} // namespace

Cluster JunctionTransitions::transition_of(const Cluster& c, const Junction& acted, bool film,
                                           bool force, double limit,
                                           TransitionRecord& record) const {
    // the product is at least twice the limit in size where the mesh lets it be
    const int id = acted.id;
    if (film && acted.sides() == 1) // collapsed, or else capped, without crossings
        return close_disc_film(c, id, &record, fit_corners_,
                               [&c](const Cluster& r, const TransitionRecord& made) {
                                   check_crossings(c, r, made);
                               });
    // a cell meets itself across a line only where the run would stop otherwise: made
    // when due, in 3 of 8 small networks, each run stopped within 0.05 in time after it,
    // on a T1 refused for an edge of four films (they had gone further without it)
    Cluster changed = !film ? t1_line_to_film(c, id, &record, 2 * limit, 0, fit_corners_, force)
                      : acted.sides() == 3
                          ? t1_film_to_line(c, id, &record, 2 * limit, 0, fit_corners_)
                          : collapse_two_sided_film(c, id, &record, 0, fit_corners_);
    check_crossings(c, changed, record);
    return changed;
}

std::optional<Cluster> JunctionTransitions::try_make(const Cluster& c, const Junction& acted,
                                                     bool film, bool force, double limit,
                                                     const std::vector<int>& original_body,
                                                     TransitionEvent& event) {
    const char* what = !film                ? "no T1"
                       : acted.sides() == 3 ? "no inverse T1"
                       : acted.sides() == 2 ? "no collapse of a two-sided film"
                                            : "no collapse of a disc film";
    const std::vector<int> contact = contact_of(acted, film);
    if (std::string why = undoes_recent(contact, force); !why.empty()) {
        refused_ = std::string(what) + " could be made: " + why;
        return std::nullopt;
    }
    const auto key = std::make_tuple(film, force, acted.cells);
    if (const auto it = refusals_.find(key); it != refusals_.end() && it->second.size == acted.size) {
        refused_ = it->second.why;
        if (force) forced_refused_ = refused_;
        return std::nullopt;
    }
    TransitionRecord record;
    try {
        Cluster changed = transition_of(c, acted, film, force, limit, record);
        event = TransitionEvent{record.kind, record.where, c.time(), 0, -1, 0, energy(c),
                                energy(changed)};
        (film ? event.film : event.line) = acted.id;
        event.cells = record.cells;
        for (int& k : event.cells)
            if (k >= 0) k = original_body[k];
        if (!film || acted.sides() == 3) { // the product: a film of a T1, a line of an inverse T1
            made_[!film].insert(product_cells(acted.cells, film));
            products_[!film][product_cells(acted.cells, film)] = -1;
        }
        contacts_[contact] = look_;
        forget_refusals_near(acted.cells);
        mesh_ = mesh_fingerprint(changed);
        return changed;
    } catch (const TopologyError& x) {
        std::string why = x.what();
        for (const std::string op :
             {"t1: ", "t1_inverse: ", "collapse_two_sided_film: ", "collapse_disc_film: "})
            if (why.rfind(op, 0) == 0) why.erase(0, op.size());
        refused_ = std::string(what) + " could be made: " + why;
        refusals_[key] = {acted.size, refused_};
        if (force) forced_refused_ = refused_;
        return std::nullopt;
    }
}

double JunctionTransitions::t1_length(const Cluster& c) const {
    return fraction_ * mean_edge_length(c);
}

std::optional<Cluster> JunctionTransitions::pinch(const Cluster& c, double max_length, bool force,
                                                  const std::vector<int>& original_body,
                                                  TransitionEvent& event) {
    if (const std::uint64_t now = mesh_fingerprint(c); now != mesh_) refusals_.clear(), mesh_ = now;
    const double limit = t1_length(c);
    for (const FilmWaist& w : waists(c, max_length, original_body)) {
        const std::vector<int> cells(w.cells.begin(), w.cells.end());
        const auto was = waist_sizes_.find(cells);
        if (!force && (was == waist_sizes_.end() || !(w.length < was->second))) continue;
        const auto key = std::make_tuple(false, force, cells);
        if (const auto it = refusals_.find(key); it != refusals_.end() && it->second.size == w.length) {
            refused_ = it->second.why;
            continue;
        }
        // the contact a lens's collapse took there in the last few looks is not given back
        const std::vector<int> lens{cells[2], cells[3]};
        if (std::string why = undoes_recent(lens, force); !why.empty()) {
            refused_ = "no film pinch could be made: " + why;
            continue;
        }
        TransitionRecord record;
        try {
            Cluster changed = pinch_film(c, w.u, w.w, &record, 2 * limit, fit_corners_);
            check_crossings(c, changed, record);
            event = TransitionEvent{record.kind, record.where, c.time(), 0, -1, 0, energy(c),
                                    energy(changed)};
            event.film = record.film;
            for (int i = 0; i < 2; ++i)
                event.cells[i] = record.cells[i] >= 0 ? original_body[record.cells[i]] : -1;
            // the lens: its two cells, then those of its sides (the pinched film's)
            contacts_[lens] = look_;
            const std::vector<int> made{cells[2], cells[3], cells[0], cells[1]};
            made_[1].insert(made);
            products_[1][made] = -1;
            forget_refusals_near(cells);
            mesh_ = mesh_fingerprint(changed);
            return changed;
        } catch (const TopologyError& x) {
            std::string why = x.what();
            if (why.rfind("pinch_film: ", 0) == 0) why.erase(0, 12);
            refused_ = "no film pinch could be made: " + why;
            refusals_[key] = {w.length, refused_};
        }
    }
    return std::nullopt;
}

} // namespace froth
