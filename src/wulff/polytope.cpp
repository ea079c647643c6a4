#include "wulff/polytope.h"

#include "core/errors.h"
#include "wulff/convex_hull.h"

#include <Eigen/QR>

#include <algorithm>
#include <numeric>
#include <string>
#include <unordered_map>

namespace froth {
namespace {

/// Union-find whose roots are the smallest members.
class UnionFind {
  public:
    explicit UnionFind(int n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
    int find(int i) {
        while (parent_[i] != i)
            i = parent_[i] = parent_[parent_[i]];
        return i;
    }
    void join(int a, int b) {
        a = find(a), b = find(b);
        if (a != b) parent_[std::max(a, b)] = std::min(a, b);
    }
    /// Class ids 0..count-1 per member, numbered in the order of their smallest members.
    std::vector<int> classes(int& count) {
        std::vector<int> id(parent_.size());
        count = 0;
        for (int i = 0; i < static_cast<int>(parent_.size()); ++i)
            id[i] = find(i) == i ? count++ : id[find(i)];
        return id;
    }

  private:
    std::vector<int> parent_;
};

using EdgeKey = long long;
EdgeKey edge_key(int a, int b) {
    return static_cast<EdgeKey>(a) << 32 | static_cast<unsigned>(b);
}

std::string prefix(const char* who) {
    return std::string(who) + ": ";
}

/// The hull triangles, oriented with 0 on the negative side of each (outward). The hull's own
/// orientation is consistent, so 0 is inside exactly when all exact signs agree.
std::vector<Tri> outward_hull(const std::vector<Vec3>& d, const char* who) {
    std::vector<Tri> tris = convex_hull_triangles(d, who);
    int sign = 0;
    for (const Tri& t : tris) {
        const int s = exact_orientation(d[t[0]], d[t[1]], d[t[2]], Vec3::Zero());
        if (s == 0 || (sign != 0 && s != sign))
            throw GeometryError(prefix(who) +
                                "the convex hull of the points p / gamma(p) is not consistently "
                                "oriented about 0 (directions that do not surround 0, or gamma "
                                "too close to crystalline for double precision)");
        sign = s;
    }
    if (sign > 0)
        for (Tri& t : tris)
            std::swap(t[1], t[2]);
    return tris;
}

/// The hull facet (0..count-1) of each triangle: neighbours across an edge belong to one facet
/// when the fourth point is coplanar with them, exactly or within `tol` (round-off: points of a
/// symmetric direction set that are coplanar in exact arithmetic are not after rounding).
std::vector<int> hull_facets(const std::vector<Vec3>& d, const std::vector<Tri>& tris, double tol,
                             int& count, const char* who) {
    std::unordered_map<EdgeKey, int> edge_tri;
    edge_tri.reserve(3 * tris.size());
    for (int t = 0; t < static_cast<int>(tris.size()); ++t)
        for (int e = 0; e < 3; ++e)
            edge_tri[edge_key(tris[t][e], tris[t][(e + 1) % 3])] = t;
    UnionFind facets(static_cast<int>(tris.size()));
    for (int t = 0; t < static_cast<int>(tris.size()); ++t) {
        const Tri& a = tris[t];
        const Vec3 n = (d[a[1]] - d[a[0]]).cross(d[a[2]] - d[a[0]]).normalized();
        for (int e = 0; e < 3; ++e) {
            const auto it = edge_tri.find(edge_key(a[(e + 1) % 3], a[e]));
            if (it == edge_tri.end())
                throw GeometryError(prefix(who) + "the convex hull is not closed");
            if (it->second < t) continue;
            const Tri& b = tris[it->second];
            const int opposite = b[0] + b[1] + b[2] - a[e] - a[(e + 1) % 3];
            if (std::abs(n.dot(d[opposite] - d[a[0]])) <= tol ||
                exact_orientation(d[a[0]], d[a[1]], d[a[2]], d[opposite]) == 0)
                facets.join(t, it->second);
        }
    }
    return facets.classes(count);
}

/// The vertex w of P polar to each hull facet: w . d = 1 on the facet's points, solved in the
/// least-squares sense over all of them (coplanar exactly or to round-off).
std::vector<Vec3> facet_vertices(const std::vector<Vec3>& d, const std::vector<Tri>& tris,
                                 const std::vector<int>& facet, int count) {
    std::vector<std::vector<int>> points(count);
    for (std::size_t t = 0; t < tris.size(); ++t)
        points[facet[t]].insert(points[facet[t]].end(), tris[t].begin(), tris[t].end());
    std::vector<Vec3> w(count);
    for (int f = 0; f < count; ++f) {
        std::vector<int>& ids = points[f];
        std::sort(ids.begin(), ids.end());
        ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
        Eigen::MatrixX3d A(ids.size(), 3);
        for (std::size_t i = 0; i < ids.size(); ++i)
            A.row(i) = d[ids[i]].transpose();
        w[f] = A.colPivHouseholderQr().solve(Eigen::VectorXd::Ones(A.rows()));
    }
    return w;
}

/// For each point on the hull, its hull triangles in counterclockwise order seen from outside:
/// after (k, x, y) comes the triangle (k, y, z). Empty for points inside the hull.
std::vector<std::vector<int>> vertex_rings(const std::vector<Tri>& tris, int n_points,
                                           const char* who) {
    struct Corner {
        int x, y, t;
    };
    std::vector<std::vector<Corner>> around(n_points);
    for (int t = 0; t < static_cast<int>(tris.size()); ++t)
        for (int c = 0; c < 3; ++c)
            around[tris[t][c]].push_back({tris[t][(c + 1) % 3], tris[t][(c + 2) % 3], t});
    std::vector<std::vector<int>> rings(n_points);
    for (int k = 0; k < n_points; ++k) {
        const std::vector<Corner>& cs = around[k];
        Corner cur = cs.empty() ? Corner{} : cs.front();
        for (std::size_t n = 0; n < cs.size(); ++n) {
            rings[k].push_back(cur.t);
            const auto next =
                std::find_if(cs.begin(), cs.end(), [&](const Corner& c) { return c.x == cur.y; });
            if (next == cs.end()) throw GeometryError(prefix(who) + "the hull is not closed");
            cur = *next;
        }
        if (!cs.empty() && cur.t != cs.front().t)
            throw GeometryError(prefix(who) + "the hull is not a closed surface at a vertex");
    }
    return rings;
}

/// Splits a cyclic vertex sequence at a repeated vertex into two cycles, recursively; cycles of
/// fewer than 3 vertices (an edge run both ways, left by a face that collapsed) are dropped.
/// The directed edges of the cycles kept are those of the input less such back-and-forth pairs,
/// so the surface stays closed.
void split_cycles(const std::vector<int>& cycle, std::vector<std::vector<int>>& out) {
    const int m = static_cast<int>(cycle.size());
    if (m < 3) return;
    for (int i = 0; i < m; ++i)
        for (int j = i + 1; j < m; ++j)
            if (cycle[i] == cycle[j]) {
                std::vector<int> inner(cycle.begin() + i, cycle.begin() + j);
                std::vector<int> outer(cycle.begin() + j, cycle.end());
                outer.insert(outer.end(), cycle.begin(), cycle.begin() + i);
                split_cycles(inner, out);
                split_cycles(outer, out);
                return;
            }
    out.push_back(cycle);
}

/// The polygons of the face polar to one hull point: the vertices (facets) around it in the
/// ring's (counterclockwise) order, without consecutive repeats. Usually one polygon; none when
/// the point is no corner of the hull (inside a facet or an edge), several if a facet touched it
/// twice (not seen; handled so that the surface stays closed).
std::vector<std::vector<int>> face_polygons(const std::vector<int>& ring,
                                            const std::vector<int>& facet) {
    std::vector<int> cycle;
    for (int t : ring) {
        const int v = facet[t];
        if (cycle.empty() || cycle.back() != v) cycle.push_back(v);
    }
    while (cycle.size() > 1 && cycle.front() == cycle.back())
        cycle.pop_back();
    std::vector<std::vector<int>> polygons;
    split_cycles(cycle, polygons);
    return polygons;
}

/// Appends the triangles of one convex face, given counterclockwise about `outward`: a
/// triangle as it is, larger polygons fanned from their centroid (no thin triangles from nearly
/// collinear consecutive vertices). A triangle whose normal does not point along `outward`
/// means the face's vertices are not resolved in double precision: GeometryError.
void add_face(TriangleSurface& out, const std::vector<int>& poly, const Vec3& outward,
              const char* who) {
    const int m = static_cast<int>(poly.size());
    std::vector<Tri> fan;
    if (m == 3) {
        fan.push_back({poly[0], poly[1], poly[2]});
    } else {
        Vec3 centroid = Vec3::Zero();
        for (int v : poly)
            centroid += out.vertices[v] / m;
        const int c = static_cast<int>(out.vertices.size());
        out.vertices.push_back(centroid);
        for (int i = 0; i < m; ++i)
            fan.push_back({c, poly[i], poly[(i + 1) % m]});
    }
    for (const Tri& t : fan) {
        const Vec3& a = out.vertices[t[0]];
        if ((out.vertices[t[1]] - a).cross(out.vertices[t[2]] - a).dot(outward) <= 0.0)
            throw GeometryError(prefix(who) +
                                "a face of the polytope folded over: its vertices are not resolved "
                                "in double precision (gamma too close to crystalline for this "
                                "many directions); use fewer directions");
        out.triangles.push_back(t);
    }
}

/// Removes vertices in no triangle (all of whose faces were dropped) and renumbers.
void drop_unused(TriangleSurface& s) {
    std::vector<int> id(s.vertices.size(), -1);
    for (const Tri& t : s.triangles)
        for (int v : t)
            id[v] = 0;
    int n = 0;
    for (std::size_t v = 0; v < s.vertices.size(); ++v)
        if (id[v] == 0) s.vertices[n] = s.vertices[v], id[v] = n++;
    s.vertices.resize(n);
    for (Tri& t : s.triangles)
        for (int& v : t)
            v = id[v];
}

/// Every directed edge once and its reverse once: a closed, consistently oriented surface.
void check_closed(const TriangleSurface& s, const char* who) {
    std::unordered_map<EdgeKey, int> count;
    count.reserve(3 * s.triangles.size());
    for (const Tri& t : s.triangles)
        for (int e = 0; e < 3; ++e)
            ++count[edge_key(t[e], t[(e + 1) % 3])];
    for (const Tri& t : s.triangles)
        for (int e = 0; e < 3; ++e) {
            const auto back = count.find(edge_key(t[(e + 1) % 3], t[e]));
            if (count[edge_key(t[e], t[(e + 1) % 3])] != 1 || back == count.end() ||
                back->second != 1)
                throw GeometryError(prefix(who) + "the polytope's surface is not closed");
        }
}

/// The engine's zero-area test (Cluster::check_spec), so that a result is never rejected there.
void check_areas(const TriangleSurface& s, const char* who) {
    for (std::size_t i = 0; i < s.triangles.size(); ++i) {
        const Tri& t = s.triangles[i];
        const Vec3 e1 = s.vertices[t[1]] - s.vertices[t[0]];
        const Vec3 e2 = s.vertices[t[2]] - s.vertices[t[0]];
        const double scale =
            std::max({e1.squaredNorm(), e2.squaredNorm(), (e2 - e1).squaredNorm()});
        if (e1.cross(e2).norm() <= 1e-12 * scale)
            throw GeometryError(prefix(who) + "facet " + std::to_string(i + 1) +
                                " of the polytope has no area in double precision (gamma too "
                                "close to crystalline for this many directions); use fewer");
    }
}

} // namespace

TriangleSurface polar_polytope(const std::vector<Vec3>& d, double coplanar_tol, const char* who) {
    const std::vector<Tri> tris = outward_hull(d, who);
    double radius = 0.0;
    for (const Vec3& x : d)
        radius = std::max(radius, x.norm());
    int n_facets = 0;
    const std::vector<int> facet = hull_facets(d, tris, coplanar_tol * radius, n_facets, who);
    TriangleSurface out;
    out.vertices = facet_vertices(d, tris, facet, n_facets);
    const std::vector<std::vector<int>> rings = vertex_rings(tris, static_cast<int>(d.size()), who);
    // The ring order is exact (combinatorial); a normal computed from the vertices is not where
    // nearly coplanar hull facets give nearby vertices.
    for (std::size_t k = 0; k < d.size(); ++k)
        for (const std::vector<int>& poly : face_polygons(rings[k], facet))
            add_face(out, poly, d[k], who);
    drop_unused(out);
    check_closed(out, who);
    check_areas(out, who);
    return out;
}

} // namespace froth
