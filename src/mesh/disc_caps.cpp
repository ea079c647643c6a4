// A disc film closed by caps (transitions.h, collapse_disc_film, where the collapse of its loop
// to two points would turn a facet over).
//
// Before: the film F between cells D and E is a disc bounded by one closed triple line l
// (vertices l_0 .. l_{n-1}), along which the films D|X and E|X meet it. After: F goes; D|X
// keeps l's vertices and closes over the hole with a fan of new facets (l_i, l_{i+1}) -> a; in
// E|X the loop's vertices are replaced by copies l_i' moved eps towards E, and it closes with a
// fan to b. a and b lie on the normal through the loop's centre, a towards D and b towards E,
// delta from it. So D|X and E|X part along the loop by eps, X fills the gap between the caps,
// and D and E no longer touch there. Unlike the collapse of the loop (t1_inverse.cpp), nothing
// moves farther than eps, so no facet beside the loop turns over however coarse the films
// around a small disc are; the caps add about twice the disc's area, which the flow takes
// back as X closes in.
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

class DiscCaps {
  public:
    DiscCaps(const Cluster& c, int film)
        : c_(c), film_(film), name_("collapse_disc_film: surface " + std::to_string(film + 1)),
          cells_(surface_cells(c)) {}

    Cluster run(TransitionRecord* record);

  private:
    void find_loop();
    void unwrap_loop();
    void cap(ClusterSpec& spec, int si, int apex, bool copies);
    std::vector<Vec3> place(const ClusterSpec& spec);

    const Cluster& c_;
    const int film_;
    const std::string name_;
    const std::vector<std::array<int, 2>> cells_;
    int d_ = -1, e_ = -1, x_ = -1;      // the cells D, E, X
    int line_ = -1, film_d_ = -1, film_e_ = -1;
    std::vector<int> loop_;             // l's vertices in order
    std::map<int, Offset> offset_;      // their lattice offsets in l_0's frame
    std::map<int, int> copy_;           // l_i -> l_i' (E|X's)
    Vec3 centre_ = Vec3::Zero(), into_d_ = Vec3::Zero();
    double radius_ = 0, perimeter_ = 0;
    int n_ = 0;                         // c's vertex count: a, b, then the copies
    std::vector<surgery::MovedFacet> moved_; // E|X's facets at a copy
};

void DiscCaps::find_loop() {
    d_ = cells_[film_][0], e_ = cells_[film_][1];
    if (d_ == e_)
        throw TopologyError(name_ + " lies between a cell and itself; only a film between two "
                            "cells can collapse");
    const auto& lines = c_.triple_lines();
    for (int l = 0; l < static_cast<int>(lines.size()); ++l) {
        const auto& s = lines[l].surfaces;
        if (std::find(s.begin(), s.end(), film_) == s.end()) continue;
        if (line_ >= 0 || !lines[l].closed)
            throw TopologyError(name_ + " is not a disc bounded by one closed triple line");
        line_ = l;
    }
    if (line_ < 0) throw TopologyError(name_ + " is not bounded by a triple line");
    std::set<int> third;
    for (int s : lines[line_].surfaces) {
        if (s == film_) continue;
        const auto& k = cells_[s];
        const bool has_d = k[0] == d_ || k[1] == d_, has_e = k[0] == e_ || k[1] == e_;
        if (has_d == has_e) continue;
        (has_d ? film_d_ : film_e_) = s;
        third.insert(k[0] == (has_d ? d_ : e_) ? k[1] : k[0]);
    }
    if (film_d_ < 0 || film_e_ < 0 || third.size() != 1 || *third.begin() == d_ ||
        *third.begin() == e_)
        throw TopologyError(name_ + ": its border does not join it to the films of one third "
                            "cell with each of its two");
    x_ = *third.begin();
    loop_ = lines[line_].vertices;
    for (int v : loop_)
        if (c_.is_fixed(v) || c_.curve_point(v) || !c_.vertex_walls(v).empty())
            throw TopologyError(name_ + " has a fixed vertex or one on a wall (" +
                                std::to_string(v + 1) + "); it cannot change");
}

/// The loop in l_0's frame, its centre, length and the unit normal into D.
void DiscCaps::unwrap_loop() {
    std::vector<Vec3> u{c_.position(loop_[0])};
    for (std::size_t i = 1; i < loop_.size(); ++i)
        u.push_back(u.back() + c_.position(loop_[i]) - c_.position(loop_[i - 1]) +
                    c_.edge_shift(loop_[i - 1], loop_[i]));
    for (std::size_t i = 0; i < loop_.size(); ++i) {
        offset_[loop_[i]] = surgery::lattice_offset(c_, u[i], c_.position(loop_[i]));
        centre_ += u[i] / static_cast<double>(u.size());
    }
    Vec3 area = Vec3::Zero(); // along the loop's order
    for (std::size_t i = 0; i < u.size(); ++i) {
        const Vec3& p = u[i];
        const Vec3& q = u[(i + 1) % u.size()];
        area += 0.5 * (p - centre_).cross(q - centre_);
        perimeter_ += (q - p).norm();
    }
    if (!(area.norm() > 0)) throw TopologyError(name_ + ": its border encloses no area");
    // F runs along the loop's order or against it: the facet at l_0 -> l_1 says which
    int along = 0;
    for (const Tri& t : c_.surface(film_).triangles)
        for (int j = 0; j < 3; ++j) {
            if (t[j] == loop_[0] && t[(j + 1) % 3] == loop_[1]) along = 1;
            if (t[j] == loop_[1] && t[(j + 1) % 3] == loop_[0]) along = -1;
        }
    int out_of_d = 0; // +1: F's normal points out of D
    for (int k : {d_, e_}) {
        if (k < 0) continue;
        for (const BodyFace& f : c_.bodies()[k].faces)
            if (f.surface == film_) out_of_d = k == d_ ? f.sign : -f.sign;
    }
    if (along == 0 || out_of_d == 0)
        throw TopologyError(name_ + ": its facets do not follow its border");
    into_d_ = -(out_of_d * along) * area.normalized();
    radius_ = perimeter_ / (2 * M_PI);
}

/// Surface si of spec closes over the loop with a fan to apex: a facet (y, x, apex) per facet
/// with the loop's edge x -> y. With `copies` (E|X) the loop's vertices are first replaced by
/// their copies in all its facets.
void DiscCaps::cap(ClusterSpec& spec, int si, int apex, bool copies) {
    ClusterSpec::Surface& s = spec.surfaces[si];
    const std::size_t n = s.triangles.size();
    const auto on_loop = [&](int v) { return offset_.count(v) > 0; };
    const auto loop_edge = [&](int a, int b) {
        const auto i = std::find(loop_.begin(), loop_.end(), a) - loop_.begin();
        const int m = static_cast<int>(loop_.size());
        return on_loop(a) && on_loop(b) &&
               (loop_[(i + 1) % m] == b || loop_[(i + m - 1) % m] == b);
    };
    for (std::size_t f = 0; f < n; ++f) {
        Tri t = s.triangles[f];
        std::array<Offset, 3> k{};
        if (!s.offsets.empty()) k = s.offsets[f];
        for (int j = 0; j < 3; ++j) {
            const int x = t[j], y = t[(j + 1) % 3];
            if (!loop_edge(x, y)) continue;
            Offset ka = k[j]; // apex in the facet's frame: x's offset there less x's in l_0's
            for (int q = 0; q < 3; ++q) ka[q] -= offset_.at(x)[q];
            const int xc = copies ? copy_.at(x) : x, yc = copies ? copy_.at(y) : y;
            s.triangles.push_back({yc, xc, apex});
            if (spec.period) s.offsets.push_back({k[(j + 1) % 3], k[j], ka});
        }
        if (!copies) continue;
        bool renamed = false;
        for (int& v : s.triangles[f])
            if (on_loop(v)) v = copy_.at(v), renamed = true;
        if (renamed) moved_.push_back({si, static_cast<int>(f), surgery::facet_area(c_, si, f)});
    }
}

/// The positions after the surgery: c's, a and b delta from the centre, the copies eps =
/// delta / 2 towards E; delta half the radius at first, halved while a facet of E|X at a copy
/// turns over, at most ten times.
std::vector<Vec3> DiscCaps::place(const ClusterSpec& spec) {
    int turned = -1;
    double delta = 0.5 * radius_;
    for (int halvings = 0; halvings <= 10; ++halvings, delta *= 0.5) {
        const double eps = 0.5 * delta;
        std::vector<Vec3> V = c_.positions();
        V.push_back(centre_ + delta * into_d_);
        V.push_back(centre_ - delta * into_d_);
        for (int v : loop_) V.push_back(c_.position(v) - eps * into_d_);
        if (!surgery::turns_a_facet(spec, V, moved_, &turned)) return V;
    }
    throw TopologyError(name_ + ": its caps would turn a facet of surface " +
                        std::to_string(turned + 1) + " over");
}

Cluster DiscCaps::run(TransitionRecord* record) {
    find_loop();
    unwrap_loop();
    n_ = c_.n_vertices();
    for (std::size_t i = 0; i < loop_.size(); ++i) copy_[loop_[i]] = n_ + 2 + static_cast<int>(i);

    ClusterSpec spec = cluster_spec(c_);
    cap(spec, film_d_, n_, false);
    cap(spec, film_e_, n_ + 1, true);
    std::vector<Vec3> V = place(spec);
    const std::vector<int> removed{film_};
    surgery::remove_surfaces(spec, removed);
    const std::vector<int> used = surgery::keep_used_vertices(spec, V);
    surgery::copy_vertex_lists(c_, [&](int v) { return used[v]; }, spec);
    Cluster r = surgery::rebuild(std::move(spec), name_, "its caps");
    surgery::carry_over_without_surfaces(c_, removed, r);
    for (int v : {n_, n_ + 1})
        if (!r.vertex_junction_edges(used[v]).empty())
            throw TopologyError(name_ + ": a cap's apex is not inside one film");

    if (record) {
        record->kind = "disc film";
        record->capped = true;
        record->size = radius_;
        record->film = film_;
        record->cells = {d_, e_};
        record->point = centre_;
        record->removed_vertices = c_.n_vertices() - r.n_vertices();
        record->removed_facets = c_.n_facets() - r.n_facets();
        record->where = "disc film " + std::to_string(film_ + 1) + " between " +
                        surgery::cell_name(d_) + " and " + surgery::cell_name(e_) +
                        " (closed triple line " + std::to_string(line_ + 1) + " of length " +
                        fmt(perimeter_) + ") closed by caps: " + surgery::cell_name(x_) +
                        " closes between them at " + point_text(centre_);
    }
    return r;
}

} // namespace

namespace surgery {

Cluster cap_disc_film(const Cluster& c, int surface, TransitionRecord* record) {
    return DiscCaps(c, surface).run(record);
}

} // namespace surgery
} // namespace froth
