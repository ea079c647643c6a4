// The T1 of 3D foams (transitions.h, t1_line_to_film): a shrinking triple line between two
// quadruple points becomes a small triangular film (the I -> H transition).
//
// Before: cells A, B, C around the line a..b, its films A|B, B|C, C|A; at a the fourth cell D
// with films A|D, B|D, C|D, at b the cell E with A|E, B|E, C|E. After: a triangle D|E with
// corners p_AB, p_BC, p_CA, each a quadruple point (p_AB of A, B, D, E), its edges the triple
// lines (D, E, B) from p_AB to p_BC and so on. In the film A|B the line's vertices become p_AB
// (its triple lines A|B|D from a and A|B|E from b now meet there) and its facets along the
// line go. The film A|D loses its corner a to two: the facets of its fan at a on the side of
// its triple line A|B|D take p_AB, those on the side of A|C|D take p_CA, and one new facet
// (p_AB, u, p_CA) fills the gap; its edge p_CA -> p_AB is the new triple line (D, E, A). So
// each new corner has six films and four triple lines: a Plateau quadruple point.
#include "mesh/transitions.h"

#include "core/errors.h"
#include "core/format.h"
#include "mesh/transition_surgery.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

namespace froth {
namespace {

std::string line_name(int l) { return "t1: triple line " + std::to_string(l + 1); }

/// What the surgery needs to know about one end (a or b) of the line.
struct LineEnd {
    int vertex = -1;
    std::vector<int> films; ///< the three films of the fourth cell there
    int cell = -1;          ///< the fourth cell (D at a, E at b)
};

class T1 {
  public:
    /// shown: the line's id in the messages and the record (its id before splits that
    /// renumbered the lines), line if negative
    T1(const Cluster& c, int line, double min_side, double smallest_side, bool fit,
       bool meets_itself, int shown = -1)
        : c_(c), line_(line), shown_(shown >= 0 ? shown : line), min_side_(min_side),
          smallest_side_(smallest_side), fit_(fit), meets_itself_(meets_itself),
          name_(line_name(shown_)), cells_(surface_cells(c)) {}

    Cluster run(TransitionRecord* record);

  private:
    void check_line();
    LineEnd end_at(int v);
    void unwrap_line();
    double first_side() const;
    void place_corners(double side);
    int corner_of(int film) const;
    void collapse_line_films(ClusterSpec& spec);
    void split_fans(ClusterSpec& spec, const LineEnd& end);
    std::vector<Vec3> place_film(const ClusterSpec& spec);
    std::vector<int> join_films_across(ClusterSpec& spec) const;
    double film_area(const std::vector<Vec3>& V) const;

    std::vector<surgery::MovedFacet> moved_; // the facets that took a new corner

    const Cluster& c_;
    const int line_, shown_;
    const double min_side_, smallest_side_;
    const bool fit_; // corners may be moved off slivers (surgery::fit_corners)
    const bool meets_itself_; // D = E is allowed (join_films_across)
    const std::string name_;
    const std::vector<std::array<int, 2>> cells_; // the bodies on each surface's sides
    std::vector<int> seg_;                 // the line's vertices, a first
    std::map<int, Offset> d_;              // their lattice offsets along the line, from a
    std::map<int, Vec3> u_;                // their unwrapped positions
    std::array<int, 3> films_{};           // A|B, B|C, C|A: the line's films
    std::set<int> line_cells_;
    LineEnd a_, b_;
    std::array<Vec3, 3> p_;                // the new corners, in a's frame
    double length_ = 0;
    double side_ = 0;                      // the new film's side
    bool fitted_ = false;                  // the corners were moved off slivers
    int n_ = 0;                            // c's vertex count: the corners are n_, n_+1, n_+2
};

void T1::check_line() {
    const TripleLine& tl = c_.triple_lines()[line_];
    if (tl.closed)
        throw TopologyError(name_ + " is a closed loop; only a line between two quadruple "
                            "points can become a film");
    seg_ = tl.vertices;
    films_ = tl.surfaces;
    const auto is_quadruple = [&](int v) { return c_.vertex_junction_edges(v).size() == 4; };
    if (seg_.front() == seg_.back() || !is_quadruple(seg_.front()) || !is_quadruple(seg_.back()))
        throw TopologyError(name_ + " does not join two distinct quadruple points");
    for (int v : seg_)
        if (c_.is_fixed(v) || c_.curve_point(v) || !c_.vertex_walls(v).empty())
            throw TopologyError(name_ + " has a fixed vertex or one on a wall (" +
                                std::to_string(v + 1) + "); it cannot change");
    for (int s : films_) line_cells_.insert(cells_[s].begin(), cells_[s].end());
}

LineEnd T1::end_at(int v) {
    LineEnd end;
    end.vertex = v;
    std::set<int> fourth;
    for (int s : surgery::surfaces_at(c_, v)) {
        if (std::find(films_.begin(), films_.end(), s) != films_.end()) continue;
        end.films.push_back(s);
        for (int k : cells_[s])
            if (!line_cells_.count(k)) fourth.insert(k);
    }
    if (end.films.size() != 3 || fourth.size() != 1)
        throw TopologyError(name_ + ": its end at vertex " + std::to_string(v + 1) + " is not a "
                            "quadruple point of four cells");
    end.cell = *fourth.begin();
    return end;
}

/// The line's positions as one connected polyline from a (through the edges' lattice shifts).
void T1::unwrap_line() {
    u_[seg_[0]] = c_.position(seg_[0]);
    for (std::size_t i = 1; i < seg_.size(); ++i) {
        const int v = seg_[i - 1], w = seg_[i];
        u_[w] = u_[v] + (c_.position(w) - c_.position(v) + c_.edge_shift(v, w));
        length_ += (u_[w] - u_[v]).norm();
    }
    for (int v : seg_) d_[v] = surgery::lattice_offset(c_, u_[v], c_.position(v));
}

/// The side the new film is first tried at: the line's length, half the mean edge at its
/// ends, or min_side, whichever is largest.
double T1::first_side() const {
    return std::max({length_, min_side_,
                     0.25 * (surgery::mean_edge_at(c_, seg_.front()) +
                             surgery::mean_edge_at(c_, seg_.back()))});
}

/// The corners p_s: in the plane through the line's midpoint normal to it, each in the
/// direction its film leaves the line (the film's conormal there), side / sqrt(3) from it.
void T1::place_corners(double side) {
    const Vec3 ua = u_[seg_.front()], ub = u_[seg_.back()];
    const Vec3 mid = 0.5 * (ua + ub);
    Vec3 along = ub - ua;
    if (along.norm() == 0) along = u_[seg_[1]] - ua;
    along.normalize();
    const std::set<int> on_line(seg_.begin(), seg_.end());
    for (int i = 0; i < 3; ++i) {
        const Surface& s = c_.surface(films_[i]);
        Vec3 conormal = Vec3::Zero();
        for (std::size_t f = 0; f < s.triangles.size() && conormal.norm() == 0; ++f) {
            const Tri& t = s.triangles[f];
            const auto x = s.corners(c_.positions(), f);
            int ka = -1, kq = -1, on = 0;
            for (int k = 0; k < 3; ++k) {
                if (t[k] == seg_.front()) ka = k;
                if (on_line.count(t[k])) ++on;
                else kq = k;
            }
            if (ka < 0 || on != 2) continue;
            const Vec3 w = x[kq] - x[ka];
            conormal = w - w.dot(along) * along;
        }
        if (!(conormal.norm() > 0))
            throw TopologyError(name_ + ": surface " + std::to_string(films_[i] + 1) +
                                " has no facet along the line at its end");
        p_[i] = mid + side / std::sqrt(3.0) * conormal.normalized();
    }
}

/// The positions after the T1: c's, then the three corners at the largest side from
/// first_side() down, halving, to an eighth of the line's length or smallest_side, that turns
/// no facet over (where the mesh beside the line is finer than the film would be). At each
/// side the corners are first placed as place_corners says, then, if a facet turns, moved by
/// surgery::fit_corners (at most the side) off the slivers beside the line, so long as the new
/// film keeps half its area. A side below the line's length is due for an inverse T1 if it
/// shrinks, but a refused T1 stops the run at the collapsing line.
std::vector<Vec3> T1::place_film(const ClusterSpec& spec) {
    const double smallest = std::max(0.125 * length_, smallest_side_);
    int turned = -1;
    for (double side = first_side();; side *= 0.5) {
        place_corners(side);
        std::vector<Vec3> V = c_.positions();
        V.insert(V.end(), p_.begin(), p_.end());
        if (!surgery::turns_a_facet(spec, V, moved_, &turned)) {
            side_ = side;
            return V;
        }
        if (fit_ && surgery::fit_corners(spec, V, moved_, {n_, n_ + 1, n_ + 2}, side) &&
            film_area(V) >= 0.5 * std::sqrt(3.0) / 4 * side * side) {
            side_ = side, fitted_ = true;
            return V;
        }
        if (0.5 * side < smallest) break;
    }
    throw TopologyError(name_ + ": the T1 would turn a facet of surface " +
                        std::to_string(turned + 1) + " over (a sliver next to the line); the "
                        "mesh there is too fine across the line for it");
}

/// The area of the new film at positions V (its corners n_, n_ + 1, n_ + 2 are in one frame).
double T1::film_area(const std::vector<Vec3>& V) const {
    return 0.5 * (V[n_ + 1] - V[n_]).cross(V[n_ + 2] - V[n_]).norm();
}

int T1::corner_of(int film) const {
    for (int i = 0; i < 3; ++i)
        if (films_[i] == film) return n_ + i;
    return -1;
}

/// In the line's films the line's vertices become the film's corner; facets with two or more
/// corners on the line go.
void T1::collapse_line_films(ClusterSpec& spec) {
    for (int i = 0; i < 3; ++i)
        surgery::collapse_onto(c_, spec, films_[i], d_, n_ + i, moved_, name_);
}

/// Each film of the fourth cell at this end: its fan at the end vertex from the triple line
/// towards film X to the one towards film Y splits between X's corner and Y's
/// (surgery::split_fan).
void T1::split_fans(ClusterSpec& spec, const LineEnd& end) {
    const int v = end.vertex;
    for (int si : end.films) {
        // the films of the line at the fan's two ends: on the junction edges (v, u_0), (v, u_n)
        const auto film_towards = [&](int w) {
            for (int e : c_.vertex_junction_edges(v)) {
                const JunctionEdge& je = c_.junction_edges()[e];
                if (je.a != w && je.b != w) continue;
                for (int film : je.surfaces)
                    if (corner_of(film) >= 0) return corner_of(film);
            }
            throw TopologyError(name_ + ": surface " + std::to_string(si + 1) + " does not end "
                                "on the line's films at vertex " + std::to_string(v + 1));
        };
        surgery::split_fan(c_, spec, si, v, d_.at(v), film_towards, moved_, name_);
    }
}

/// Where the fourth cells are one, D (a cell that wraps around the line), no film D|D forms:
/// A, B and C part and D's two sides meet through the gap. The film D|X at b joins D|X at a
/// (X = A, B, C; the one at b goes, unless it is the same film), so each new corner's edges
/// are inner edges of one film and the corner a point of the line (A, B, D) joined from both
/// ends (and so on): the two quadruple points go. The surfaces that go, sorted.
std::vector<int> T1::join_films_across(ClusterSpec& spec) const {
    std::vector<int> removed;
    for (int at_a : a_.films) {
        const int x = cells_[at_a][0] == a_.cell ? cells_[at_a][1] : cells_[at_a][0];
        for (int at_b : b_.films) {
            const auto& cb = cells_[at_b];
            if (at_b == at_a || !(cb[0] == x || cb[1] == x)) continue;
            surgery::join_films(c_, spec, at_a, at_b, x >= 0 ? x : a_.cell);
            removed.push_back(at_b);
        }
    }
    std::sort(removed.begin(), removed.end());
    if (std::adjacent_find(removed.begin(), removed.end()) != removed.end())
        throw TopologyError(name_ + ": the films of the cell that meets itself across it do not "
                            "pair up");
    return removed;
}

Cluster T1::run(TransitionRecord* record) {
    check_line();
    a_ = end_at(seg_.front());
    b_ = end_at(seg_.back());
    const bool self = a_.cell == b_.cell; // the cell meets itself across the line
    if (self && !meets_itself_)
        throw TopologyError(name_ + ": the same cell (" + surgery::cell_name(a_.cell) +
                            ") meets both its ends; it may meet itself across the line only "
                            "when forced");
    unwrap_line();
    n_ = c_.n_vertices();

    ClusterSpec spec = cluster_spec(c_);
    collapse_line_films(spec);
    split_fans(spec, a_);
    split_fans(spec, b_);
    const int new_film = static_cast<int>(spec.surfaces.size());
    std::vector<int> removed; // self: the films of D at b that joined those at a
    if (self) {
        removed = join_films_across(spec);
    } else {
        ClusterSpec::Surface film;
        film.triangles.push_back({n_, n_ + 1, n_ + 2});
        film.sigma = c_.surface(a_.films.front()).sigma;
        if (spec.period) film.offsets.push_back({});
        spec.surfaces.push_back(std::move(film));
        for (int cell : {a_.cell, b_.cell})
            if (cell >= 0) spec.bodies[cell].push_back(new_film);
    }

    std::vector<Vec3> V = place_film(spec);
    surgery::remove_surfaces(spec, removed);
    const std::vector<int> used = surgery::keep_used_vertices(spec, V);
    surgery::copy_vertex_lists(c_, [&](int v) { return used[v]; }, spec);
    Cluster r = surgery::rebuild(std::move(spec), name_, "the T1");
    for (int i = 0; i < 3; ++i)
        if (r.vertex_junction_edges(used[n_ + i]).size() != (self ? 2u : 4u))
            throw TopologyError(name_ + ": the new corner " + std::to_string(i + 1) + " is not " +
                                (self ? "a point of one triple line" : "a quadruple point") +
                                "; refine the mesh around the line first");
    surgery::carry_over_without_surfaces(c_, removed, r);
    if (!self) {
        r.set_anisotropy(new_film, c_.surface(a_.films.front()).gamma);
        r.set_mobility(new_film, c_.surface(a_.films.front()).beta);
    }

    if (record) {
        const Vec3 mid = 0.5 * (u_[seg_.front()] + u_[seg_.back()]);
        record->kind = "T1";
        record->fitted = fitted_;
        record->size = side_;
        record->line = shown_;
        record->cells = {a_.cell, b_.cell};
        record->point = mid;
        record->removed_vertices = static_cast<int>(seg_.size());
        // a gap facet per fan, and the film
        record->removed_facets = c_.n_facets() + (self ? 6 : 7) - r.n_facets();
        record->where =
            "triple line " + std::to_string(shown_ + 1) + " (length " + fmt(length_) +
            ", vertices " + std::to_string(seg_.front() + 1) + " .. " +
            std::to_string(seg_.back() + 1) + ") became " +
            (self ? "a gap of side " + fmt(side_) + " through which " +
                        surgery::cell_name(a_.cell) + " meets itself"
                  : "a film of side " + fmt(side_) + " between " + surgery::cell_name(a_.cell) +
                        " and " + surgery::cell_name(b_.cell)) +
            " at " + point_text(mid);
    }
    return r;
}

/// The T1 of c's line `line` made on `split`, c with some edges split (vertex ids kept), where
/// the line is found again by its vertices; on c itself without.
Cluster t1_after_splits(const Cluster& c, int line, const std::optional<Cluster>& split,
                        TransitionRecord* record, double min_side, double smallest_side,
                        bool fit_corners, bool meets_itself) {
    if (split) {
        const std::vector<int>& vertices = c.triple_lines()[line].vertices;
        const auto& lines = split->triple_lines();
        for (std::size_t l = 0; l < lines.size(); ++l) {
            const std::vector<int>& w = lines[l].vertices;
            if (w != vertices && !std::equal(vertices.rbegin(), vertices.rend(), w.begin(), w.end()))
                continue;
            return T1(*split, static_cast<int>(l), min_side, smallest_side, fit_corners,
                      meets_itself, line)
                .run(record);
        }
    }
    return T1(c, line, min_side, smallest_side, fit_corners, meets_itself).run(record);
}

} // namespace

Cluster t1_line_to_film(const Cluster& c, int line, TransitionRecord* record, double min_side,
                        double smallest_side, bool fit_corners, bool meets_itself) {
    if (line < 0 || line >= static_cast<int>(c.triple_lines().size()))
        throw InvalidInput("t1: triple line " + std::to_string(line + 1) + " does not exist (the "
                           "cluster has " + std::to_string(c.triple_lines().size()) + ")");
    // a triangular film of one facet beside the line would be left without a facet: its
    // other sides are split first, and it becomes a lens of two facets
    const auto t1_after = [&](const std::optional<Cluster>& split) {
        return t1_after_splits(c, line, split, record, min_side, smallest_side, fit_corners,
                               meets_itself);
    };
    const std::optional<Cluster> split = split_films_emptied_by_t1(c, line);
    try {
        return t1_after(split);
    } catch (const TopologyError& refused) {
        // a vertex joined to both ends through the fourth cells' films can make an edge of
        // four films (the 200-grain network's stop at t = 0.970): those edges are split and
        // the T1 tried again, only where it failed and only with fitted corners (evolve, by
        // hand): minimize, which fits none, went 100 -> 84 iterations on a 27-cell foam with
        // the T1s it then made
        if (!fit_corners) throw;
        std::optional<Cluster> parted = split_films_emptied_by_t1(c, line, true);
        // (no common neighbour: the same splits, the same refusal)
        const int before = split ? split->n_vertices() : c.n_vertices();
        if (!parted || parted->n_vertices() == before) throw;
        try {
            return t1_after(parted);
        } catch (const TopologyError&) {
            throw refused;
        }
    }
}

} // namespace froth
