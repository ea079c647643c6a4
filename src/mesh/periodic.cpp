// Periodic clusters (Evolver's torus model, ClusterSpec::period): space is R^3 modulo the
// lattice L Z^3. A vertex is stored once; a facet corner of vertex v sits at X[v] + L k with
// its own integer offset k, so every facet is whole (Surface::corners). What needs more than
// one facet at a time is here: identifying the periodic images of an unwrapped mesh, checking
// that each edge joins its vertices across one offset, and finding each body's unwrapped cell.
//
// A body's cell is found by walking its boundary: from a facet with a chosen outward side,
// across each edge to the film the body meets first when it turns about the edge through its
// own interior (the wedge rule below), with the lattice translation that makes the two facets
// share the edge. The walk gives every facet of the body its sign and translation, also where
// a film bounds the cell on both sides (a film between a cell and its own image, as the
// squares of Kelvin's two-cell foam do), which a sign per surface could not express. The
// volume is then the divergence theorem over the translated facets, exact for the polyhedron.

#include "core/errors.h"
#include "core/format.h"
#include "mesh/cluster.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <tuple>
#include <unordered_map>

namespace froth {
namespace {

Eigen::Vector3i lattice(const Offset& k) { return {k[0], k[1], k[2]}; }

std::string edge_name(int a, int b) {
    return "edge " + std::to_string(a + 1) + "-" + std::to_string(b + 1);
}

/// One side of a facet: the edge from its corner `corner` to the next, keyed undirected.
struct FacetSide {
    int lo, hi;
    int surface, facet, corner;
};

std::vector<FacetSide> facet_sides(const std::vector<Surface>& surfaces) {
    std::vector<FacetSide> sides;
    for (int s = 0; s < static_cast<int>(surfaces.size()); ++s)
        for (int f = 0; f < static_cast<int>(surfaces[s].triangles.size()); ++f)
            for (int k = 0; k < 3; ++k) {
                const int a = surfaces[s].triangles[f][k], b = surfaces[s].triangles[f][(k + 1) % 3];
                sides.push_back({std::min(a, b), std::max(a, b), s, f, k});
            }
    std::sort(sides.begin(), sides.end(), [](const FacetSide& x, const FacetSide& y) {
        return std::tie(x.lo, x.hi, x.surface, x.facet) < std::tie(y.lo, y.hi, y.surface, y.facet);
    });
    return sides;
}

int corner_of(const Tri& t, int v) { return t[0] == v ? 0 : t[1] == v ? 1 : 2; }

} // namespace

std::vector<int> identify_periodic_images(ClusterSpec& spec, const Eigen::Matrix3d& L) {
    const double scale = L.colwise().norm().prod();
    if (!L.allFinite() || !(std::abs(L.determinant()) > 1e-12 * scale))
        throw InvalidInput("periodic: the period vectors must be finite and linearly independent");
    if (!spec.curve_points.empty() || !spec.attachments.empty())
        throw InvalidInput("periodic: wire curves and wall attachments are not supported");
    const Eigen::Matrix3d Linv = L.inverse();
    // In lattice coordinates u = L^-1 x a point is r = u - k with k = floor(u + tol): r in
    // [-tol, 1 - tol), so images of one point get the same r however round-off placed them.
    const double tol = 1e-9, cell = 1e-6;
    std::unordered_map<std::int64_t, std::vector<int>> grid; // cell of r -> new vertex ids
    auto key = [](const Eigen::Vector3i& g) {
        return (static_cast<std::int64_t>(g[0]) * 2000003 + g[1]) * 2000003 + g[2];
    };
    std::vector<Vec3> reduced; // r of each new vertex
    std::vector<int> new_id(spec.vertices.size());
    std::vector<Offset> offset(spec.vertices.size());
    for (std::size_t v = 0; v < spec.vertices.size(); ++v) {
        const Vec3 u = Linv * spec.vertices[v];
        if (!u.allFinite()) throw InvalidInput("periodic: vertex " + std::to_string(v + 1) +
                                               " has a non-finite coordinate");
        const Vec3 k = (u.array() + tol).floor().matrix();
        if (k.cwiseAbs().maxCoeff() > kMaxOffset)
            throw InvalidInput("periodic: vertex " + std::to_string(v + 1) + " lies " +
                               fmt(k.cwiseAbs().maxCoeff()) + " periods from the cell; at most " +
                               std::to_string(kMaxOffset));
        const Vec3 r = u - k;
        const Eigen::Vector3i g = (r / cell).array().floor().cast<int>();
        int found = -1;
        for (int dx = -1; dx <= 1 && found < 0; ++dx)
            for (int dy = -1; dy <= 1 && found < 0; ++dy)
                for (int dz = -1; dz <= 1 && found < 0; ++dz) {
                    const auto it = grid.find(key(g + Eigen::Vector3i(dx, dy, dz)));
                    if (it == grid.end()) continue;
                    for (int w : it->second)
                        if ((reduced[w] - r).cwiseAbs().maxCoeff() <= tol) found = w;
                }
        if (found < 0) {
            found = static_cast<int>(reduced.size());
            reduced.push_back(r);
            grid[key(g)].push_back(found);
        }
        new_id[v] = found;
        offset[v] = {static_cast<int>(k[0]), static_cast<int>(k[1]), static_cast<int>(k[2])};
    }
    for (auto& s : spec.surfaces) {
        s.offsets.assign(s.triangles.size(), {});
        for (std::size_t f = 0; f < s.triangles.size(); ++f)
            for (int a = 0; a < 3; ++a) {
                int& v = s.triangles[f][a];
                if (v < 0 || v >= static_cast<int>(new_id.size()))
                    throw InvalidInput("periodic: a facet names vertex " + std::to_string(v + 1) +
                                       ", but there are " + std::to_string(new_id.size()));
                s.offsets[f][a] = offset[v];
                v = new_id[v];
            }
    }
    auto remap = [&](std::vector<int>& ids) {
        for (int& v : ids)
            if (v >= 0 && v < static_cast<int>(new_id.size())) v = new_id[v];
        std::sort(ids.begin(), ids.end());
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
    };
    remap(spec.fixed);
    spec.vertices.clear();
    for (const Vec3& r : reduced) spec.vertices.push_back(L * r);
    spec.period = L;
    return new_id;
}

void Cluster::index_edge_offsets() {
    struct Link {
        int lo, hi;
        Eigen::Vector3i rel; // offset of hi's corner less lo's
        int surface, facet;
    };
    std::vector<Link> links;
    for (int s = 0; s < n_surfaces(); ++s) {
        const Surface& S = surfaces_[s];
        for (int f = 0; f < static_cast<int>(S.triangles.size()); ++f)
            for (int k = 0; k < 3; ++k) {
                int a = S.triangles[f][k], b = S.triangles[f][(k + 1) % 3];
                Eigen::Vector3i rel = lattice(S.offsets[f][(k + 1) % 3]) - lattice(S.offsets[f][k]);
                if (a > b) std::swap(a, b), rel = -rel;
                links.push_back({a, b, rel, s, f});
            }
    }
    std::sort(links.begin(), links.end(),
              [](const Link& x, const Link& y) { return std::tie(x.lo, x.hi) < std::tie(y.lo, y.hi); });
    for (std::size_t i = 1; i < links.size(); ++i) {
        const Link &p = links[i - 1], &q = links[i];
        if (p.lo == q.lo && p.hi == q.hi && p.rel != q.rel)
            throw TopologyError("cluster: " + edge_name(p.lo, p.hi) + " joins its vertices across "
                                "two different lattice offsets (in facet " +
                                std::to_string(p.facet + 1) + " of surface " +
                                std::to_string(p.surface + 1) + " and facet " +
                                std::to_string(q.facet + 1) + " of surface " +
                                std::to_string(q.surface + 1) + "): two edges of the periodic "
                                "mesh between the same vertices; refine the mesh");
    }
    for (const Link& l : links)
        edge_shift_[static_cast<std::int64_t>(l.lo) * n_vertices() + l.hi] =
            *period_ * l.rel.cast<double>();
}

Vec3 Cluster::edge_shift(int a, int b) const {
    if (!period_) return Vec3::Zero();
    const auto it = edge_shift_.find(static_cast<std::int64_t>(std::min(a, b)) * n_vertices() +
                                     std::max(a, b));
    if (it == edge_shift_.end()) return Vec3::Zero();
    return a < b ? it->second : Vec3(-it->second);
}

namespace {

/// One facet of a body's unwrapped cell: the facet, the sign that turns it outward, and the
/// lattice translation m that puts it in the cell (its corners at X + L (k + m)).
struct CellFacet {
    int surface, facet, sign;
    Eigen::Vector3i m;
};

struct CellWalk {
    std::vector<CellFacet> facets;
    std::string error; ///< empty when the walk closed a cell
};

class CellWalker {
  public:
    CellWalker(const std::vector<Surface>& surfaces, const std::vector<Vec3>& X,
               const Eigen::Matrix3d& L)
        : surfaces_(surfaces), X_(X), L_(L), sides_(facet_sides(surfaces)) {
        first_facet_.push_back(0);
        for (const Surface& S : surfaces_)
            first_facet_.push_back(first_facet_.back() + static_cast<int>(S.triangles.size()));
        // each facet side's group in sides_ (the facets at its edge), found once
        group_.resize(3 * static_cast<std::size_t>(first_facet_.back()));
        for (std::size_t i = 0; i < sides_.size();) {
            std::size_t end = i;
            while (end < sides_.size() && sides_[end].lo == sides_[i].lo &&
                   sides_[end].hi == sides_[i].hi)
                ++end;
            for (std::size_t k = i; k < end; ++k)
                group_[3 * facet_index(sides_[k].surface, sides_[k].facet) + sides_[k].corner] =
                    {static_cast<int>(i), static_cast<int>(end)};
            i = end;
        }
        seen_.assign(2 * static_cast<std::size_t>(first_facet_.back()), -1);
        seen_m_.resize(seen_.size());
    }

    /// Walks the cell of a body that names each surface `times[s]` times (0, 1 or 2), from
    /// facet 0 of `start` with outward sign `sign`.
    CellWalk walk(const std::string& name, const std::vector<int>& times, int start, int sign) const {
        CellWalk out;
        ++walks_; // seen_ holds this walk's facet sides where it equals walks_, with seen_m_
        const auto seen_at = [&](int surface, int facet, int side) {
            return 2 * static_cast<std::size_t>(facet_index(surface, facet)) + (side > 0);
        };
        std::vector<int> side_of(surfaces_.size(), 0); // the sign met on a surface named once
        std::vector<CellFacet> queue = {{start, 0, sign, Eigen::Vector3i::Zero()}};
        seen_[seen_at(start, 0, sign)] = walks_;
        seen_m_[seen_at(start, 0, sign)] = Eigen::Vector3i::Zero();
        side_of[start] = sign;
        while (!queue.empty()) {
            const CellFacet f = queue.back();
            queue.pop_back();
            out.facets.push_back(f);
            for (int j = 0; j < 3; ++j) {
                CellFacet g{};
                if (!out.error.empty() || !next_across(name, times, f, j, g, out.error)) break;
                if (times[g.surface] == 0) {
                    out.error = "cluster: " + name + " is not closed: across " + edge(f, j) +
                                " its region is bounded by surface " + std::to_string(g.surface + 1) +
                                ", which the body does not name";
                    break;
                }
                if (times[g.surface] == 1) {
                    int& known = side_of[g.surface];
                    if (known == 0) known = g.sign;
                    if (known != g.sign) {
                        out.error = "cluster: " + name + " meets surface " +
                                    std::to_string(g.surface + 1) + " from both sides; name it "
                                    "twice if it is a film between the cell and its own image";
                        break;
                    }
                }
                const std::size_t at = seen_at(g.surface, g.facet, g.sign);
                if (seen_[at] != walks_) {
                    seen_[at] = walks_, seen_m_[at] = g.m;
                    queue.push_back(g);
                } else if (seen_m_[at] != g.m) {
                    out.error = "cluster: " + name + " wraps around the periodic box (its films "
                                "do not close up into one cell once unwrapped, near " +
                                edge(f, j) + ")";
                    break;
                }
            }
            if (!out.error.empty()) return out;
        }
        std::map<int, int> got; // facets of the cell on each surface
        for (const CellFacet& f : out.facets) ++got[f.surface];
        for (std::size_t s = 0; s < surfaces_.size(); ++s) {
            if (times[s] == 0) continue;
            const int wanted = times[s] * static_cast<int>(surfaces_[s].triangles.size());
            if (got[static_cast<int>(s)] != wanted)
                out.error = "cluster: " + name + ": its surfaces do not bound one cell (surface " +
                            std::to_string(s + 1) + " has " + std::to_string(wanted) +
                            " facet sides in the body, its cell reaches " +
                            std::to_string(got[static_cast<int>(s)]) + ")";
        }
        return out;
    }

  private:
    std::array<Vec3, 3> unwrapped(const CellFacet& f) const {
        std::array<Vec3, 3> x = surfaces_[f.surface].corners(X_, f.facet);
        const Vec3 shift = L_ * f.m.cast<double>();
        for (Vec3& p : x) p += shift;
        return x;
    }

    std::string edge(const CellFacet& f, int j) const {
        const Tri& t = surfaces_[f.surface].triangles[f.facet];
        return edge_name(t[j], t[(j + 1) % 3]) + " of facet " + std::to_string(f.facet + 1) +
               " of surface " + std::to_string(f.surface + 1);
    }

    /// The facet of the cell across side j of f: the only other facet at that edge on a
    /// surface the body names, if there is one; else, of all facets at the edge, the one the
    /// cell's interior reaches first turning about the edge from f (the wedge rule). The first
    /// rule does not depend on the positions, so a state whose films a step has crossed near a
    /// line (the wedges out of order) still has its cells.
    bool next_across(const std::string& name, const std::vector<int>& times, const CellFacet& f,
                     int j, CellFacet& next, std::string& error) const {
        const Tri& t = surfaces_[f.surface].triangles[f.facet];
        const Offset* k = surfaces_[f.surface].offsets[f.facet].data();
        const int a = t[j], b = t[(j + 1) % 3];
        const std::array<int, 2> group = group_[3 * facet_index(f.surface, f.facet) + j];
        const auto range = std::pair{sides_.begin() + group[0], sides_.begin() + group[1]};
        const auto facet_across = [&](const FacetSide& side) {
            const Surface& S = surfaces_[side.surface];
            const Tri& tg = S.triangles[side.facet];
            const int ca = corner_of(tg, a);
            CellFacet g{side.surface, side.facet, 0,
                        lattice(k[j]) + f.m - lattice(S.offsets[side.facet][ca])};
            const int dir = tg[(ca + 1) % 3] == b ? 1 : -1; // +1: g runs a -> b, as f does
            g.sign = -f.sign * dir;                          // so that the two run it oppositely
            return g;
        };
        // the first rule needs no geometry (inside a film, the common case: the rebuilds of
        // a 20k-vertex network spent most of their time in the wedges' angles)
        int named = 0;
        const FacetSide* only_named = nullptr;
        for (auto it = range.first; it != range.second; ++it)
            if (!(it->surface == f.surface && it->facet == f.facet) && times[it->surface] > 0)
                ++named, only_named = &*it;
        if (named == 1) {
            next = facet_across(*only_named);
            return true;
        }
        const std::array<Vec3, 3> p = unwrapped(f);
        const Vec3 e = (p[(j + 1) % 3] - p[j]).normalized();
        const Vec3 inward = -f.sign * (p[1] - p[0]).cross(p[2] - p[0]).normalized();
        auto across = [&](const Vec3& q) { // the direction from the edge to q, across it
            const Vec3 d = q - p[j];
            return Vec3((d - e.dot(d) * e).normalized());
        };
        const Vec3 u = across(p[(j + 2) % 3]);
        double best = INFINITY;
        for (auto it = range.first; it != range.second; ++it) {
            if (it->surface == f.surface && it->facet == f.facet) continue;
            const CellFacet g = facet_across(*it);
            const Tri& tg = surfaces_[it->surface].triangles[it->facet];
            const std::array<Vec3, 3> q = unwrapped(g);
            const Vec3 w = across(q[3 - corner_of(tg, a) - corner_of(tg, b)]);
            double angle = std::atan2(w.dot(inward), w.dot(u));
            if (angle <= 0) angle += 2 * std::numbers::pi;
            if (angle < best) best = angle, next = g;
        }
        if (best == INFINITY) {
            error = "cluster: " + name + " is not closed: " + edge(f, j) + " is in no other facet";
            return false;
        }
        return true;
    }

    int facet_index(int surface, int facet) const { return first_facet_[surface] + facet; }

    const std::vector<Surface>& surfaces_;
    const std::vector<Vec3>& X_;
    const Eigen::Matrix3d& L_;
    std::vector<FacetSide> sides_;
    std::vector<int> first_facet_;            // surface s's facets are first_facet_[s] + f
    std::vector<std::array<int, 2>> group_;   // per facet side: its edge's range in sides_
    mutable std::vector<int> seen_;           // per facet and sign: the walk that reached it
    mutable std::vector<Eigen::Vector3i> seen_m_; // and the lattice translation it had then
    mutable int walks_ = 0;
};

} // namespace

void Cluster::orient_periodic_bodies(const std::vector<std::vector<int>>& body_surfaces) {
    const CellWalker walker(surfaces_, X_, *period_);
    for (std::size_t b = 0; b < body_surfaces.size(); ++b) {
        const std::string name = "body " + std::to_string(b + 1);
        std::vector<int> times(surfaces_.size(), 0);
        for (int s : body_surfaces[b]) {
            if (s < 0 || s >= n_surfaces())
                throw InvalidInput("cluster: " + name + " names surface " + std::to_string(s + 1) +
                                   ", but there are " + std::to_string(n_surfaces()) + " surfaces");
            if (++times[s] > 2)
                throw InvalidInput("cluster: " + name + " names surface " + std::to_string(s + 1) +
                                   " more than twice (twice: a film with the cell on both sides)");
        }
        if (body_surfaces[b].empty()) throw InvalidInput("cluster: " + name + " has no surfaces");
        // The outward side of the first facet is not known: the walk from the wrong side
        // traces the neighbouring cells and fails or encloses a negative volume.
        std::optional<Body> body;
        std::string error;
        std::size_t reached = 0;
        for (int sign : {1, -1}) {
            const CellWalk cell = walker.walk(name, times, body_surfaces[b][0], sign);
            if (!cell.error.empty()) {
                if (cell.facets.size() >= reached) error = cell.error, reached = cell.facets.size();
                continue;
            }
            Body candidate;
            for (int s : body_surfaces[b])
                for (int sg : {1, -1}) {
                    if (std::any_of(candidate.faces.begin(), candidate.faces.end(),
                                    [&](const BodyFace& x) { return x.surface == s && x.sign == sg; }))
                        continue;
                    BodyFace face{s, sg, std::vector<Vec3>(surfaces_[s].triangles.size())};
                    bool any = false;
                    for (const CellFacet& f : cell.facets)
                        if (f.surface == s && f.sign == sg)
                            face.shift[f.facet] = *period_ * f.m.cast<double>(), any = true;
                    if (any) candidate.faces.push_back(std::move(face));
                }
            const double volume = body_volume(*this, candidate, X_);
            double area = 0;
            for (const BodyFace& f : candidate.faces)
                for (std::size_t k = 0; k < surfaces_[f.surface].triangles.size(); ++k) {
                    const auto x = surfaces_[f.surface].corners(X_, k);
                    area += 0.5 * (x[1] - x[0]).cross(x[2] - x[0]).norm();
                }
            if (volume > 1e-12 * std::pow(area, 1.5)) {
                body = std::move(candidate);
                break;
            }
            error = "cluster: " + name + " encloses no volume (its cell bounds " + fmt(volume) + ")";
            reached = cell.facets.size();
        }
        if (!body) throw TopologyError(error);
        initial_volumes_.push_back(body_volume(*this, *body, X_));
        bodies_.push_back(std::move(*body));
    }
    // Filled: each surface once on each side of the cells, in all (then sum_b dV_b = 0).
    std::vector<int> plus(surfaces_.size(), 0), minus(surfaces_.size(), 0);
    for (const Body& b : bodies_)
        for (const BodyFace& f : b.faces) ++(f.sign > 0 ? plus : minus)[f.surface];
    fills_box_ = !bodies_.empty();
    for (std::size_t s = 0; s < surfaces_.size(); ++s)
        fills_box_ = fills_box_ && plus[s] == 1 && minus[s] == 1;
}

double Cluster::box_volume() const { return period_ ? std::abs(period_->determinant()) : 0.0; }

void check_filled_box_targets(const Cluster& c, const char* op) {
    if (!c.fills_box()) return;
    double sum = 0;
    for (double v : c.target_volumes()) sum += v;
    const double box = c.box_volume();
    if (!(std::abs(sum - box) <= 1e-9 * box))
        throw InvalidInput(std::string(op) + ": the cells fill the periodic box, so their target "
                           "volumes must add up to its volume " + fmt(box) + "; they add up to " +
                           fmt(sum) + " (c:set_volume)");
}

DisplayMesh display_mesh(const Cluster& c) {
    DisplayMesh m;
    if (!c.periodic()) {
        m.points = c.positions();
        m.vertex.resize(c.n_vertices());
        for (int v = 0; v < c.n_vertices(); ++v) m.vertex[v] = v;
        for (const Surface& s : c.surfaces()) m.triangles.push_back(s.triangles);
        return m;
    }
    std::map<std::pair<int, Offset>, int> point; // (vertex, offset) -> point
    for (const Surface& s : c.surfaces()) {
        std::vector<Tri> tris(s.triangles.size());
        for (std::size_t f = 0; f < s.triangles.size(); ++f)
            for (int a = 0; a < 3; ++a) {
                const int v = s.triangles[f][a];
                const auto [it, fresh] =
                    point.try_emplace({v, s.offsets[f][a]}, static_cast<int>(m.points.size()));
                if (fresh) m.points.push_back(c.position(v) + s.shifts[f][a]), m.vertex.push_back(v);
                tris[f][a] = it->second;
            }
        m.triangles.push_back(std::move(tris));
    }
    return m;
}

} // namespace froth
