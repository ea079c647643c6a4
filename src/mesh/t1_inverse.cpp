// The inverse T1 of 3D foams (transitions.h, t1_film_to_line): a small triangular film
// collapses to a triple line (the H -> I transition; Evolver's pop_tri_to_edge).
//
// Before: the film F between cells D and E is bounded by three triple lines l_A, l_B, l_C
// between the quadruple points q_AB, q_BC, q_CA, l_X with cells (D, E, X) and films F, D|X,
// E|X; at q_XY the film X|Y starts, between the lines (D, X, Y) and (E, X, Y). After: a
// line from a (cells A, B, C, D) to b (A, B, C, E) with the films A|B, B|C, C|A around it.
// F goes; in D|X the vertices of l_X (its corners too) become a and its facets along l_X go,
// in E|X they become b; the fan of X|Y at q_XY splits, the facets on the side of (D, X, Y)
// take a, those on the side of (E, X, Y) take b, and a new facet (a, u, b) fills the gap,
// its edge the new line's edge in X|Y. So a and b each have six films and four triple
// lines: Plateau quadruple points. This is the T1 of t1.cpp run backwards.
//
// A two-sided film (a lens between two quadruple points q_1, q_2, sides l_X and l_Y; what a T1
// on a side of a triangular film leaves) collapses by the same surgery: its sides become a
// (in D|X, D|Y) and b (in E|X, E|Y), and the fans of X|Y at q_1 and q_2 split between a and b,
// the two gap facets sharing the edge (a, b). That edge is not a triple line: the two X|Y
// films at q_1 and q_2 (or the one, met twice) become one film across it, and a and b are
// points of the lines (D, X, Y) and (E, X, Y), which run on through them. D and E no longer
// touch there; two quadruple points go.
//
// A disc film (F bounded by one closed triple line l_X, a contact of D and E through a hole in
// the films of X; what a T1 of a cell that meets itself leaves behind) collapses the same way
// with one side and no corners: l_X becomes a in D|X and b in E|X, points inside those films,
// which close over the hole. D and E no longer touch there, and X fills the gap between them.
#include "mesh/transitions.h"

#include "core/errors.h"
#include "core/format.h"
#include "mesh/transition_surgery.h"
#include "mesh/walls.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace froth {
namespace {

/// One side of the film: triple line l_X and the two other films along it.
constexpr int kNoCell = -2; // -1 is the outside

struct Side {
    int line = -1;
    int cell = kNoCell; ///< X
    int film_d = -1; ///< D|X
    int film_e = -1; ///< E|X
    double length = 0;
};

class InverseT1 {
  public:
    /// sides: 3 for the inverse T1 of a triangular film, 2 for the collapse of a lens, 1 for
    /// that of a disc.
    InverseT1(const Cluster& c, int film, int sides, double min_length, double smallest_length,
              bool fit)
        : c_(c), film_(film), n_sides_(sides), min_length_(min_length),
          smallest_length_(smallest_length), fit_(fit),
          name_(std::string(operation(sides)) + ": surface " + std::to_string(film + 1)),
          cells_(surface_cells(c)) {}

    static const char* operation(int sides) {
        return sides == 3 ? "t1_inverse"
               : sides == 2 ? "collapse_two_sided_film"
                            : "collapse_disc_film";
    }

    Cluster run(TransitionRecord* record);

  private:
    void check_film();
    void find_sides();
    std::string shape_wanted() const;
    Side side_of(int line) const;
    void find_corner_films();
    void unwrap_film();
    int corner_towards(int q, int film, int w) const;
    std::vector<Vec3> place_line(const ClusterSpec& spec);
    void join_corner_films(ClusterSpec& spec);
    Cluster finish(Cluster r) const;
    void check_ends(const Cluster& r, const std::vector<int>& used) const;
    std::string where() const;

    const Cluster& c_;
    const int film_;
    const int n_sides_;
    const double min_length_, smallest_length_;
    const bool fit_; // the line's ends may be moved off slivers (surgery::fit_corners)
    const std::string name_;
    const std::vector<std::array<int, 2>> cells_;
    int d_cell_ = -1, e_cell_ = -1;       // D, E
    std::set<int> vertices_;              // F's vertices
    std::vector<Side> sides_;
    std::map<int, int> corner_film_;      // q_XY -> X|Y
    std::vector<int> removed_;            // the surfaces that go, sorted: F (and a lens's X|Y)
    std::map<int, Vec3> u_;               // F's vertices unwrapped, in one frame
    std::map<int, Offset> d_;             // their lattice offsets in that frame
    Vec3 centre_ = Vec3::Zero(), into_d_ = Vec3::Zero();
    double length_ = 0;                   // the new line's
    bool fitted_ = false;                 // its ends were moved off slivers
    int n_ = 0;                           // c's vertex count: a is n_, b is n_ + 1
    std::vector<surgery::MovedFacet> moved_;
};

void InverseT1::check_film() {
    d_cell_ = cells_[film_][0];
    e_cell_ = cells_[film_][1];
    if (d_cell_ == e_cell_)
        throw TopologyError(name_ + " lies between " + surgery::cell_name(d_cell_) +
                            " and itself; only "
                            "a film between two cells can collapse to a line");
    const Surface& s = c_.surface(film_);
    std::set<std::pair<int, int>> edges;
    for (const Tri& t : s.triangles)
        for (int j = 0; j < 3; ++j) {
            vertices_.insert(t[j]);
            edges.insert(std::minmax(t[j], t[(j + 1) % 3]));
        }
    for (int v : vertices_)
        if (c_.is_fixed(v) || c_.curve_point(v) || !c_.vertex_walls(v).empty())
            throw TopologyError(name_ + " has a fixed vertex or one on a wall (" +
                                std::to_string(v + 1) + "); it cannot change");
    const long euler = static_cast<long>(vertices_.size()) - static_cast<long>(edges.size()) +
                       static_cast<long>(s.triangles.size());
    if (euler != 1)
        throw TopologyError(name_ + " is not a disk (Euler characteristic " +
                            std::to_string(euler) + ")");
}

Side InverseT1::side_of(int line) const {
    const TripleLine& tl = c_.triple_lines()[line];
    Side side;
    side.line = line;
    for (int s : tl.surfaces) {
        if (s == film_) continue;
        const auto& k = cells_[s];
        const bool has_d = k[0] == d_cell_ || k[1] == d_cell_;
        const bool has_e = k[0] == e_cell_ || k[1] == e_cell_;
        if (has_d == has_e) continue; // neither or both: not a D|X or E|X film
        (has_d ? side.film_d : side.film_e) = s;
        const int x = k[0] == (has_d ? d_cell_ : e_cell_) ? k[1] : k[0];
        if (side.cell != kNoCell && side.cell != x) side.film_d = side.film_e = -1;
        side.cell = x;
    }
    if (side.film_d < 0 || side.film_e < 0 || side.cell == d_cell_ || side.cell == e_cell_)
        throw TopologyError(name_ + ": triple line " + std::to_string(line + 1) +
                            " on its "
                            "border does not join it to the films of one third cell with " +
                            surgery::cell_name(d_cell_) + " and " + surgery::cell_name(e_cell_));
    return side;
}

/// The three lines around F, each open, between quadruple points, three corners in all (two
/// for a lens); for a disc the one closed line.
void InverseT1::find_sides() {
    static const char* const number[] = {"", "one", "two", "three"};
    const auto& lines = c_.triple_lines();
    for (int l = 0; l < static_cast<int>(lines.size()); ++l) {
        const auto& fs = lines[l].surfaces;
        if (std::find(fs.begin(), fs.end(), film_) == fs.end()) continue;
        if (lines[l].closed != (n_sides_ == 1))
            throw TopologyError(name_ + " is bounded by the " +
                                (lines[l].closed ? "closed" : "open") + " triple line " +
                                std::to_string(l + 1) + "; " +
                                (n_sides_ == 1 ? shape_wanted()
                                               : "only a triangle of three lines between "
                                                 "quadruple points collapses"));
        sides_.push_back(side_of(l));
    }
    if (static_cast<int>(sides_.size()) != n_sides_)
        throw TopologyError(name_ + " has " + std::to_string(sides_.size()) + " triple lines "
                            "on its border, not " + number[n_sides_] + "; " + shape_wanted());
    if (n_sides_ == 1) return; // a loop has no corners
    std::map<int, int> ends;
    std::set<int> cells;
    for (const Side& side : sides_) {
        const auto& v = lines[side.line].vertices;
        ++ends[v.front()];
        ++ends[v.back()];
        cells.insert(side.cell);
    }
    for (const auto& [q, count] : ends)
        if (count != 2 || c_.vertex_junction_edges(q).size() != 4)
            throw TopologyError(name_ + ": its border's corner at vertex " +
                                std::to_string(q + 1) + " is not a quadruple point where two "
                                "of its lines meet");
    if (static_cast<int>(ends.size()) != n_sides_ || static_cast<int>(cells.size()) != n_sides_)
        throw TopologyError(name_ + ": the cells around its border are not " +
                            (n_sides_ == 3 ? "three" : "two") + " distinct ones besides " +
                            surgery::cell_name(d_cell_) + " and " + surgery::cell_name(e_cell_));
}

/// What this collapse takes, for the messages.
std::string InverseT1::shape_wanted() const {
    return n_sides_ == 3   ? "only a triangular film collapses to a line"
           : n_sides_ == 2 ? "only a two-sided film (a lens) collapses this way"
                           : "only a disc bounded by one closed triple line collapses this way";
}

/// At each corner q_XY, the one film there that is neither F nor a side's: X|Y.
void InverseT1::find_corner_films() {
    if (n_sides_ == 1) return;
    std::set<int> side_films{film_};
    for (const Side& side : sides_) side_films.insert({side.film_d, side.film_e});
    for (const Side& side : sides_) {
        const auto& v = c_.triple_lines()[side.line].vertices;
        for (int q : {v.front(), v.back()}) {
            if (corner_film_.count(q)) continue;
            std::vector<int> others;
            for (int s : surgery::surfaces_at(c_, q))
                if (!side_films.count(s)) others.push_back(s);
            if (others.size() != 1)
                throw TopologyError(name_ + ": its corner at vertex " + std::to_string(q + 1) +
                                    " has " + std::to_string(others.size()) + " films besides "
                                    "its own and its sides', not one");
            corner_film_[q] = others.front();
        }
    }
}

/// F's vertices in one frame (through its edges' lattice shifts), its centre and the unit
/// normal into D, the sides' lengths.
void InverseT1::unwrap_film() {
    const Surface& s = c_.surface(film_);
    std::map<int, std::vector<int>> next;
    for (const Tri& t : s.triangles)
        for (int j = 0; j < 3; ++j) next[t[j]].push_back(t[(j + 1) % 3]);
    std::vector<int> queue{*vertices_.begin()};
    u_[queue[0]] = c_.position(queue[0]);
    for (std::size_t i = 0; i < queue.size(); ++i) {
        const int v = queue[i];
        for (int w : next[v]) {
            if (u_.count(w)) continue;
            u_[w] = u_[v] + (c_.position(w) - c_.position(v) + c_.edge_shift(v, w));
            queue.push_back(w);
        }
    }
    if (u_.size() != vertices_.size())
        throw TopologyError(name_ + " is not connected");
    for (const auto& [v, u] : u_) d_[v] = surgery::lattice_offset(c_, u, c_.position(v));

    Vec3 area = Vec3::Zero();
    double total = 0;
    for (const Tri& t : s.triangles) {
        const Vec3 n = 0.5 * (u_[t[1]] - u_[t[0]]).cross(u_[t[2]] - u_[t[0]]);
        area += n;
        total += n.norm();
        centre_ += n.norm() * (u_[t[0]] + u_[t[1]] + u_[t[2]]) / 3.0;
    }
    if (!(area.norm() > 0)) throw TopologyError(name_ + " has no area");
    centre_ /= total;
    // sign +1: the surface's normal points out of the body
    int out_of_d = 0;
    for (int k : {d_cell_, e_cell_}) {
        if (k < 0) continue;
        for (const BodyFace& f : c_.bodies()[k].faces)
            if (f.surface == film_) out_of_d = k == d_cell_ ? f.sign : -f.sign;
    }
    into_d_ = -out_of_d * area.normalized();
    for (Side& side : sides_) {
        const TripleLine& tl = c_.triple_lines()[side.line];
        const auto& v = tl.vertices;
        for (std::size_t i = 1; i < v.size(); ++i) side.length += (u_[v[i]] - u_[v[i - 1]]).norm();
        if (tl.closed) side.length += (u_[v.front()] - u_[v.back()]).norm();
    }
}

/// In X|Y at corner q, the new corner its fan takes towards w: a on the side of the line
/// (D, X, Y), b on that of (E, X, Y).
int InverseT1::corner_towards(int q, int film, int w) const {
    for (int e : c_.vertex_junction_edges(q)) {
        const JunctionEdge& je = c_.junction_edges()[e];
        if (je.a != w && je.b != w) continue;
        for (int s : je.surfaces) {
            if (s == film) continue;
            const auto& k = cells_[s];
            if (k[0] == d_cell_ || k[1] == d_cell_) return n_;
            if (k[0] == e_cell_ || k[1] == e_cell_) return n_ + 1;
        }
    }
    throw TopologyError(name_ + ": surface " + std::to_string(film + 1) + " does not end on "
                        "the lines of the corner at vertex " + std::to_string(q + 1));
}

/// The positions after the collapse: c's, then a and b on the normal through F's centre,
/// length_ apart, length_ from the sides' mean length (or min_length) halved while a facet
/// would turn over, at most ten times and not below smallest_length. Where a facet turns, a
/// and b are first moved off the slivers (surgery::fit_corners, at most the length) so long as
/// they stay half the length apart.
std::vector<Vec3> InverseT1::place_line(const ClusterSpec& spec) {
    double mean = 0; // a disc's: its diameter, the loop's length over pi
    for (const Side& side : sides_) mean += side.length / (n_sides_ == 1 ? M_PI : n_sides_);
    int turned = -1;
    double length = std::max(mean, min_length_);
    for (int halvings = 0; halvings <= 10; ++halvings, length *= 0.5) {
        std::vector<Vec3> V = c_.positions();
        V.push_back(centre_ + 0.5 * length * into_d_);
        V.push_back(centre_ - 0.5 * length * into_d_);
        if (!surgery::turns_a_facet(spec, V, moved_, &turned)) {
            length_ = length;
            return V;
        }
        if (fit_ && surgery::fit_corners(spec, V, moved_, {n_, n_ + 1}, length) &&
            (V[n_] - V[n_ + 1]).norm() >= 0.5 * length) {
            length_ = length, fitted_ = true;
            return V;
        }
        if (0.5 * length < smallest_length_) break;
    }
    throw TopologyError(name_ + ": its collapse would turn a facet of surface " +
                        std::to_string(turned + 1) + " over; the mesh around it is too fine "
                        "or too coarse for it");
}

/// A lens: the X|Y film at its second corner joins the one at its first (its facets turned
/// if the two face different ways), which keeps its tension; the second goes.
void InverseT1::join_corner_films(ClusterSpec& spec) {
    removed_ = {film_};
    if (n_sides_ != 2) return;
    const int keep = corner_film_.begin()->second, gone = corner_film_.rbegin()->second;
    if (keep == gone) return;
    // both lie between X and Y, one of which is a body: the sign it gives each says their ways
    surgery::join_films(c_, spec, keep, gone, sides_[0].cell >= 0 ? sides_[0].cell : sides_[1].cell);
    removed_.push_back(gone);
    std::sort(removed_.begin(), removed_.end());
}

/// The materials of the kept surfaces, the time and the bodies' volumes go over to r.
Cluster InverseT1::finish(Cluster r) const {
    surgery::carry_over_without_surfaces(c_, removed_, r);
    return r;
}

/// a and b are quadruple points after an inverse T1, points of one triple line each after a
/// lens's collapse, points inside one film each after a disc's.
void InverseT1::check_ends(const Cluster& r, const std::vector<int>& used) const {
    const std::size_t lines = n_sides_ == 3 ? 4 : n_sides_ == 2 ? 2 : 0;
    const char* what = n_sides_ == 3   ? "an end of the new line is not a quadruple point"
                       : n_sides_ == 2 ? "a new point is not on one triple line"
                                       : "a new point is not inside one film";
    for (int p : {n_, n_ + 1})
        if (r.vertex_junction_edges(used[p]).size() != lines)
            throw TopologyError(name_ + ": " + what + "; refine the mesh around the film first");
}

std::string InverseT1::where() const {
    std::string lines, cells;
    for (const Side& side : sides_) {
        lines += (lines.empty() ? "" : ", ") + std::to_string(side.line + 1) + " (" +
                 fmt(side.length) + ")";
        cells += (cells.empty()                     ? ""
                  : side.line == sides_.back().line ? " and "
                                                    : ", ") +
                 surgery::cell_name(side.cell);
    }
    const std::string film = std::to_string(film_ + 1) + " between " + surgery::cell_name(d_cell_) +
                             " and " + surgery::cell_name(e_cell_) + " (triple lines " + lines +
                             ")";
    if (n_sides_ == 2)
        return "two-sided film " + film + " collapsed: " + cells + " meet across it at " +
               point_text(centre_);
    if (n_sides_ == 1)
        return "disc film " + film + " collapsed: " + cells + " closes between them at " +
               point_text(centre_);
    return "triangular film " + film + " became a triple line of length " + fmt(length_) +
           " between " + cells + " at " + point_text(centre_);
}

Cluster InverseT1::run(TransitionRecord* record) {
    check_film();
    find_sides();
    find_corner_films();
    unwrap_film();
    n_ = c_.n_vertices();

    ClusterSpec spec = cluster_spec(c_);
    for (const Side& side : sides_) {
        std::map<int, Offset> on_line;
        for (int v : c_.triple_lines()[side.line].vertices) on_line[v] = d_.at(v);
        surgery::collapse_onto(c_, spec, side.film_d, on_line, n_, moved_, name_);
        surgery::collapse_onto(c_, spec, side.film_e, on_line, n_ + 1, moved_, name_);
    }
    for (const auto& [q, film] : corner_film_) {
        const auto towards = [&, q = q, film = film](int w) { return corner_towards(q, film, w); };
        surgery::split_fan(c_, spec, film, q, d_.at(q), towards, moved_, name_);
    }
    std::vector<Vec3> V = place_line(spec);
    join_corner_films(spec);
    surgery::remove_surfaces(spec, removed_);
    const std::vector<int> used = surgery::keep_used_vertices(spec, V);
    surgery::copy_vertex_lists(c_, [&](int v) { return used[v]; }, spec);
    Cluster r = finish(surgery::rebuild(std::move(spec), name_, "its collapse"));
    check_ends(r, used);
    if (record) {
        record->kind = n_sides_ == 3   ? "inverse T1"
                       : n_sides_ == 2 ? "two-sided film"
                                       : "disc film";
        record->fitted = fitted_;
        record->size = length_;
        record->film = film_;
        record->cells = {d_cell_, e_cell_};
        record->point = centre_;
        record->removed_vertices = c_.n_vertices() + 2 - r.n_vertices();
        const int corners = n_sides_ == 1 ? 0 : n_sides_; // a gap facet per corner
        record->removed_facets = c_.n_facets() + corners - r.n_facets();
        record->where = where();
    }
    return r;
}

/// The collapse of `film` with `sides` sides; a film along its border that it would leave
/// without a facet has its other edges split first (as before a T1), which keeps the film's
/// id.
Cluster collapse_film(const Cluster& c, int film, int sides, double min_length,
                      double smallest_length, bool fit, TransitionRecord* record) {
    const std::optional<Cluster> split = split_films_emptied_by_collapse(c, film);
    return InverseT1(split ? *split : c, film, sides, min_length, smallest_length, fit)
        .run(record);
}

} // namespace

Cluster t1_film_to_line(const Cluster& c, int surface, TransitionRecord* record,
                        double min_length, double smallest_length, bool fit_corners) {
    if (surface < 0 || surface >= c.n_surfaces())
        throw InvalidInput("t1_inverse: surface " + std::to_string(surface + 1) + " does not "
                           "exist (the cluster has " + std::to_string(c.n_surfaces()) + ")");
    return collapse_film(c, surface, 3, min_length, smallest_length, fit_corners, record);
}

Cluster collapse_two_sided_film(const Cluster& c, int surface, TransitionRecord* record,
                                double min_length, bool fit_corners) {
    if (surface < 0 || surface >= c.n_surfaces())
        throw InvalidInput("collapse_two_sided_film: surface " + std::to_string(surface + 1) +
                           " does not exist (the cluster has " + std::to_string(c.n_surfaces()) +
                           ")");
    return collapse_film(c, surface, 2, min_length, 0, fit_corners, record);
}

Cluster collapse_disc_film(const Cluster& c, int surface, TransitionRecord* record,
                           double min_length, bool fit_corners, bool by_caps) {
    if (surface < 0 || surface >= c.n_surfaces())
        throw InvalidInput("collapse_disc_film: surface " + std::to_string(surface + 1) +
                           " does not exist (the cluster has " + std::to_string(c.n_surfaces()) +
                           ")");
    if (by_caps) return surgery::cap_disc_film(c, surface, record);
    return collapse_film(c, surface, 1, min_length, 0, fit_corners, record);
}

Cluster close_disc_film(const Cluster& c, int surface, TransitionRecord* record,
                        bool fit_corners, const DiscCheck& check) {
    TransitionRecord collapse_record, caps_record;
    const auto made = [&](Cluster r, TransitionRecord& made_record) {
        if (check) check(r, made_record);
        if (record) *record = made_record;
        return r;
    };
    try {
        return made(collapse_disc_film(c, surface, &collapse_record, 0, fit_corners),
                    collapse_record);
    } catch (const TopologyError& collapse) {
        try {
            return made(collapse_disc_film(c, surface, &caps_record, 0, fit_corners, true),
                        caps_record);
        } catch (const TopologyError& caps) {
            std::string why = caps.what();
            const std::string name = "collapse_disc_film: ";
            if (why.rfind(name, 0) == 0) why.erase(0, name.size());
            throw TopologyError(std::string(collapse.what()) + "; nor can caps close it: " + why);
        }
    }
}

} // namespace froth
