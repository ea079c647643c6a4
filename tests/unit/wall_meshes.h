#pragma once
// Hand-made meshes and small helpers for the wall tests (walls_test.cpp, wall_steps_test.cpp):
// open boxes, surfaces of revolution (cups, frusta, domes), tubes, and walls to attach.
#include "mesh/cluster.h"
#include "mesh/walls.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace froth::wall_test {

// ---------------------------------------------------------------------------------------------
// Meshes

/// Builds a ClusterSpec from faces given as point grids, merging coincident points.
class SpecBuilder {
  public:
    int vertex(const Vec3& x) {
        const std::array<long long, 3> key = {std::llround(x.x() * 1e9), std::llround(x.y() * 1e9),
                                              std::llround(x.z() * 1e9)};
        const auto it = index_.find(key);
        if (it != index_.end()) return it->second;
        spec.vertices.push_back(x);
        return index_[key] = static_cast<int>(spec.vertices.size()) - 1;
    }
    /// An n x n grid on the parallelogram p0 + [0,1] u + [0,1] v, normal u x v, into surface s.
    void quad_grid(int s, const Vec3& p0, const Vec3& u, const Vec3& v, int n) {
        surface(s);
        auto at = [&](int i, int j) {
            return vertex(p0 + (double(i) / n) * u + (double(j) / n) * v);
        };
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                const int a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
                spec.surfaces[s].triangles.push_back({a, b, c});
                spec.surfaces[s].triangles.push_back({a, c, d});
            }
    }
    void surface(int s) {
        while (static_cast<int>(spec.surfaces.size()) <= s)
            spec.surfaces.push_back({{}, 1.0});
    }
    ClusterSpec spec;

  private:
    std::map<std::array<long long, 3>, int> index_;
};

enum BoxFace { kXlo = 1, kXhi = 2, kYlo = 4, kYhi = 8, kZlo = 16, kZhi = 32, kAll = 63 };

/// The faces in `faces` of the box [lo, hi], each an n x n grid of triangle pairs, outward
/// normals, all in surface 0 (or face k in surface k when `separate`); one body {all surfaces}.
inline ClusterSpec box(const Vec3& lo, const Vec3& hi, int n, int faces = kAll,
                       bool separate = false) {
    SpecBuilder b;
    const Vec3 d = hi - lo;
    const Vec3 dx(d.x(), 0, 0), dy(0, d.y(), 0), dz(0, 0, d.z());
    int s = 0;
    auto face = [&](int bit, const Vec3& p0, const Vec3& u, const Vec3& v) {
        if (!(faces & bit)) return;
        b.quad_grid(separate ? s++ : 0, p0, u, v, n);
    };
    face(kXlo, lo, dz, dy);
    face(kXhi, lo + dx, dy, dz);
    face(kYlo, lo, dx, dz);
    face(kYhi, lo + dy, dz, dx);
    face(kZlo, lo, dy, dx);
    face(kZhi, lo + dz, dx, dy);
    ClusterSpec spec = std::move(b.spec);
    std::vector<int> all;
    for (int i = 0; i < static_cast<int>(spec.surfaces.size()); ++i)
        all.push_back(i);
    spec.bodies = {all};
    return spec;
}

/// A surface of revolution about the z axis: rings (rho_j, z_j) of K vertices each (every other
/// ring turned by half a step), closed by an apex at (0, z_apex) on the axis unless z_apex is
/// NaN (then open at both ends). Normals point away from the axis where the profile rises
/// (cross(theta, profile)).
inline ClusterSpec revolution(const std::vector<std::array<double, 2>>& rings, double z_apex,
                              int K) {
    ClusterSpec s;
    const int J = static_cast<int>(rings.size());
    for (int j = 0; j < J; ++j)
        for (int k = 0; k < K; ++k) {
            const double th = 2 * M_PI * (k + 0.5 * (j % 2)) / K;
            s.vertices.push_back(
                Vec3(rings[j][0] * std::cos(th), rings[j][0] * std::sin(th), rings[j][1]));
        }
    const bool closed = !std::isnan(z_apex);
    if (closed) s.vertices.push_back(Vec3(0, 0, z_apex));
    auto id = [&](int j, int k) { return j * K + (k % K); };
    std::vector<Tri> t;
    for (int j = 0; j + 1 < J; ++j)
        for (int k = 0; k < K; ++k) {
            if (j % 2 == 0) { // ring j+1 is turned by +half a step
                t.push_back({id(j, k), id(j, k + 1), id(j + 1, k)});
                t.push_back({id(j, k + 1), id(j + 1, k + 1), id(j + 1, k)});
            } else { // ring j is turned by +half a step
                t.push_back({id(j, k), id(j + 1, k + 1), id(j + 1, k)});
                t.push_back({id(j, k), id(j, k + 1), id(j + 1, k + 1)});
            }
        }
    const int apex = J * K;
    if (closed)
        for (int k = 0; k < K; ++k)
            t.push_back({id(J - 1, k), id(J - 1, k + 1), apex});
    s.surfaces.push_back({t, 1.0});
    s.bodies = {{0}};
    return s;
}

/// A cup: the cylinder rho = R from z = z0 to z0 + H (m rings up the side) closed by a flat
/// top (rings shrinking to the apex). Open at z = z0.
inline ClusterSpec cup(double R, double H, int m, int K, double z0 = 0) {
    std::vector<std::array<double, 2>> rings;
    for (int j = 0; j <= m; ++j)
        rings.push_back({R, z0 + H * j / m});
    for (int j = 1; j < m; ++j)
        rings.push_back({R * (1 - double(j) / m), z0 + H});
    return revolution(rings, z0 + H, K);
}

/// The frustum from radius R0 at z = 0 to radius R1 at z = H (m rings), flat top.
inline ClusterSpec frustum(double R0, double R1, double H, int m, int K) {
    std::vector<std::array<double, 2>> rings;
    for (int j = 0; j <= m; ++j)
        rings.push_back({R0 + (R1 - R0) * j / m, H * j / m});
    for (int j = 1; j < m; ++j)
        rings.push_back({R1 * (1 - double(j) / m), H});
    return revolution(rings, H, K);
}

/// The tube: the four side faces of the box [lo, hi], open at both ends.
inline ClusterSpec tube(const Vec3& lo, const Vec3& hi, int n) {
    return box(lo, hi, n, kXlo | kXhi | kYlo | kYhi);
}

/// Drops the vertices no facet uses and renumbers the rest by first use.
inline ClusterSpec compact(ClusterSpec s) {
    std::vector<int> id(s.vertices.size(), -1);
    std::vector<Vec3> X;
    for (auto& surface : s.surfaces)
        for (Tri& t : surface.triangles)
            for (int& v : t) {
                if (id[v] < 0) id[v] = static_cast<int>(X.size()), X.push_back(s.vertices[v]);
                v = id[v];
            }
    s.vertices = std::move(X);
    return s;
}

/// The unit-ish box [0, size] without its faces x = 0 and z = 0, in the corner of those planes.
inline ClusterSpec corner_box(const Vec3& size, int n) {
    ClusterSpec s = compact(box(Vec3::Zero(), size, n, kAll & ~kZlo & ~kXlo));
    s.walls = {make_plane(Vec3::UnitX(), 0), make_plane(Vec3::UnitZ(), 0)};
    return s;
}

inline ClusterSpec with_walls(ClusterSpec s, std::vector<WallPtr> walls) {
    s.walls = std::move(walls);
    return s;
}

/// The message of the exception that f throws as E (fails if it throws nothing or another type).
template <class E, class F> inline std::string message_of(F&& f) {
    try {
        f();
    } catch (const E& e) {
        return e.what();
    }
    ADD_FAILURE() << "no exception of the expected type";
    return "";
}

inline bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

inline WallPtr floor_plane(double z = 0) {
    return make_plane(Vec3::UnitZ(), z);
}

} // namespace froth::wall_test
