// The pinch of a film between two of its triple lines (transitions.h, pinch_film): where two
// lines on a film's border approach each other across it, the cells beyond them meet.
//
// Before: film F between cells A and B; on its border the line (A, B, C) through vertex u and
// the line (A, B, D) through w, C != D, and the edge (u, w) inside F. Cut across the edge, F
// is a 2D T1's shrinking edge: in the plane normal to the lines, its segment between the two
// lines shrinks and a segment C|D takes its place. After: u and w become two quadruple points
// p (on the side of the lines' first neighbours) and q (the other side); F loses its two
// facets at the edge and parts into a film at p and one at q (or stays one film, if it is
// joined elsewhere). The films A|C and B|C at u split their fans between p and q (as a T1's
// films do at its ends), so do A|D and B|D at w, and the lens C|D with corners p, q and r fills
// the gap: its border is the line (A, C, D) along the edge p q and the line (B, C, D) through r.
// This is collapse_two_sided_film backwards: that collapse leaves its two points joined by
// such an edge across the film it joins.
#include "mesh/transitions.h"

#include "core/errors.h"
#include "core/format.h"
#include "mesh/transition_surgery.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <tuple>

namespace froth {
namespace {

int index_of(const Tri& t, int v) {
    return static_cast<int>(std::find(t.begin(), t.end(), v) - t.begin());
}

/// Where x is in a fan's link (its size if nowhere).
int position_in(const surgery::BorderFan& fan, int x) {
    return static_cast<int>(std::find(fan.link.begin(), fan.link.end(), x) - fan.link.begin());
}

class FilmPinch {
  public:
    FilmPinch(const Cluster& c, int u, int w, double min_side, bool fit)
        : c_(c), u_(u), w_(w), min_side_(min_side), fit_(fit),
          name_("pinch_film: edge " + std::to_string(u + 1) + "-" + std::to_string(w + 1)),
          cells_(surface_cells(c)) {}

    Cluster run(TransitionRecord* record);

  private:
    void find_films();
    void split_sides();
    int line_of(int v) const;
    Vec3 unwrapped_neighbour(int v, const Vec3& at_v, int x) const;
    void rewrite_film(ClusterSpec& spec);
    int part_film(ClusterSpec& spec);
    void split_fans(ClusterSpec& spec);
    void add_lens(ClusterSpec& spec);
    Vec3 fan_centre(bool p_side) const;
    void place_corners(double side, std::vector<Vec3>& V) const;
    std::vector<Vec3> place_lens(const ClusterSpec& spec);

    const Cluster& c_;
    const int u_, w_;
    const double min_side_;
    const bool fit_;
    const std::string name_;
    const std::vector<std::array<int, 2>> cells_;
    int film_ = -1; // F
    int A_ = -1, B_ = -1, C_ = -1, D_ = -1;
    std::array<int, 2> at_u_{}; // the films A|C and B|C
    std::array<int, 2> at_w_{}; // A|D and B|D
    std::set<int> p_facets_;    // F's facets at u or w that take p (the others at them, q)
    std::set<int> bridge_;      // F's two facets at the edge
    int u1_ = -1, u2_ = -1, w1_ = -1, w2_ = -1; // the lines' neighbours of u, w on p's side, q's
    Offset dw_{};                               // w's lattice offset in u's frame
    Vec3 xw_ = Vec3::Zero();                    // w unwrapped in u's frame
    std::vector<surgery::MovedFacet> moved_;
    int n_ = 0; // c's vertex count: p, q, r are n_, n_ + 1, n_ + 2
    double side_ = 0;
    bool fitted_ = false;
};

/// F and the films at u and w with their cells; throws where the edge is not a pinch of a film
/// between two lines of different third cells.
void FilmPinch::find_films() {
    const std::vector<int> rank = surgery::vertex_ranks(c_);
    for (int v : {u_, w_})
        if (rank[v] != 1)
            throw TopologyError(name_ + ": vertex " + std::to_string(v + 1) +
                                " is not a free point of a triple line (a quadruple point, "
                                "inside a film, fixed or on a wall)");
    const std::set<int> su = surgery::surfaces_at(c_, u_), sw = surgery::surfaces_at(c_, w_);
    std::vector<int> common;
    std::set_intersection(su.begin(), su.end(), sw.begin(), sw.end(), std::back_inserter(common));
    if (common.size() != 1)
        throw TopologyError(name_ + ": its ends share " + std::to_string(common.size()) +
                            " films, not one (they must lie on two triple lines of one film)");
    film_ = common.front();
    A_ = cells_[film_][0], B_ = cells_[film_][1];
    if (A_ == B_)
        throw TopologyError(name_ + ": surface " + std::to_string(film_ + 1) +
                            " lies between a cell and itself");
    // the cell beyond the line through v: its films other than F are one of A and one of B
    const auto third = [&](const std::set<int>& films, std::array<int, 2>& sorted) {
        std::set<int> beyond;
        std::array<int, 2> of{0, 0}; // films of A, of B
        for (int s : films) {
            if (s == film_) continue;
            const auto& k = cells_[s];
            const bool a = k[0] == A_ || k[1] == A_, b = k[0] == B_ || k[1] == B_;
            if (a == b) return -2; // not a film of A or B alone
            sorted[a ? 0 : 1] = s, ++of[a ? 0 : 1];
            beyond.insert(k[0] == (a ? A_ : B_) ? k[1] : k[0]);
        }
        return of[0] == 1 && of[1] == 1 && beyond.size() == 1 ? *beyond.begin() : -2;
    };
    C_ = third(su, at_u_), D_ = third(sw, at_w_);
    if (C_ == -2 || D_ == -2 || C_ == A_ || C_ == B_ || D_ == A_ || D_ == B_)
        throw TopologyError(name_ +
                            ": the films at its ends are not those of two triple lines "
                            "along surface " +
                            std::to_string(film_ + 1));
    if (C_ == D_)
        throw TopologyError(name_ + ": the same cell (" + surgery::cell_name(C_) +
                            ") lies beyond both "
                            "lines; it would meet itself across surface " +
                            std::to_string(film_ + 1));
}

/// Which of F's facets at u and w take p: at u those before the edge in its fan (the edge's
/// facet (u, x, w) last), at w those after it (the same facet is (w, u, x) there, first).
void FilmPinch::split_sides() {
    const auto& triangles = c_.surface(film_).triangles;
    const surgery::BorderFan at_u = surgery::border_fan(triangles, u_, name_, film_);
    const surgery::BorderFan at_w = surgery::border_fan(triangles, w_, name_, film_);
    const int iw = position_in(at_u, w_), iu = position_in(at_w, u_);
    const int nu = static_cast<int>(at_u.facets.size()), nw = static_cast<int>(at_w.facets.size());
    if (iw <= 0 || iw >= nu || iu <= 0 || iu >= nw)
        throw TopologyError(name_ + ": the edge lies on the border of surface " +
                            std::to_string(film_ + 1) + ", not across it");
    bridge_ = {at_u.facets[iw - 1], at_u.facets[iw]};
    for (int j = 0; j < iw - 1; ++j)
        p_facets_.insert(at_u.facets[j]);
    for (int j = iu + 1; j < nw; ++j)
        p_facets_.insert(at_w.facets[j]);
    // each corner keeps a fan of F, or F would lose its border there
    if (p_facets_.empty() || (iw + 1 >= nu && iu - 1 <= 0))
        throw TopologyError(name_ + ": surface " + std::to_string(film_ + 1) +
                            " has no facet "
                            "beside the edge on one side; refine the mesh there first");
    u1_ = at_u.link.front(), u2_ = at_u.link.back();
    w1_ = at_w.link.back(), w2_ = at_w.link.front();
}

/// The triple line through v (a free point of one line), or -1.
int FilmPinch::line_of(int v) const {
    const auto& lines = c_.triple_lines();
    for (std::size_t l = 0; l < lines.size(); ++l)
        if (std::find(lines[l].vertices.begin(), lines[l].vertices.end(), v) !=
            lines[l].vertices.end())
            return static_cast<int>(l);
    return -1;
}

/// Vertex x, a neighbour of v, unwrapped next to v's position at_v.
Vec3 FilmPinch::unwrapped_neighbour(int v, const Vec3& at_v, int x) const {
    return at_v + (c_.position(x) - c_.position(v) + c_.edge_shift(v, x));
}

/// F without its two facets at the edge; its facets at u and w take p or q (offsets in u's
/// frame).
void FilmPinch::rewrite_film(ClusterSpec& spec) {
    const Surface& old = c_.surface(film_);
    ClusterSpec::Surface& s = spec.surfaces[film_];
    ClusterSpec::Surface out;
    out.sigma = s.sigma;
    for (std::size_t f = 0; f < old.triangles.size(); ++f) {
        if (bridge_.count(static_cast<int>(f))) continue;
        Tri t = s.triangles[f];
        std::array<Offset, 3> k{};
        if (!s.offsets.empty()) k = s.offsets[f];
        const int corner = p_facets_.count(static_cast<int>(f)) ? n_ : n_ + 1;
        bool moved = false;
        for (int j = 0; j < 3; ++j) {
            if (t[j] != u_ && t[j] != w_) continue;
            if (t[j] == w_)
                for (int x = 0; x < 3; ++x)
                    k[j][x] -= dw_[x];
            t[j] = corner, moved = true;
        }
        if (moved)
            moved_.push_back(
                {film_, static_cast<int>(out.triangles.size()), surgery::facet_area(c_, film_, f)});
        out.triangles.push_back(t);
        if (spec.period) out.offsets.push_back(k);
    }
    s = std::move(out);
}

/// F's facets joined across edges (the lattice shift counted in a periodic cluster): where
/// those at q are no longer joined to those at p, they become a new surface (its id, else -1)
/// between the same cells, with F's tension.
int FilmPinch::part_film(ClusterSpec& spec) {
    ClusterSpec::Surface& s = spec.surfaces[film_];
    const std::size_t n = s.triangles.size();
    std::vector<int> parent(n);
    for (std::size_t f = 0; f < n; ++f)
        parent[f] = static_cast<int>(f);
    const auto find = [&](int f) {
        while (parent[f] != f)
            f = parent[f] = parent[parent[f]];
        return f;
    };
    std::map<std::tuple<int, int, int, int, int>, int> first_at; // (lo, hi, offset hi - lo)
    for (std::size_t f = 0; f < n; ++f)
        for (int j = 0; j < 3; ++j) {
            int a = j, b = (j + 1) % 3;
            if (s.triangles[f][a] > s.triangles[f][b]) std::swap(a, b);
            Offset d{};
            if (!s.offsets.empty())
                for (int x = 0; x < 3; ++x)
                    d[x] = s.offsets[f][b][x] - s.offsets[f][a][x];
            const auto key =
                std::make_tuple(s.triangles[f][a], s.triangles[f][b], d[0], d[1], d[2]);
            const auto [it, fresh] = first_at.emplace(key, static_cast<int>(f));
            if (!fresh) parent[find(static_cast<int>(f))] = find(it->second);
        }
    int at_p = -1, at_q = -1;
    for (std::size_t f = 0; f < n; ++f) {
        const Tri& t = s.triangles[f];
        if (index_of(t, n_) < 3) at_p = find(static_cast<int>(f));
        if (index_of(t, n_ + 1) < 3) at_q = find(static_cast<int>(f));
    }
    if (at_p < 0 || at_q < 0)
        throw TopologyError(name_ + ": surface " + std::to_string(film_ + 1) +
                            " keeps no facet at one of the new corners");
    if (at_p == at_q) return -1;
    const int id = static_cast<int>(spec.surfaces.size());
    ClusterSpec::Surface keep, part;
    keep.sigma = part.sigma = s.sigma;
    std::vector<std::pair<int, int>> now(n); // each facet's surface and index after the parting
    for (std::size_t f = 0; f < n; ++f) {
        const bool q_side = find(static_cast<int>(f)) == at_q;
        ClusterSpec::Surface& to = q_side ? part : keep;
        now[f] = {q_side ? id : film_, static_cast<int>(to.triangles.size())};
        to.triangles.push_back(s.triangles[f]);
        if (!s.offsets.empty()) to.offsets.push_back(s.offsets[f]);
    }
    for (surgery::MovedFacet& m : moved_)
        if (m.surface == film_) std::tie(m.surface, m.facet) = now[m.facet];
    s = std::move(keep);
    spec.surfaces.push_back(std::move(part));
    for (int cell : {A_, B_})
        if (cell >= 0) spec.bodies[cell].push_back(id);
    return id;
}

/// The films of C at u and of D at w: each fan splits between p (towards the lines' first
/// neighbours) and q, with a gap facet whose edge q p is the line (A, C, D) or, in the films of
/// B, the line (B, C, D) once r splits it (add_lens).
void FilmPinch::split_fans(ClusterSpec& spec) {
    const auto towards = [&](int first, int second) {
        return [this, first, second](int x) {
            if (x == first) return n_;
            if (x == second) return n_ + 1;
            throw TopologyError(name_ + ": a film at its ends does not end on the lines there");
        };
    };
    for (int s : at_u_)
        surgery::split_fan(c_, spec, s, u_, Offset{}, towards(u1_, u2_), moved_, name_);
    for (int s : at_w_)
        surgery::split_fan(c_, spec, s, w_, dw_, towards(w1_, w2_), moved_, name_);
}

/// r on the gap edge of B's films, and the lens (p, q, r) between C and D with the tension,
/// anisotropy and mobility of A|C (set after the rebuild).
void FilmPinch::add_lens(ClusterSpec& spec) {
    const int p = n_, q = n_ + 1, r = n_ + 2;
    for (int s : {at_u_[1], at_w_[1]}) {
        ClusterSpec::Surface& film = spec.surfaces[s];
        const Tri gap = film.triangles.back(); // (p or q, u_m, the other)
        film.triangles.back() = {gap[0], gap[1], r};
        film.triangles.push_back({gap[1], gap[2], r});
        if (!film.offsets.empty()) {
            std::array<Offset, 3> k = film.offsets.back();
            film.offsets.back() = {k[0], k[1], k[0]};
            film.offsets.push_back({k[1], k[2], k[0]});
        }
    }
    ClusterSpec::Surface lens;
    lens.triangles.push_back({p, q, r});
    lens.sigma = c_.surface(at_u_[0]).sigma;
    if (spec.period) lens.offsets.push_back({});
    const int id = static_cast<int>(spec.surfaces.size());
    spec.surfaces.push_back(std::move(lens));
    for (int cell : {C_, D_})
        if (cell >= 0) spec.bodies[cell].push_back(id);
}

/// The mean of the other corners of F's facets at u and w that take p (`p_side`) or q, in
/// u's frame: where the film goes on beyond each new corner.
Vec3 FilmPinch::fan_centre(bool p_side) const {
    const Surface& s = c_.surface(film_);
    Vec3 sum = Vec3::Zero();
    int count = 0;
    for (std::size_t f = 0; f < s.triangles.size(); ++f) {
        const int id = static_cast<int>(f);
        if (bridge_.count(id) || p_facets_.count(id) != static_cast<std::size_t>(p_side)) continue;
        const Tri& t = s.triangles[f];
        const int k = index_of(t, u_) < 3 ? index_of(t, u_) : index_of(t, w_);
        if (k == 3) continue;
        const auto x = s.corners(c_.positions(), f);
        const Vec3 base = t[k] == u_ ? c_.position(u_) : xw_;
        sum += (x[(k + 1) % 3] - x[k]) + (x[(k + 2) % 3] - x[k]) + 2 * base;
        count += 2;
    }
    return sum / count;
}

/// p and q side apart about the edge's midpoint, towards the film's parts beyond them (normal
/// to the edge), a quarter side towards A, and r a quarter side towards B: the lens stands
/// across the edge, normal to it.
void FilmPinch::place_corners(double side, std::vector<Vec3>& V) const {
    const Vec3 xu = c_.position(u_);
    const Vec3 mid = 0.5 * (xu + xw_);
    Vec3 across = xw_ - xu;
    across = across.norm() > 0 ? Vec3(across.normalized()) : Vec3::Zero();
    Vec3 along = fan_centre(true) - fan_centre(false);
    along -= along.dot(across) * across;
    along.normalize();
    // towards B: the side of F the film B|C leaves the line on
    Vec3 to_b = across.cross(along);
    Vec3 b_side = Vec3::Zero();
    const Surface& bc = c_.surface(at_u_[1]);
    for (std::size_t f = 0; f < bc.triangles.size(); ++f) {
        const auto x = bc.corners(c_.positions(), f);
        const int k = index_of(bc.triangles[f], u_);
        if (k < 3) b_side += x[(k + 1) % 3] + x[(k + 2) % 3] - 2 * x[k];
    }
    if (b_side.dot(to_b) < 0) to_b = -to_b;
    V[n_] = mid + 0.5 * side * along - 0.25 * side * to_b;
    V[n_ + 1] = mid - 0.5 * side * along - 0.25 * side * to_b;
    V[n_ + 2] = mid + 0.25 * side * to_b;
}

/// The positions after the pinch: c's and the lens's corners at the largest side from the
/// first down, halving (at most ten times), at which no facet turns over, the corners moved
/// off slivers where needed (surgery::fit_corners) so long as the lens keeps half its area.
std::vector<Vec3> FilmPinch::place_lens(const ClusterSpec& spec) {
    const double first =
        std::max(min_side_, 0.5 * (surgery::mean_edge_at(c_, u_) + surgery::mean_edge_at(c_, w_)));
    std::vector<Vec3> V = c_.positions();
    V.resize(n_ + 3);
    const auto area = [&](const std::vector<Vec3>& X) {
        return 0.5 * (X[n_ + 1] - X[n_]).cross(X[n_ + 2] - X[n_]).norm();
    };
    int turned = -1;
    double side = first;
    for (int halvings = 0; halvings <= 10; ++halvings, side *= 0.5) {
        place_corners(side, V);
        const double nominal = area(V);
        if (!surgery::turns_a_facet(spec, V, moved_, &turned)) {
            side_ = side;
            return V;
        }
        if (fit_ && surgery::fit_corners(spec, V, moved_, {n_, n_ + 1, n_ + 2}, side) &&
            area(V) >= 0.5 * nominal) {
            side_ = side, fitted_ = true;
            return V;
        }
    }
    throw TopologyError(name_ + ": the pinch would turn a facet of surface " +
                        std::to_string(turned + 1) + " over at every size of the lens down to " +
                        fmt(side) + "; refine the mesh there first");
}

Cluster FilmPinch::run(TransitionRecord* record) {
    find_films();
    split_sides();
    xw_ = unwrapped_neighbour(u_, c_.position(u_), w_);
    dw_ = surgery::lattice_offset(c_, xw_, c_.position(w_));
    n_ = c_.n_vertices();
    const int line_u = line_of(u_), line_w = line_of(w_);

    ClusterSpec spec = cluster_spec(c_);
    rewrite_film(spec);
    const int parted = part_film(spec);
    split_fans(spec);
    add_lens(spec);
    const int lens = static_cast<int>(spec.surfaces.size()) - 1;
    std::vector<Vec3> V = place_lens(spec);

    const std::vector<int> used = surgery::keep_used_vertices(spec, V);
    surgery::copy_vertex_lists(
        c_, [&](int v) { return used[v]; }, spec);
    Cluster r = surgery::rebuild(std::move(spec), name_, "the pinch");
    for (int i = 0; i < 3; ++i)
        if (r.vertex_junction_edges(used[n_ + i]).size() != (i < 2 ? 4u : 2u))
            throw TopologyError(name_ + ": the new corner " + std::to_string(i + 1) + " is not " +
                                (i < 2 ? "a quadruple point" : "a point of one triple line") +
                                "; refine the mesh around the edge first");
    surgery::carry_over_without_surfaces(c_, {}, r);
    if (parted >= 0) {
        r.set_anisotropy(parted, c_.surface(film_).gamma);
        r.set_mobility(parted, c_.surface(film_).beta);
    }
    r.set_anisotropy(lens, c_.surface(at_u_[0]).gamma);
    r.set_mobility(lens, c_.surface(at_u_[0]).beta);

    if (record) {
        const Vec3 mid = 0.5 * (c_.position(u_) + xw_);
        record->kind = "film pinch";
        record->fitted = fitted_;
        record->size = side_;
        record->film = film_;
        record->cells = {C_, D_};
        record->point = mid;
        record->removed_vertices = 2;
        record->removed_facets = 2; // F's at the edge
        record->where = "surface " + std::to_string(film_ + 1) + " between " +
                        surgery::cell_name(A_) + " and " + surgery::cell_name(B_) +
                        ", pinched between triple lines " + std::to_string(line_u + 1) + " and " +
                        std::to_string(line_w + 1) + " (edge " + std::to_string(u_ + 1) + "-" +
                        std::to_string(w_ + 1) + ", length " + fmt((xw_ - c_.position(u_)).norm()) +
                        "), parted " + (parted >= 0 ? "in two" : "but stays one film") +
                        "; a two-sided film of side " + fmt(side_) + " between " +
                        surgery::cell_name(C_) + " and " + surgery::cell_name(D_) + " at " +
                        point_text(mid);
    }
    return r;
}

/// c with the edges that join u or w, inside the one film they share, to another point of a
/// line (not the edge (u, w), nor the lines' own edges) split at their midpoints, or c itself
/// if there are none: where the film is a facet or two wide, such an edge would join a new
/// corner to a line across the film's part and make an edge of four films (the 200-grain
/// network at t = 1.3255: u joined to w's neighbour on w's line).
Cluster part_fans_from_lines(const Cluster& c, int u, int w) {
    const std::set<int> su = surgery::surfaces_at(c, u), sw = surgery::surfaces_at(c, w);
    std::vector<int> common;
    std::set_intersection(su.begin(), su.end(), sw.begin(), sw.end(), std::back_inserter(common));
    if (common.size() != 1) return c; // FilmPinch says why
    const std::vector<int> rank = surgery::vertex_ranks(c);
    const auto on_line = [&](int v, int x) { // x a neighbour of v along v's line
        for (int e : c.vertex_junction_edges(v)) {
            const JunctionEdge& je = c.junction_edges()[e];
            if (je.a == x || je.b == x) return true;
        }
        return false;
    };
    std::set<std::array<int, 2>> split;
    const Surface& film = c.surface(common.front());
    for (const Tri& t : film.triangles)
        for (int v : {u, w}) {
            const int k = index_of(t, v);
            if (k == 3) continue;
            for (int x : {t[(k + 1) % 3], t[(k + 2) % 3]})
                if (x != u && x != w && rank[x] != 0 && !on_line(v, x))
                    split.insert({std::min(v, x), std::max(v, x)});
        }
    Cluster out = c;
    for (const auto& [a, b] : split)
        out = surgery::split_edge(out, a, b, 0.5);
    return out;
}

} // namespace

Cluster pinch_film(const Cluster& c, int u, int w, TransitionRecord* record, double min_side,
                   bool fit_corners) {
    for (int v : {u, w})
        if (v < 0 || v >= c.n_vertices())
            throw InvalidInput("pinch_film: vertex " + std::to_string(v + 1) +
                               " does not exist (the "
                               "cluster has " +
                               std::to_string(c.n_vertices()) + ")");
    if (u == w) throw InvalidInput("pinch_film: the edge's two vertices are the same");
    const Cluster parted = part_fans_from_lines(c, u, w);
    return FilmPinch(parted, u, w, min_side, fit_corners).run(record);
}

} // namespace froth

namespace froth {

std::vector<FilmWaist> film_waists(const Cluster& c, double shorter_than) {
    const std::vector<int> rank = surgery::vertex_ranks(c);
    std::vector<int> line(c.n_vertices(), -1);
    const auto& lines = c.triple_lines();
    for (std::size_t l = 0; l < lines.size(); ++l)
        for (int v : lines[l].vertices)
            if (rank[v] == 1) line[v] = static_cast<int>(l);
    std::vector<std::vector<int>> along(c.n_vertices()); // neighbours along the lines
    for (const JunctionEdge& e : c.junction_edges())
        along[e.a].push_back(e.b), along[e.b].push_back(e.a);
    // within three edges along the lines: a film's corner, which zip_slit's upkeep narrows
    const auto near_along = [&](int a, int b) {
        std::set<int> reached{a};
        std::vector<int> front{a};
        for (int hop = 0; hop < 3; ++hop) {
            std::vector<int> next;
            for (int v : front)
                for (int x : along[v])
                    if (reached.insert(x).second) next.push_back(x);
            front = std::move(next);
        }
        return reached.count(b) > 0;
    };
    std::map<std::array<int, 2>, FilmWaist> found;
    for (int si = 0; si < c.n_surfaces(); ++si) {
        const Surface& s = c.surface(si);
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const Tri& t = s.triangles[f];
            const auto x = s.corners(c.positions(), f);
            for (int j = 0; j < 3; ++j) {
                const int a = t[j], b = t[(j + 1) % 3];
                if (line[a] < 0 || line[b] < 0 || line[a] == line[b]) continue;
                const double length = (x[(j + 1) % 3] - x[j]).norm();
                if (length < shorter_than)
                    found.emplace(std::array<int, 2>{std::min(a, b), std::max(a, b)},
                                  FilmWaist{std::min(a, b), std::max(a, b), si, {}, length});
            }
        }
    }
    const std::vector<std::array<int, 2>> sides = surface_cells(c);
    // the cell beyond v's line: on v's films but not on `film`
    const auto beyond = [&](int v, int film) {
        for (int s : surgery::surfaces_at(c, v))
            for (int k : sides[s])
                if (k != sides[film][0] && k != sides[film][1]) return k;
        return -1;
    };
    std::vector<FilmWaist> out;
    for (auto& [edge, waist] : found) {
        if (near_along(edge[0], edge[1])) continue;
        std::array<int, 2> film{sides[waist.film][0], sides[waist.film][1]};
        std::array<int, 2> lines_beyond{beyond(waist.u, waist.film), beyond(waist.w, waist.film)};
        std::sort(film.begin(), film.end());
        std::sort(lines_beyond.begin(), lines_beyond.end());
        waist.cells = {film[0], film[1], lines_beyond[0], lines_beyond[1]};
        out.push_back(waist);
    }
    std::sort(out.begin(), out.end(),
              [](const FilmWaist& x, const FilmWaist& y) { return x.length < y.length; });
    return out;
}

} // namespace froth
