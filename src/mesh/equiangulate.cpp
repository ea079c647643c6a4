// Evolver's `u`: edge flips towards the Delaunay triangulation of each film (equiangulate in
// cluster.h). An interior edge ab of one surface, between the triangles (a, b, p) and (b, a, q),
// is flipped to pq when the angles at p and q opposite it add up to more than pi (the local
// Delaunay test of the two triangles); the two new triangles (a, q, p) and (b, p, q) keep the
// surface's orientation. In a periodic cluster the test and the new facets use the first
// triangle's frame: q's corner offset there is its offset in the second triangle moved by
// the difference of a's offsets in the two.
#include "core/errors.h"
#include "mesh/cluster.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

namespace froth {
namespace {

using EdgeKey = std::pair<int, int>;

EdgeKey key(int a, int b) {
    return {std::min(a, b), std::max(a, b)};
}

double angle_at(const Vec3& p, const Vec3& a, const Vec3& b) {
    const Vec3 u = a - p, w = b - p;
    return std::atan2(u.cross(w).norm(), u.dot(w));
}

/// One triangle side: the surface, the triangle's index in it, and the corner k where the
/// directed edge t[k] -> t[k+1] starts.
struct Side {
    int surface, triangle, corner;
};

struct Flipper {
    const Cluster& c;
    std::vector<std::vector<Tri>> tris; // per surface
    std::vector<std::vector<std::array<Offset, 3>>> offsets; // per surface (periodic only)
    std::set<EdgeKey> edges;            // every edge of every surface

    /// The corner of vertex v at lattice offset k.
    Vec3 corner(int v, const Offset& k) const {
        Vec3 x = c.position(v);
        if (c.periodic()) x += c.period() * Vec3(k[0], k[1], k[2]);
        return x;
    }

    /// Flips the edge of sides s1 and s2 if the Delaunay test asks for it and the result is a
    /// valid film: the new edge is new, the two new facets are not degenerate and face the
    /// way the old pair did (no fold), and the four corners are not all fixed (a held face).
    bool try_flip(const Side& s1, const Side& s2, std::vector<char>& touched) {
        std::vector<Tri>& t = tris[s1.surface];
        Tri& t1 = t[s1.triangle];
        Tri& t2 = t[s2.triangle];
        const int a = t1[s1.corner], b = t1[(s1.corner + 1) % 3], p = t1[(s1.corner + 2) % 3];
        const int q = t2[(s2.corner + 2) % 3];
        if (p == q || edges.count(key(p, q))) return false;
        if (c.is_fixed(a) && c.is_fixed(b) && c.is_fixed(p) && c.is_fixed(q)) return false;
        // the four corners in t1's frame
        Offset ka{}, kb{}, kp{}, kq{};
        if (c.periodic()) {
            const auto& o1 = offsets[s1.surface][s1.triangle];
            const auto& o2 = offsets[s2.surface][s2.triangle];
            ka = o1[s1.corner], kb = o1[(s1.corner + 1) % 3], kp = o1[(s1.corner + 2) % 3];
            const Offset& a2 = o2[(s2.corner + 1) % 3]; // t2 runs b -> a
            kq = o2[(s2.corner + 2) % 3];
            for (int x = 0; x < 3; ++x) kq[x] += ka[x] - a2[x];
        }
        const Vec3 xa = corner(a, ka), xb = corner(b, kb), xp = corner(p, kp), xq = corner(q, kq);
        if (angle_at(xp, xa, xb) + angle_at(xq, xb, xa) <= std::numbers::pi + 1e-12)
            return false;
        const auto normal = [](const Vec3& i, const Vec3& j, const Vec3& k) {
            return Vec3((j - i).cross(k - i));
        };
        const Vec3 before = normal(xa, xb, xp) + normal(xb, xa, xq);
        const Vec3 n1 = normal(xa, xq, xp), n2 = normal(xb, xp, xq);
        const double scale = before.norm();
        if (n1.dot(before) <= 1e-12 * scale * scale || n2.dot(before) <= 1e-12 * scale * scale)
            return false;
        t1 = {a, q, p};
        t2 = {b, p, q};
        if (c.periodic()) {
            offsets[s1.surface][s1.triangle] = {ka, kq, kp};
            offsets[s2.surface][s2.triangle] = {kb, kp, kq};
        }
        edges.erase(key(a, b));
        edges.insert(key(p, q));
        touched[s1.triangle] = touched[s2.triangle] = 1;
        return true;
    }

    /// One pass over the films' interior edges; a triangle flipped in this pass waits for the
    /// next (its sides are stale). Returns the flips made.
    int sweep() {
        std::map<EdgeKey, std::vector<Side>> sides;
        for (int s = 0; s < static_cast<int>(tris.size()); ++s)
            for (int i = 0; i < static_cast<int>(tris[s].size()); ++i)
                for (int k = 0; k < 3; ++k)
                    sides[key(tris[s][i][k], tris[s][i][(k + 1) % 3])].push_back({s, i, k});
        std::vector<std::vector<char>> touched(tris.size());
        for (std::size_t s = 0; s < tris.size(); ++s)
            touched[s].assign(tris[s].size(), 0);
        int flips = 0;
        for (const auto& [edge, list] : sides) {
            // Interior to one film: two sides of one surface and no other surface (a triple
            // line has three, a wall or wire edge one).
            if (list.size() != 2 || list[0].surface != list[1].surface) continue;
            std::vector<char>& mark = touched[list[0].surface];
            if (mark[list[0].triangle] || mark[list[1].triangle]) continue;
            flips += try_flip(list[0], list[1], mark);
        }
        return flips;
    }
};

} // namespace

EquiangulateResult equiangulate(const Cluster& c, int max_sweeps) {
    if (max_sweeps < 1)
        throw InvalidInput("equiangulate: max_sweeps must be at least 1, got " +
                           std::to_string(max_sweeps));
    Flipper f{c, {}, {}, {}};
    for (const Surface& s : c.surfaces()) {
        f.tris.push_back(s.triangles);
        f.offsets.push_back(s.offsets);
        for (const Tri& t : s.triangles)
            for (int k = 0; k < 3; ++k)
                f.edges.insert(key(t[k], t[(k + 1) % 3]));
    }
    EquiangulateResult r;
    for (; r.sweeps < max_sweeps; ++r.sweeps) {
        const int flips = f.sweep();
        if (flips == 0) break;
        r.flips += flips;
    }
    if (r.flips == 0) return r;
    ClusterSpec spec = cluster_spec(c);
    for (std::size_t s = 0; s < spec.surfaces.size(); ++s) {
        spec.surfaces[s].triangles = std::move(f.tris[s]);
        spec.surfaces[s].offsets = std::move(f.offsets[s]);
    }
    Cluster flipped(std::move(spec));
    if (flipped.n_bodies() != c.n_bodies())
        throw TopologyError("equiangulate: the flipped cluster has " +
                            std::to_string(flipped.n_bodies()) + " bodies, the original " +
                            std::to_string(c.n_bodies()));
    carry_over(c, flipped);
    r.cluster = std::move(flipped);
    return r;
}

} // namespace froth
