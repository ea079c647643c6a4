// Film angles at triple lines by local quadratic fits (see geometry.h for why not chords).
#include "geometry/geometry.h"

#include <Eigen/QR>

#include <algorithm>
#include <cmath>
#include <map>

namespace froth {
namespace {

/// Facets of each (surface, vertex) pair, as CSR over Cluster pairs.
struct PairFacets {
    std::vector<int> start, facet_surface, facet_index;
};

PairFacets pair_facets(const Cluster& c) {
    PairFacets p;
    p.start.assign(c.n_pairs() + 1, 0);
    for (int i = 0; i < c.n_surfaces(); ++i)
        for (const Tri& t : c.surface(i).triangles)
            for (int v : t) ++p.start[c.pair_index(v, i) + 1];
    for (int k = 0; k < c.n_pairs(); ++k) p.start[k + 1] += p.start[k];
    p.facet_index.resize(p.start.back());
    std::vector<int> fill(p.start.begin(), p.start.end() - 1);
    for (int i = 0; i < c.n_surfaces(); ++i)
        for (int f = 0; f < static_cast<int>(c.surface(i).triangles.size()); ++f)
            for (int v : c.surface(i).triangles[f]) p.facet_index[fill[c.pair_index(v, i)]++] = f;
    return p;
}

/// The edge vector from a to its neighbour b (unwrapped in a periodic cluster).
Vec3 edge_vector(const Cluster& c, int a, int b) {
    return c.position(b) - c.position(a) + c.edge_shift(a, b);
}

/// A vertex near v and where it is relative to v (along mesh edges: unwrapped).
struct RingPoint {
    int vertex;
    Vec3 d;
};

/// Vertices of surface s within two facet rings of v (v excluded).
std::vector<RingPoint> two_ring(const Cluster& c, const PairFacets& pf, int v, int s) {
    std::vector<RingPoint> ring = {{v, Vec3::Zero()}};
    std::map<int, bool> seen = {{v, true}};
    for (int pass = 0; pass < 2; ++pass) {
        const std::vector<RingPoint> seeds = ring;
        for (const RingPoint& u : seeds) {
            const int k = c.pair_index(u.vertex, s);
            for (int x = pf.start[k]; x < pf.start[k + 1]; ++x)
                for (int w : c.surface(s).triangles[pf.facet_index[x]])
                    if (seen.emplace(w, true).second)
                        ring.push_back({w, u.d + edge_vector(c, u.vertex, w)});
        }
    }
    ring.erase(ring.begin());
    return ring;
}

/// True if vertex u is a corner of a facet of surface s whose normal is within the crease
/// angle's cosine band of n (45 degrees): u is then on the same smooth part of the film.
bool on_facet_facing(const Cluster& c, const PairFacets& pf, int u, int s, const Vec3& n) {
    const int k = c.pair_index(u, s);
    for (int x = pf.start[k]; x < pf.start[k + 1]; ++x) {
        const Vec3 a = area_vector2(c.surface(s).corners(c.positions(), pf.facet_index[x]));
        if (a.dot(n) > std::cos(M_PI / 4) * a.norm()) return true;
    }
    return false;
}

/// Unit direction in which film s leaves the line at x (tangent t), starting from the chord
/// direction e1: fit w = a u + e r + b u^2 + c r^2 + d u r in the frame (e1, t, e2 = t x e1)
/// and tilt e1 by the slope a.
Vec3 film_direction(const std::vector<RingPoint>& ring, const Vec3& t, const Vec3& e1) {
    const Vec3 e2 = t.cross(e1);
    Eigen::MatrixXd P(ring.size(), 5);
    Eigen::VectorXd w(ring.size());
    for (std::size_t k = 0; k < ring.size(); ++k) {
        const Vec3& d = ring[k].d;
        const double u = d.dot(e1), r = d.dot(t);
        P.row(k) << u, r, u * u, r * r, u * r;
        w[k] = d.dot(e2);
    }
    if (ring.size() < 7) return e1;
    Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(P);
    if (qr.rank() < 5) return e1;
    const double slope = qr.solve(w)[0];
    return (e1 + slope * e2).normalized();
}

/// The angle (degrees) between films j and k that Young's law predicts when film i is third.
/// Where the fitted film normal at a wall differs from the boundary facets' by more than this,
/// the fit spans a crease and the facets' normal is used: on smooth films the two differ by
/// about h kappa / 2, a few degrees.
constexpr double kCreaseAngle = 10.0 * M_PI / 180.0;

double young_angle(double si, double sj, double sk) {
    const double cosine = (si * si - sj * sj - sk * sk) / (2 * sj * sk);
    if (cosine < -1 || cosine > 1) return NAN; // no force balance exists for these tensions
    return std::acos(cosine) * 180.0 / M_PI;
}

/// Accumulates angles into stats (min/max/mean computed at the end by finish()).
struct AngleAccumulator {
    AngleStats stats;
    double sum = 0;
    AngleAccumulator() { stats.min = 360; }
    void add(double degrees) {
        stats.min = std::min(stats.min, degrees);
        stats.max = std::max(stats.max, degrees);
        sum += degrees;
        ++stats.count;
    }
    AngleStats finish() {
        stats.mean = stats.count ? sum / stats.count : 0;
        if (!stats.count) stats.min = 0;
        return stats;
    }
};

double angle_between(const Vec3& a, const Vec3& b) {
    return std::acos(std::clamp(a.dot(b), -1.0, 1.0)) * 180.0 / M_PI;
}

/// The relative imbalance of (2.3) at a line point with tangent t where film j (of surface
/// surfaces[j]) leaves in direction mu[j]: the normals t x mu_j are consistently oriented
/// ((nu_j, mu_j) all turn the same way about t), and gamma' is odd for (1.15), so no sign of a
/// surface's own normal field enters.
double force_imbalance(const Cluster& c, const std::array<int, 3>& surfaces, const Vec3 mu[3],
                       const Vec3& t) {
    Vec3 sum = Vec3::Zero();
    double scale = 0;
    for (int j = 0; j < 3; ++j) {
        const Surface& s = c.surface(surfaces[j]);
        const Vec3 nu = t.cross(mu[j]);
        if (!(nu.norm() > 0.5)) return 0; // no film direction across the line: nothing to weigh
        Vec3 g = s.sigma * (s.gamma ? Vec3(s.gamma->gamma_prime(nu)) : nu);
        g -= g.dot(t) * t;
        sum += g;
        scale += g.norm();
    }
    return scale > 0 ? sum.norm() / scale : 0;
}

/// Next vertex along the triple line that leaves v through junction edge e, or -1 at a line end.
int next_on_line(const Cluster& c, int v, int e) {
    const JunctionEdge& edge = c.junction_edges()[e];
    const int w = edge.a == v ? edge.b : edge.a;
    const std::vector<int> at = c.vertex_junction_edges(w);
    if (at.size() != 2) return -1;
    const int f = at[0] == e ? at[1] : at[0];
    if (c.junction_edges()[f].surfaces != edge.surfaces) return -1;
    const JunctionEdge& g = c.junction_edges()[f];
    return g.a == w ? g.b : g.a;
}

} // namespace

std::vector<LineVertexAngles> triple_line_vertex_angles(const Cluster& c) {
    const PairFacets pf = pair_facets(c);
    std::vector<LineVertexAngles> out;
    for (int v = 0; v < c.n_vertices(); ++v) {
        const std::vector<int> edges = c.vertex_junction_edges(v);
        if (edges.size() != 2) continue; // not on a line, or a quadruple point / line end
        const JunctionEdge& e0 = c.junction_edges()[edges[0]];
        const JunctionEdge& e1 = c.junction_edges()[edges[1]];
        if (e0.surfaces != e1.surfaces) continue;
        const int prev = e0.a == v ? e0.b : e0.a, next = e1.a == v ? e1.b : e1.a;
        const Vec3 t = (edge_vector(c, v, next) - edge_vector(c, v, prev)).normalized();
        Vec3 dir[3];
        double sigma[3];
        for (int j = 0; j < 3; ++j) {
            // chord directions into the film from the facets at both line edges, averaged
            Vec3 chord = Vec3::Zero();
            for (const JunctionEdge* e : {&e0, &e1}) {
                const Vec3 d = edge_vector(c, v, e->opposite[j]);
                chord += (d - d.dot(t) * t).normalized();
            }
            chord = (chord - chord.dot(t) * t).normalized();
            dir[j] = film_direction(two_ring(c, pf, v, e0.surfaces[j]), t, chord);
            sigma[j] = c.surface(e0.surfaces[j]).sigma;
        }
        LineVertexAngles a;
        a.vertex = v;
        a.surfaces = e0.surfaces;
        a.force_imbalance = force_imbalance(c, e0.surfaces, dir, t);
        for (int j = 0; j < 3; ++j) {
            const int k = (j + 1) % 3, i = (j + 2) % 3; // film i is opposite the angle (j, k)
            a.angles[i] = angle_between(dir[j], dir[k]);
            const double error = std::abs(a.angles[i] - young_angle(sigma[i], sigma[j], sigma[k]));
            a.young_error = std::isnan(error) || std::isnan(a.young_error)
                                ? NAN
                                : std::max(a.young_error, error);
        }
        out.push_back(a);
    }
    return out;
}

AngleStats triple_line_angles(const Cluster& c) {
    AngleAccumulator acc;
    for (const LineVertexAngles& a : triple_line_vertex_angles(c)) {
        acc.stats.force_imbalance = std::max(acc.stats.force_imbalance, a.force_imbalance);
        for (int i : {2, 0, 1}) acc.add(a.angles[i]); // the order of the fits: the same mean
        acc.stats.young_error = std::isnan(a.young_error) || std::isnan(acc.stats.young_error)
                                    ? NAN
                                    : std::max(acc.stats.young_error, a.young_error);
    }
    return acc.finish();
}

AngleStats quadruple_point_angles(const Cluster& c) {
    AngleAccumulator acc;
    for (int q : c.quadruple_points()) {
        std::vector<Vec3> dirs;
        for (int e : c.vertex_junction_edges(q)) {
            const JunctionEdge& edge = c.junction_edges()[e];
            const int p1 = edge.a == q ? edge.b : edge.a;
            const Vec3 d1 = edge_vector(c, q, p1);
            const int p2 = next_on_line(c, q, e);
            if (p2 < 0) {
                dirs.push_back(d1.normalized());
                continue;
            }
            // derivative at s = 0 of the quadratic through (0, 0), (s1, d1), (s2, d2)
            const Vec3 d2 = d1 + edge_vector(c, p1, p2);
            const double s1 = d1.norm(), s2 = s1 + (d2 - d1).norm();
            dirs.push_back((d1 * s2 / (s1 * (s2 - s1)) - d2 * s1 / (s2 * (s2 - s1))).normalized());
        }
        for (std::size_t a = 0; a < dirs.size(); ++a)
            for (std::size_t b = a + 1; b < dirs.size(); ++b) acc.add(angle_between(dirs[a], dirs[b]));
    }
    return acc.finish();
}

AngleStats contact_angles(const Cluster& c) {
    AngleAccumulator acc;
    if (!c.has_walls()) return acc.finish();
    // Per (surface, vertex) pair, the boundary edges there and their facets' third corners.
    std::map<std::array<int, 2>, int> edge_id;
    const auto& edges = c.boundary_edges();
    for (int e = 0; e < static_cast<int>(edges.size()); ++e) edge_id[{edges[e].a, edges[e].b}] = e;
    std::vector<int> opposite(edges.size(), -1);
    std::vector<Vec3> facet_normal(edges.size());
    for (int i = 0; i < c.n_surfaces(); ++i)
        for (const Tri& t : c.surface(i).triangles)
            for (int k = 0; k < 3; ++k) {
                const int a = t[k], b = t[(k + 1) % 3];
                const auto it = edge_id.find({std::min(a, b), std::max(a, b)});
                if (it == edge_id.end()) continue;
                opposite[it->second] = t[(k + 2) % 3];
                facet_normal[it->second] = area_vector2(c.positions(), t);
            }
    std::vector<std::vector<int>> at(c.n_pairs());
    for (int e = 0; e < static_cast<int>(edges.size()); ++e)
        for (int v : {edges[e].a, edges[e].b}) at[c.pair_index(v, edges[e].surface)].push_back(e);
    const PairFacets pf = pair_facets(c);
    for (int v = 0; v < c.n_vertices(); ++v)
        for (int k = c.pair_begin(v); k < c.pair_begin(v + 1); ++k) {
            if (at[k].size() != 2) continue; // not on the film's boundary (or a pinched corner)
            const BoundaryEdge& e0 = edges[at[k][0]];
            const BoundaryEdge& e1 = edges[at[k][1]];
            const int prev = e0.a == v ? e0.b : e0.a, next = e1.a == v ? e1.b : e1.a;
            const Vec3 t = (c.position(next) - c.position(prev)).normalized();
            Vec3 chord = Vec3::Zero();
            for (int e : at[k]) {
                const Vec3 d = c.position(opposite[e]) - c.position(v);
                chord += (d - d.dot(t) * t).normalized();
            }
            chord = (chord - chord.dot(t) * t).normalized();
            const int s = c.pair_surface(k);
            // The normal of the boundary facets, averaged: first order, but right at a crease
            // (a box's edge standing on the wall), where a fit across the crease is not. The fit
            // uses only vertices on facets that face the same way (not across a crease).
            const Vec3 chord_normal = (facet_normal[at[k][0]].normalized() +
                                       facet_normal[at[k][1]].normalized()).normalized();
            std::vector<RingPoint> ring = two_ring(c, pf, v, s);
            ring.erase(std::remove_if(ring.begin(), ring.end(),
                                      [&](const RingPoint& u) {
                                          return !on_facet_facing(c, pf, u.vertex, s, chord_normal);
                                      }),
                       ring.end());
            const Vec3 into = film_direction(ring, t, chord);
            Vec3 nu = t.cross(into).normalized();
            if (nu.dot(chord_normal) < 0) nu = -nu;
            // On the crease itself (the two boundary facets 30+ degrees apart: a box corner) the
            // film has no normal; the facets' mean is the one that meets the wall as they do.
            const bool creased = facet_normal[at[k][0]].normalized().dot(
                                     facet_normal[at[k][1]].normalized()) < std::cos(M_PI / 6);
            if (creased || nu.dot(chord_normal) < std::cos(kCreaseAngle)) nu = chord_normal;
            // (1.26b): n . gamma'(nu) = 0; gamma' is odd, so nu's sign does not enter
            const Surface& surface = c.surface(s);
            const Vec3 g = surface.gamma ? Vec3(surface.gamma->gamma_prime(nu)) : nu;
            for (int w : c.vertex_walls(v)) {
                const Vec3 n = c.walls()[w]->normal(c.position(v));
                const double angle = angle_between(nu, n);
                acc.add(angle);
                acc.stats.young_error = std::max(acc.stats.young_error, std::abs(angle - 90));
                acc.stats.force_imbalance =
                    std::max(acc.stats.force_imbalance, std::abs(n.dot(g)) / g.norm());
            }
        }
    return acc.finish();
}

double wall_drift(const Cluster& c) {
    double drift = 0;
    for (int v = 0; v < c.n_vertices(); ++v)
        for (int w : c.vertex_walls(v))
            drift = std::max(drift, c.walls()[w]->distance(c.position(v)));
    return drift;
}

} // namespace froth
