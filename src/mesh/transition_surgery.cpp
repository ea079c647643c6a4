// Shared steps of the topological transitions (transition_surgery.h).
#include "mesh/transition_surgery.h"

#include "core/errors.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

namespace froth::surgery {

std::string cell_name(int k) {
    return k < 0 ? std::string("the outside") : "body " + std::to_string(k + 1);
}

std::vector<int> keep_used_vertices(ClusterSpec& spec, const std::vector<Vec3>& V) {
    std::vector<int> used(V.size(), -1);
    for (const auto& s : spec.surfaces)
        for (const Tri& t : s.triangles)
            for (int v : t) used[v] = 0;
    int count = 0;
    spec.vertices.clear();
    for (std::size_t v = 0; v < V.size(); ++v)
        if (used[v] == 0) used[v] = count++, spec.vertices.push_back(V[v]);
    for (auto& s : spec.surfaces)
        for (Tri& t : s.triangles)
            for (int& v : t) v = used[v];
    return used;
}

void copy_vertex_lists(const Cluster& c, const std::function<int(int)>& map, ClusterSpec& spec) {
    spec.walls = c.walls();
    spec.attachments.clear();
    for (const auto& [v, wall] : c.wall_attachments()) spec.attachments.push_back({map(v), wall});
    spec.fixed.clear();
    for (int v : c.fixed_vertices()) spec.fixed.push_back(map(v));
    spec.curves = c.curves();
    spec.curve_points.clear();
    for (CurvePoint cp : c.curve_points()) {
        cp.vertex = map(cp.vertex);
        spec.curve_points.push_back(cp);
    }
}

Cluster rebuild(ClusterSpec spec, const std::string& what, const std::string& surgery) {
    std::optional<Cluster> r;
    try {
        r.emplace(std::move(spec));
    } catch (const Error& e) {
        throw TopologyError(what + ": the cluster after " + surgery + " is not valid: " + e.what());
    }
    return std::move(*r);
}

void carry_over_without_body(const Cluster& c, int gone, const std::vector<int>& kept_surfaces,
                             Cluster& r) {
    for (std::size_t i = 0; i < kept_surfaces.size(); ++i) {
        r.set_anisotropy(static_cast<int>(i), c.surface(kept_surfaces[i]).gamma);
        r.set_mobility(static_cast<int>(i), c.surface(kept_surfaces[i]).beta);
    }
    r.set_time(c.time());
    std::vector<double> initial, target;
    for (int k = 0; k < c.n_bodies(); ++k)
        if (k != gone) initial.push_back(c.initial_volumes()[k]);
    for (const Body& body : r.bodies()) target.push_back(body_volume(r, body, r.positions()));
    r.set_volume_references(std::move(initial), std::move(target));
}

void join_films(const Cluster& c, ClusterSpec& spec, int keep, int gone, int k) {
    const auto sign_in_k = [&](int surface) {
        for (const BodyFace& f : c.bodies()[k].faces)
            if (f.surface == surface) return f.sign;
        return 0;
    };
    const bool flip = sign_in_k(keep) != sign_in_k(gone);
    const auto& from = spec.surfaces[gone];
    auto& to = spec.surfaces[keep];
    for (std::size_t f = 0; f < from.triangles.size(); ++f) {
        Tri t = from.triangles[f];
        if (flip) std::swap(t[1], t[2]);
        to.triangles.push_back(t);
        if (!to.offsets.empty()) {
            auto o = from.offsets[f];
            if (flip) std::swap(o[1], o[2]);
            to.offsets.push_back(o);
        }
    }
}

void remove_surfaces(ClusterSpec& spec, const std::vector<int>& removed) {
    for (auto it = removed.rbegin(); it != removed.rend(); ++it)
        spec.surfaces.erase(spec.surfaces.begin() + *it);
    const auto new_id = [&](int s) {
        return s - static_cast<int>(std::lower_bound(removed.begin(), removed.end(), s) -
                                    removed.begin());
    };
    for (auto& body : spec.bodies) {
        std::vector<int> kept;
        for (int s : body)
            if (!std::binary_search(removed.begin(), removed.end(), s)) kept.push_back(new_id(s));
        body = std::move(kept);
    }
}

void carry_over_without_surfaces(const Cluster& c, const std::vector<int>& removed, Cluster& r) {
    for (int s = 0, old = 0; s < r.n_surfaces(); ++s, ++old) {
        while (std::binary_search(removed.begin(), removed.end(), old)) ++old;
        if (old >= c.n_surfaces()) break; // surfaces r added
        r.set_anisotropy(s, c.surface(old).gamma);
        r.set_mobility(s, c.surface(old).beta);
    }
    r.set_time(c.time());
    r.set_volume_references(c.initial_volumes(), c.target_volumes());
}

void check_one_fan(const std::vector<std::pair<int, int>>& link, int surface,
                   const std::string& what) {
    if (link.empty()) return;
    const std::string name = "surface " + std::to_string(surface + 1);
    std::map<int, int> next, in;
    for (const auto& [x, y] : link) {
        if (!next.emplace(x, y).second || ++in[y] > 1)
            throw TopologyError(what + ": it would fold " + name + " over the point; refine "
                                "the mesh around it first");
    }
    int start = link.front().first; // a path starts where nothing comes in; a cycle anywhere
    for (const auto& [x, y] : link)
        if (!in.count(x)) start = x;
    std::size_t walked = 0;
    for (int v = start; next.count(v) && walked < link.size();) {
        v = next[v];
        ++walked;
        if (v == start) break; // round a closed fan
    }
    if (walked != link.size())
        throw TopologyError(what + ": it would pinch " + name + " at the point (its facets "
                            "there would form more than one fan); refine the mesh around it "
                            "first");
}

std::vector<int> vertex_ranks(const Cluster& c) {
    std::vector<int> rank(c.n_vertices(), -1);
    for (int v = 0; v < c.n_vertices(); ++v) {
        if (c.is_fixed(v) || c.curve_point(v) || !c.vertex_walls(v).empty()) continue;
        const std::size_t surfaces = c.pair_begin(v + 1) - c.pair_begin(v);
        const std::size_t lines = c.vertex_junction_edges(v).size();
        if (surfaces == 1 && lines == 0) rank[v] = 0;
        else if (surfaces == 3 && lines == 2) rank[v] = 1;
        else if (surfaces == 6 && lines == 4) rank[v] = 2;
    }
    for (const BoundaryEdge& e : c.boundary_edges()) rank[e.a] = rank[e.b] = -1;
    for (const BoundaryEdge& e : c.wire_edges()) rank[e.a] = rank[e.b] = -1;
    return rank;
}

bool keeps_its_side(const Vec3& old_area, const std::array<Vec3, 3>& y) {
    const Vec3 area = (y[1] - y[0]).cross(y[2] - y[0]);
    const double scale = std::max({(y[1] - y[0]).squaredNorm(), (y[2] - y[0]).squaredNorm(),
                                   (y[2] - y[1]).squaredNorm()});
    return area.dot(old_area) > 0 && area.norm() > 1e-8 * scale;
}

Offset lattice_offset(const Cluster& c, const Vec3& unwrapped, const Vec3& stored) {
    if (!c.periodic()) return {0, 0, 0};
    const Vec3 k = c.period().inverse() * (unwrapped - stored);
    return {static_cast<int>(std::lround(k.x())), static_cast<int>(std::lround(k.y())),
            static_cast<int>(std::lround(k.z()))};
}

std::set<int> surfaces_at(const Cluster& c, int v) {
    std::set<int> at;
    for (int k = c.pair_begin(v); k < c.pair_begin(v + 1); ++k) at.insert(c.pair_surface(k));
    return at;
}

double mean_edge_at(const Cluster& c, int v) {
    double sum = 0;
    int count = 0;
    for (int si : surfaces_at(c, v)) {
        const Surface& s = c.surface(si);
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const Tri& t = s.triangles[f];
            const int k = static_cast<int>(std::find(t.begin(), t.end(), v) - t.begin());
            if (k == 3) continue;
            const auto x = s.corners(c.positions(), f);
            sum += (x[(k + 1) % 3] - x[k]).norm() + (x[(k + 2) % 3] - x[k]).norm();
            count += 2;
        }
    }
    return count ? sum / count : 0;
}

Vec3 facet_area(const Cluster& c, int surface, std::size_t facet) {
    const auto x = c.surface(surface).corners(c.positions(), facet);
    return (x[1] - x[0]).cross(x[2] - x[0]);
}

namespace {

int index_of(const Tri& t, int v) {
    return static_cast<int>(std::find(t.begin(), t.end(), v) - t.begin());
}

} // namespace

void collapse_onto(const Cluster& c, ClusterSpec& spec, int si, const std::map<int, Offset>& d,
                   int p, std::vector<MovedFacet>& moved, const std::string& what) {
    ClusterSpec::Surface& s = spec.surfaces[si];
    ClusterSpec::Surface out;
    out.sigma = s.sigma;
    std::vector<std::pair<int, int>> link;
    for (std::size_t f = 0; f < s.triangles.size(); ++f) {
        Tri t = s.triangles[f];
        std::array<Offset, 3> k{};
        if (!s.offsets.empty()) k = s.offsets[f];
        int on = 0;
        for (int j = 0; j < 3; ++j) {
            const auto it = d.find(t[j]);
            if (it == d.end()) continue;
            ++on;
            for (int x = 0; x < 3; ++x) k[j][x] -= it->second[x];
            t[j] = p;
        }
        if (on > 1) continue;
        if (on == 1) {
            const int j = index_of(t, p);
            link.push_back({t[(j + 1) % 3], t[(j + 2) % 3]});
            moved.push_back({si, static_cast<int>(out.triangles.size()), facet_area(c, si, f)});
        }
        out.triangles.push_back(t);
        if (spec.period) out.offsets.push_back(k);
    }
    check_one_fan(link, si, what);
    s = std::move(out);
}

BorderFan border_fan(const std::vector<Tri>& triangles, int v, const std::string& what,
                     int surface) {
    const std::string at = "surface " + std::to_string(surface + 1);
    const std::string vertex = " vertex " + std::to_string(v + 1);
    std::map<int, int> next, facet_from; // link u_j -> u_{j+1}, and its facet
    std::set<int> targets;
    for (std::size_t f = 0; f < triangles.size(); ++f) {
        const Tri& t = triangles[f];
        const int j = index_of(t, v);
        if (j == 3) continue;
        const int x = t[(j + 1) % 3], y = t[(j + 2) % 3];
        if (!next.emplace(x, y).second || !targets.insert(y).second)
            throw TopologyError(what + ": " + at + " is folded at" + vertex);
        facet_from[x] = static_cast<int>(f);
    }
    int start = -1;
    for (const auto& [x, y] : next)
        if (!targets.count(x)) start = x;
    if (start < 0)
        throw TopologyError(what + ": " + at + " surrounds" + vertex + "; it must end there");
    BorderFan fan{{start}, {}};
    while (next.count(fan.link.back()) && fan.facets.size() < next.size()) {
        fan.facets.push_back(facet_from[fan.link.back()]);
        fan.link.push_back(next[fan.link.back()]);
    }
    if (fan.facets.size() != next.size())
        throw TopologyError(what + ": " + at + " is pinched at" + vertex);
    return fan;
}

void split_fan(const Cluster& c, ClusterSpec& spec, int si, int v, const Offset& dv,
               const std::function<int(int)>& corner_towards, std::vector<MovedFacet>& moved,
               const std::string& what) {
    ClusterSpec::Surface& s = spec.surfaces[si];
    // a facet appended by the split of another fan of this transition (its gap facet)
    // reaches v (a T1 of a cell that meets itself: one film with fans at both ends):
    // the facet has no area in c to test its turn against (it was read out of c's
    // bounds: a crash of the 200-grain network at t = 0.6759)
    for (std::size_t f = c.surface(si).triangles.size(); f < s.triangles.size(); ++f)
        if (index_of(s.triangles[f], v) < 3)
            throw TopologyError(what + ": surface " + std::to_string(si + 1) +
                                " joins its fans at vertex " + std::to_string(v + 1) +
                                " and at another corner of the transition across one facet");
    const BorderFan fan = border_fan(s.triangles, v, what, si);
    const std::vector<int>& u = fan.link;
    const int p = corner_towards(u.front()), q = corner_towards(u.back());
    const int n = static_cast<int>(u.size()) - 1, m = (n + 1) / 2;
    for (int j = 0; j < n; ++j) {
        const int f = fan.facets[j];
        const int k = index_of(s.triangles[f], v);
        moved.push_back({si, f, facet_area(c, si, f)});
        s.triangles[f][k] = j < m ? p : q;
        if (!s.offsets.empty())
            for (int x = 0; x < 3; ++x) s.offsets[f][k][x] -= dv[x];
    }
    // the gap facet, in the frame of facet m - 1 (which holds p, u_{m-1}, u_m)
    const int g = fan.facets[m - 1];
    s.triangles.push_back({p, u[m], q});
    if (!s.offsets.empty()) {
        const Tri& t = s.triangles[g];
        const Offset kp = s.offsets[g][index_of(t, p)];
        s.offsets.push_back({kp, s.offsets[g][index_of(t, u[m])], kp});
    }
}

namespace {

/// The corners of moved facet m at positions V, in the frame of its corner 0 (offsets added).
std::array<Vec3, 3> moved_corners(const ClusterSpec& spec, const std::vector<Vec3>& V,
                                  const MovedFacet& m) {
    const auto& s = spec.surfaces[m.surface];
    std::array<Vec3, 3> x;
    for (int k = 0; k < 3; ++k) {
        x[k] = V[s.triangles[m.facet][k]];
        if (!s.offsets.empty()) {
            const Offset& o = s.offsets[m.facet][k];
            x[k] += *spec.period * Vec3(o[0], o[1], o[2]);
        }
    }
    return x;
}

} // namespace

bool turns_a_facet(const ClusterSpec& spec, const std::vector<Vec3>& V,
                   const std::vector<MovedFacet>& moved, int* surface) {
    for (const MovedFacet& m : moved)
        if (!keeps_its_side(m.area, moved_corners(spec, V, m))) {
            if (surface) *surface = m.surface;
            return true;
        }
    return false;
}

bool fit_corners(const ClusterSpec& spec, std::vector<Vec3>& V, const std::vector<MovedFacet>& moved,
                 const std::vector<int>& movable, double max_shift) {
    constexpr double kMargin = 0.01; // height over the opposite edge, in the edge's length
    constexpr int kSweeps = 50;
    std::map<int, Vec3> start;
    for (int v : movable) start[v] = V[v];
    for (int sweep = 0; sweep < kSweeps; ++sweep) {
        bool moved_any = false;
        for (const MovedFacet& m : moved) {
            const Tri& t = spec.surfaces[m.surface].triangles[m.facet];
            const Vec3 n = m.area.normalized();
            for (int k = 0; k < 3; ++k) {
                if (!start.count(t[k])) continue;
                const std::array<Vec3, 3> x = moved_corners(spec, V, m);
                const Vec3& y1 = x[(k + 1) % 3];
                const Vec3& y2 = x[(k + 2) % 3];
                // n . ((y1 - p) x (y2 - p)) = g . p + n . (y1 x y2): linear in the corner p
                const Vec3 g = (y1 - y2).cross(n);
                const double value = g.dot(x[k]) + n.dot(y1.cross(y2));
                const double wanted = kMargin * (y1 - y2).squaredNorm();
                if (value >= wanted || g.squaredNorm() == 0) continue;
                V[t[k]] += (wanted - value) / g.squaredNorm() * g;
                moved_any = true;
            }
        }
        if (!moved_any) break;
    }
    for (const auto& [v, x] : start)
        if ((V[v] - x).norm() > max_shift) return false;
    return !turns_a_facet(spec, V, moved);
}

} // namespace froth::surgery

namespace froth {

std::vector<std::array<int, 2>> surface_cells(const Cluster& c) {
    std::vector<std::vector<int>> listed(c.n_surfaces());
    for (int k = 0; k < c.n_bodies(); ++k)
        for (const BodyFace& f : c.bodies()[k].faces) listed[f.surface].push_back(k);
    std::vector<std::array<int, 2>> cells(c.n_surfaces(), {-1, -1});
    for (int s = 0; s < c.n_surfaces(); ++s)
        for (std::size_t i = 0; i < listed[s].size() && i < 2; ++i) cells[s][i] = listed[s][i];
    return cells;
}

} // namespace froth

