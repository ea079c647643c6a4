// External boundaries (seed (1.25), (3.10), (3.11); numerics.md §1, §3): the preset and function
// walls, attaching free boundary edges to walls when a cluster is made, lids closing body
// volumes on walls, the tangent bases T_v of PositionBasis, both flows with walls against dense
// solves, drift off curved walls and its projection, drop_wall_lids, and contact angles.
// Every mesh is built here by hand (no gmsh).
#include "assembly/flow_systems.h"
#include "assembly/kappa_basis.h"
#include "assembly/position_basis.h"
#include "core/errors.h"
#include "flows/stepper.h"
#include "geometry/geometry.h"
#include "mesh/walls.h"
#include "test_meshes.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

namespace froth {
namespace {

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
ClusterSpec box(const Vec3& lo, const Vec3& hi, int n, int faces = kAll, bool separate = false) {
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
ClusterSpec revolution(const std::vector<std::array<double, 2>>& rings, double z_apex, int K) {
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
ClusterSpec cup(double R, double H, int m, int K, double z0 = 0) {
    std::vector<std::array<double, 2>> rings;
    for (int j = 0; j <= m; ++j)
        rings.push_back({R, z0 + H * j / m});
    for (int j = 1; j < m; ++j)
        rings.push_back({R * (1 - double(j) / m), z0 + H});
    return revolution(rings, z0 + H, K);
}

/// The frustum from radius R0 at z = 0 to radius R1 at z = H (m rings), flat top.
ClusterSpec frustum(double R0, double R1, double H, int m, int K) {
    std::vector<std::array<double, 2>> rings;
    for (int j = 0; j <= m; ++j)
        rings.push_back({R0 + (R1 - R0) * j / m, H * j / m});
    for (int j = 1; j < m; ++j)
        rings.push_back({R1 * (1 - double(j) / m), H});
    return revolution(rings, H, K);
}

/// The tube: the four side faces of the box [lo, hi], open at both ends.
ClusterSpec tube(const Vec3& lo, const Vec3& hi, int n) {
    return box(lo, hi, n, kXlo | kXhi | kYlo | kYhi);
}

/// Drops the vertices no facet uses and renumbers the rest by first use.
ClusterSpec compact(ClusterSpec s) {
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
ClusterSpec corner_box(const Vec3& size, int n) {
    ClusterSpec s = compact(box(Vec3::Zero(), size, n, kAll & ~kZlo & ~kXlo));
    s.walls = {make_plane(Vec3::UnitX(), 0), make_plane(Vec3::UnitZ(), 0)};
    return s;
}

ClusterSpec with_walls(ClusterSpec s, std::vector<WallPtr> walls) {
    s.walls = std::move(walls);
    return s;
}

/// The message of the exception that f throws as E (fails if it throws nothing or another type).
template <class E, class F> std::string message_of(F&& f) {
    try {
        f();
    } catch (const E& e) {
        return e.what();
    }
    ADD_FAILURE() << "no exception of the expected type";
    return "";
}

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

WallPtr floor_plane(double z = 0) {
    return make_plane(Vec3::UnitZ(), z);
}

// ---------------------------------------------------------------------------------------------
// The walls

TEST(Walls, PlaneValuesGradientDistanceNormalProject) {
    // The normal is normalised and the offset is then the signed distance of the plane from
    // the origin: {normal (0, 0, 2), offset 3} is the plane z = 3.
    const WallPtr w = make_plane(Vec3(0, 0, 2), 3);
    EXPECT_DOUBLE_EQ(w->value(Vec3(1, 2, 5)), 2.0);
    EXPECT_DOUBLE_EQ(w->value(Vec3(-4, 7, 3)), 0.0);
    EXPECT_EQ(w->gradient(Vec3(1, 2, 5)), Vec3(0, 0, 1));
    EXPECT_DOUBLE_EQ(w->distance(Vec3(1, 2, 1)), 2.0);
    EXPECT_EQ(w->normal(Vec3(9, 9, 9)), Vec3(0, 0, 1));
    EXPECT_LT((w->project(Vec3(1, 2, 5)) - Vec3(1, 2, 3)).norm(), 1e-15);
    EXPECT_TRUE(w->is_flat());
    EXPECT_TRUE(contains(w->describe(), "plane")) << w->describe();

    const WallPtr tilted = make_plane(Vec3(1, 1, 0), std::sqrt(2.0)); // x + y = 2
    const Vec3 p = tilted->project(Vec3(3, 3, 4));
    EXPECT_LT((p - Vec3(1, 1, 4)).norm(), 1e-14);
    EXPECT_LT(std::abs(tilted->value(p)), 1e-15);
    EXPECT_NEAR(tilted->distance(Vec3(0, 0, 0)), std::sqrt(2.0), 1e-15);
    EXPECT_LT((tilted->normal(Vec3::Zero()) - Vec3(1, 1, 0) / std::sqrt(2.0)).norm(), 1e-15);
}

TEST(Walls, SlabIsTwoPlanes) {
    const WallPtr w = make_slab(Vec3(0, 0, 1), -1, 2); // -1 <= z <= 2, middle 0.5
    EXPECT_TRUE(w->is_flat());
    EXPECT_DOUBLE_EQ(w->value(Vec3(0, 0, 0)), 1.0);   // 1 from the lower plane
    EXPECT_DOUBLE_EQ(w->value(Vec3(5, 1, 1.5)), 0.5); // 0.5 from the upper plane
    EXPECT_DOUBLE_EQ(w->value(Vec3(0, 0, 3)), -1.0);  // outside, above
    EXPECT_DOUBLE_EQ(w->value(Vec3(0, 0, -1)), 0.0);
    EXPECT_DOUBLE_EQ(w->value(Vec3(0, 0, 2)), 0.0);
    EXPECT_EQ(w->gradient(Vec3(0, 0, 0)), Vec3(0, 0, 1));    // into the slab from below
    EXPECT_EQ(w->gradient(Vec3(0, 0, 1.5)), Vec3(0, 0, -1)); // into the slab from above
    EXPECT_DOUBLE_EQ(w->distance(Vec3(0, 0, 0.2)), 1.2);
    EXPECT_DOUBLE_EQ(w->distance(Vec3(0, 0, 3)), 1.0);
    EXPECT_DOUBLE_EQ(w->distance(Vec3(0, 0, -4)), 3.0);
    EXPECT_LT((w->project(Vec3(1, 2, 0.2)) - Vec3(1, 2, -1)).norm(), 1e-15);
    EXPECT_LT((w->project(Vec3(1, 2, 1.5)) - Vec3(1, 2, 2)).norm(), 1e-15);
    EXPECT_LT((w->project(Vec3(1, 2, 3)) - Vec3(1, 2, 2)).norm(), 1e-15);
    EXPECT_LT((w->project(Vec3(1, 2, -4)) - Vec3(1, 2, -1)).norm(), 1e-15);
    EXPECT_EQ(w->normal(Vec3(0, 0, 1.9)), Vec3(0, 0, -1));
}

TEST(Walls, SphereWall) {
    const WallPtr w = make_sphere_wall(Vec3(1, 0, 0), 2);
    EXPECT_FALSE(w->is_flat());
    EXPECT_DOUBLE_EQ(w->value(Vec3(1, 0, 3)), 1.0);
    EXPECT_DOUBLE_EQ(w->value(Vec3(3, 0, 0)), 0.0);
    EXPECT_DOUBLE_EQ(w->value(Vec3(1, 0, 0)), -2.0);
    EXPECT_LT((w->gradient(Vec3(1, 0, 3)) - Vec3(0, 0, 1)).norm(), 1e-15);
    EXPECT_DOUBLE_EQ(w->distance(Vec3(1, 0.5, 0)), 1.5);
    const Vec3 x(2, 1, 1);
    EXPECT_NEAR(w->distance(x), std::abs(std::sqrt(3.0) - 2), 1e-15);
    EXPECT_LT((w->normal(x) - Vec3(1, 1, 1) / std::sqrt(3.0)).norm(), 1e-15);
    const Vec3 p = w->project(x);
    EXPECT_LT((p - (Vec3(1, 0, 0) + 2 * Vec3(1, 1, 1) / std::sqrt(3.0))).norm(), 1e-14);
    EXPECT_LT(std::abs(w->value(p)), 1e-14);
    // grad F vanishes at the center: no normal there.
    EXPECT_THROW(w->normal(Vec3(1, 0, 0)), GeometryError);
}

TEST(Walls, CylinderWall) {
    const WallPtr w = make_cylinder_wall(Vec3(0, 0, 1), Vec3(0, 0, 5), 1); // axis normalised
    EXPECT_FALSE(w->is_flat());
    EXPECT_DOUBLE_EQ(w->value(Vec3(3, 4, 7)), 4.0);
    EXPECT_DOUBLE_EQ(w->value(Vec3(0, 1, -3)), 0.0);
    EXPECT_LT((w->gradient(Vec3(3, 4, 7)) - Vec3(0.6, 0.8, 0)).norm(), 1e-15);
    EXPECT_DOUBLE_EQ(w->distance(Vec3(0.5, 0, 2)), 0.5);
    EXPECT_LT((w->normal(Vec3(0, -2, 9)) - Vec3(0, -1, 0)).norm(), 1e-15);
    const Vec3 p = w->project(Vec3(3, 4, 7));
    EXPECT_LT((p - Vec3(0.6, 0.8, 7)).norm(), 1e-14);
    EXPECT_LT(std::abs(w->value(p)), 1e-14);
    // A tilted axis: the cylinder of radius 1 about the line x = y = z.
    const WallPtr t = make_cylinder_wall(Vec3::Zero(), Vec3(1, 1, 1), 1);
    const Vec3 q(2, 0, 0); // radial part (2, 0, 0) - 2/3 (1, 1, 1), length sqrt(8/3)
    EXPECT_NEAR(t->value(q), std::sqrt(8.0 / 3.0) - 1, 1e-15);
    const Vec3 pq = t->project(q);
    EXPECT_LT(std::abs(t->value(pq)), 1e-14);
    EXPECT_NEAR((pq - q).dot(Vec3(1, 1, 1)), 0, 1e-14); // moved perpendicularly to the axis
}

TEST(Walls, FunctionWallWithFiniteDifferenceGradient) {
    // F = |x|^2 - 4: the sphere of radius 2, with |grad F| = 4 on it (not a distance function).
    auto F = [](const Vec3& x) { return x.squaredNorm() - 4; };
    const WallPtr w = make_function_wall(F, nullptr, "ball");
    const Vec3 x(1, 1, 1);
    EXPECT_DOUBLE_EQ(w->value(x), -1.0);
    EXPECT_LT((w->gradient(x) - 2 * x).norm(), 1e-8); // central differences: exact up to round-off
    const Vec3 y(0.3, -1.7, 2.2);
    EXPECT_LT((w->gradient(y) - 2 * y).norm(), 1e-8);
    EXPECT_NEAR(w->distance(x), 1 / std::sqrt(12.0), 1e-9); // first order: |F| / |grad F|
    EXPECT_LT((w->normal(x) - x.normalized()).norm(), 1e-9);
    const Vec3 p = w->project(x);
    EXPECT_NEAR(p.norm(), 2.0, 1e-12);
    EXPECT_LT((p.normalized() - x.normalized()).norm(), 1e-9);
    EXPECT_TRUE(contains(w->describe(), "ball")) << w->describe();
    EXPECT_FALSE(w->is_flat());

    // A coarser step still gives the gradient to O(step^2) (F is quadratic: exact).
    const WallPtr coarse = make_function_wall(F, nullptr, "coarse", 1e-2);
    EXPECT_LT((coarse->gradient(y) - 2 * y).norm(), 1e-10);
}

TEST(Walls, FunctionWallWithAnalyticGradient) {
    int gradient_calls = 0;
    const WallPtr w = make_function_wall([](const Vec3& x) { return x.z() - 0.1 * x.x() * x.x(); },
                                         [&](const Vec3& x) {
                                             ++gradient_calls;
                                             return Vec3(-0.2 * x.x(), 0, 1);
                                         },
                                         "parabola");
    EXPECT_EQ(w->gradient(Vec3(1, 0, 0)), Vec3(-0.2, 0, 1));
    EXPECT_EQ(gradient_calls, 1);
    const Vec3 p = w->project(Vec3(1, 0, 1));
    EXPECT_LT(std::abs(w->value(p)), 1e-14);
}

TEST(Walls, FunctionWallRejectsNonFiniteValues) {
    const WallPtr nan_wall = make_function_wall([](const Vec3&) { return NAN; }, nullptr, "nan");
    const std::string m = message_of<GeometryError>([&] { nan_wall->value(Vec3(1, 2, 3)); });
    EXPECT_TRUE(contains(m, "wall 'nan'")) << m;
    EXPECT_TRUE(contains(m, "(1, 2, 3)")) << m;
    EXPECT_THROW(nan_wall->distance(Vec3(1, 2, 3)), GeometryError);
    EXPECT_THROW(nan_wall->gradient(Vec3(1, 2, 3)), GeometryError); // differences of NaN
    EXPECT_THROW(nan_wall->project(Vec3(1, 2, 3)), GeometryError);
    const WallPtr inf_wall = make_function_wall(
        [](const Vec3& x) { return x.z() > 0 ? INFINITY : x.z(); }, nullptr, "inf");
    EXPECT_NO_THROW(inf_wall->value(Vec3(0, 0, -1)));
    EXPECT_THROW(inf_wall->value(Vec3(0, 0, 1)), GeometryError);
    const WallPtr bad_gradient =
        make_function_wall([](const Vec3& x) { return x.z(); },
                           [](const Vec3&) { return Vec3(0, NAN, 1); }, "bad gradient");
    const std::string g = message_of<GeometryError>([&] { bad_gradient->gradient(Vec3::Zero()); });
    EXPECT_TRUE(contains(g, "grad F")) << g;
    // grad F = 0 on the wall: no tangent plane.
    const WallPtr flat =
        make_function_wall([](const Vec3& x) { return x.z() * x.z(); },
                           [](const Vec3& x) { return Vec3(0, 0, 2 * x.z()); }, "double root");
    EXPECT_THROW(flat->normal(Vec3(1, 1, 0)), GeometryError);
    // No zero at all: Newton cannot converge.
    const WallPtr none =
        make_function_wall([](const Vec3& x) { return x.squaredNorm() + 1; }, nullptr, "no zero");
    EXPECT_THROW(none->project(Vec3(1, 0, 0)), GeometryError);
}

TEST(Walls, ConstructorsRejectBadInput) {
    EXPECT_THROW(make_plane(Vec3::Zero(), 0), InvalidInput);
    EXPECT_THROW(make_plane(Vec3(NAN, 0, 1), 0), InvalidInput);
    EXPECT_THROW(make_plane(Vec3(0, 0, 1), INFINITY), InvalidInput);
    EXPECT_THROW(make_slab(Vec3::Zero(), 0, 1), InvalidInput);
    EXPECT_THROW(make_slab(Vec3::UnitZ(), 1, 1), InvalidInput);
    EXPECT_THROW(make_slab(Vec3::UnitZ(), 2, 1), InvalidInput);
    EXPECT_THROW(make_slab(Vec3::UnitZ(), NAN, 1), InvalidInput);
    EXPECT_THROW(make_slab(Vec3::UnitZ(), 0, INFINITY), InvalidInput);
    EXPECT_THROW(make_sphere_wall(Vec3::Zero(), 0), InvalidInput);
    EXPECT_THROW(make_sphere_wall(Vec3::Zero(), -1), InvalidInput);
    EXPECT_THROW(make_sphere_wall(Vec3::Zero(), NAN), InvalidInput);
    EXPECT_THROW(make_sphere_wall(Vec3(INFINITY, 0, 0), 1), InvalidInput);
    EXPECT_THROW(make_cylinder_wall(Vec3::Zero(), Vec3::UnitZ(), 0), InvalidInput);
    EXPECT_THROW(make_cylinder_wall(Vec3::Zero(), Vec3::UnitZ(), -2), InvalidInput);
    EXPECT_THROW(make_cylinder_wall(Vec3::Zero(), Vec3::Zero(), 1), InvalidInput);
    EXPECT_THROW(make_cylinder_wall(Vec3(0, NAN, 0), Vec3::UnitZ(), 1), InvalidInput);
    EXPECT_THROW(make_function_wall(nullptr, nullptr, "f"), InvalidInput);
    EXPECT_THROW(make_function_wall([](const Vec3&) { return 0.0; }, nullptr, "f", 0),
                 InvalidInput);
    EXPECT_THROW(make_function_wall([](const Vec3&) { return 0.0; }, nullptr, "f", -1e-6),
                 InvalidInput);
    const std::string m = message_of<InvalidInput>([] { make_slab(Vec3::UnitZ(), 2, 1); });
    EXPECT_TRUE(contains(m, "slab")) << m;
}

// ---------------------------------------------------------------------------------------------
// Attaching films to walls when a cluster is made

TEST(WallAttachment, FreeBoundaryEdgeWithoutWallsIsNamed) {
    ClusterSpec s = box(Vec3::Zero(), Vec3(1, 1, 1), 1, kAll & ~kZlo);
    const std::string m = message_of<TopologyError>([&] { Cluster c(s); });
    EXPECT_TRUE(contains(m, "free boundary edge")) << m;
    EXPECT_TRUE(contains(m, "edge ")) << m;
    EXPECT_TRUE(contains(m, "surface 1")) << m;
    // The named edge is a bottom edge of the box (both ends at z = 0).
    int a = 0, b = 0;
    ASSERT_EQ(std::sscanf(m.substr(m.find("edge ")).c_str(), "edge %d-%d", &a, &b), 2) << m;
    ASSERT_TRUE(a >= 1 && b >= 1 && a <= int(s.vertices.size()) && b <= int(s.vertices.size()));
    EXPECT_EQ(s.vertices[a - 1].z(), 0.0) << m;
    EXPECT_EQ(s.vertices[b - 1].z(), 0.0) << m;
}

TEST(WallAttachment, BoundaryVertexOffEveryWallIsNamedWithTheNearestDistance) {
    ClusterSpec s = box(Vec3::Zero(), Vec3(1, 1, 1), 2, kAll & ~kZlo);
    // Lift one bottom corner 0.25 off the floor.
    int lifted = -1;
    for (int v = 0; v < static_cast<int>(s.vertices.size()); ++v)
        if (s.vertices[v] == Vec3(1, 0, 0)) lifted = v;
    ASSERT_GE(lifted, 0);
    s.vertices[lifted].z() = 0.25;
    s.walls = {make_plane(Vec3::UnitX(), -5), floor_plane()}; // the floor is wall 2, nearer
    const std::string m = message_of<TopologyError>([&] { Cluster c(s); });
    EXPECT_TRUE(contains(m, "vertex " + std::to_string(lifted + 1) + " ")) << m;
    EXPECT_TRUE(contains(m, "on no wall")) << m;
    EXPECT_TRUE(contains(m, "wall 2")) << m;
    EXPECT_TRUE(contains(m, "distance 0.25")) << m;
}

TEST(WallAttachment, VertexFreedomOnOneAndTwoWalls) {
    // The unit cube without its faces x = 0 and z = 0, in the corner of those two planes; the
    // vertex (0, 0.5, 0) belonged to the removed faces only and is gone.
    const ClusterSpec t = corner_box(Vec3(1, 1, 1), 2);
    const Cluster c(t);
    EXPECT_TRUE(c.has_walls());
    int on_two = 0, on_one = 0, inner = 0;
    for (int v = 0; v < c.n_vertices(); ++v) {
        const Vec3& x = c.position(v);
        const bool on_x = x.x() == 0, on_z = x.z() == 0;
        const std::vector<int> w = c.vertex_walls(v);
        if (on_x && on_z) {
            ++on_two;
            EXPECT_EQ(c.vertex_freedom(v), 1) << x.transpose();
            EXPECT_EQ(w, (std::vector<int>{0, 1})) << x.transpose();
        } else if (on_x || on_z) {
            ++on_one;
            EXPECT_EQ(c.vertex_freedom(v), 2) << x.transpose();
            EXPECT_EQ(w, std::vector<int>{on_x ? 0 : 1}) << x.transpose();
        } else {
            ++inner;
            EXPECT_EQ(c.vertex_freedom(v), 3) << x.transpose();
            EXPECT_TRUE(w.empty()) << x.transpose();
        }
    }
    EXPECT_EQ(on_two, 2);  // (0, 0, 0) and (0, 1, 0)
    EXPECT_EQ(on_one, 10); // 5 more on each plane
    EXPECT_GT(inner, 0);
    EXPECT_EQ(c.boundary_edges().size(), 12u);
}

TEST(WallAttachment, InteriorVertexOnAWallStaysFree) {
    // The plane x = 0.5 passes through the top face's middle row; only boundary vertices attach.
    ClusterSpec s = box(Vec3::Zero(), Vec3(1, 1, 1), 2, kAll & ~kZlo);
    s.walls = {floor_plane(), make_plane(Vec3::UnitX(), 0.5)};
    const Cluster c(s);
    for (int v = 0; v < c.n_vertices(); ++v)
        if (c.position(v) == Vec3(0.5, 0.5, 1)) {
            EXPECT_EQ(c.vertex_freedom(v), 3);
            EXPECT_TRUE(c.vertex_walls(v).empty());
        }
}

TEST(WallAttachment, VertexOnThreeWallsCannotMove) {
    ClusterSpec s = box(Vec3::Zero(), Vec3(1, 1, 1), 1, kAll & ~kZlo);
    s.walls = {floor_plane(), make_plane(Vec3::UnitX(), 0), make_plane(Vec3::UnitY(), 0)};
    const std::string m = message_of<TopologyError>([&] { Cluster c(s); });
    EXPECT_TRUE(contains(m, "could not move")) << m;
}

TEST(WallAttachment, BoundaryEdgeBetweenTwoWallsIsRejected) {
    // Every bottom corner is on x = 0 or x = 1, but the edges along x join the two walls.
    ClusterSpec s = box(Vec3::Zero(), Vec3(1, 1, 1), 1, kAll & ~kZlo);
    s.walls = {make_plane(Vec3::UnitX(), 0), make_plane(Vec3::UnitX(), 1)};
    const std::string m = message_of<TopologyError>([&] { Cluster c(s); });
    EXPECT_TRUE(contains(m, "different walls")) << m;
}

TEST(WallAttachment, ClosedClusterWithWallsHasNoAttachedVertices) {
    ClusterSpec s = test::icosphere(1);
    s.walls = {floor_plane(-5)};
    const Cluster c(s);
    EXPECT_FALSE(c.has_walls());
    EXPECT_EQ(c.walls().size(), 1u);
    EXPECT_TRUE(c.boundary_edges().empty());
    for (int v = 0; v < c.n_vertices(); ++v)
        EXPECT_EQ(c.vertex_freedom(v), 3);
    EXPECT_EQ(contact_angles(c).count, 0);
    EXPECT_EQ(wall_drift(c), 0.0);
    const PositionBasis P(c);
    EXPECT_EQ(P.size(), 3 * c.n_vertices());
}

TEST(WallAttachment, NullWallIsInvalidInput) {
    ClusterSpec s = box(Vec3::Zero(), Vec3(1, 1, 1), 1, kAll & ~kZlo);
    s.walls = {floor_plane(), nullptr};
    EXPECT_THROW(Cluster c(s), InvalidInput);
}

// ---------------------------------------------------------------------------------------------
// Volumes closed by lids

double closed_volume(const Vec3& lo, const Vec3& hi, int n) {
    return body_volumes(Cluster(box(lo, hi, n)))[0];
}

TEST(Lids, OpenBoxOnTheFloorHasItsClosedVolume) {
    const Vec3 lo(0, 0, 0), hi(1.5, 1, 0.75);
    const Cluster c(with_walls(box(lo, hi, 3, kAll & ~kZlo), {floor_plane()}));
    ASSERT_EQ(c.n_bodies(), 1);
    EXPECT_EQ(c.bodies()[0].lids.size(), 1u);
    EXPECT_NEAR(body_volumes(c)[0], closed_volume(lo, hi, 3), 1e-14);
    EXPECT_NEAR(body_volumes(c)[0], 1.5 * 0.75, 1e-14);
    EXPECT_NEAR(c.initial_volumes()[0], 1.5 * 0.75, 1e-14);
}

TEST(Lids, LidOffTheOriginIsCounted) {
    // The plane z = 1 does not pass through the origin: the lid's fan adds a real volume.
    const Vec3 lo(0.3, -0.2, 1), hi(1.3, 0.8, 2.5);
    const double exact = 1.5;
    const Cluster up(with_walls(box(lo, hi, 2, kAll & ~kZlo), {floor_plane(1)}));
    EXPECT_NEAR(body_volumes(up)[0], exact, 1e-14);
    EXPECT_NEAR(closed_volume(lo, hi, 2), exact, 1e-14);
    // The same plane with the opposite normal.
    const Cluster down(with_walls(box(lo, hi, 2, kAll & ~kZlo), {make_plane(-Vec3::UnitZ(), -1)}));
    EXPECT_NEAR(body_volumes(down)[0], exact, 1e-14);
    // Hanging from a ceiling z = 2.5 (the top face is the lid).
    const Cluster hung(with_walls(box(lo, hi, 2, kAll & ~kZhi), {floor_plane(2.5)}));
    EXPECT_NEAR(body_volumes(hung)[0], exact, 1e-14);
    // A rigid motion of the box and its wall keeps the volume.
    const Eigen::Matrix3d R =
        (Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized())).toRotationMatrix();
    const Vec3 shift(-2, 0.5, 3);
    ClusterSpec moved = box(lo, hi, 2, kAll & ~kZlo);
    for (Vec3& x : moved.vertices)
        x = R * x + shift;
    const Vec3 n = R * Vec3::UnitZ();
    moved.walls = {make_plane(n, n.dot(R * Vec3(0, 0, 1) + shift))};
    const Cluster m(moved);
    EXPECT_NEAR(body_volumes(m)[0], exact, 1e-13);
}

TEST(Lids, TubeInASlabHasTwoLids) {
    const Vec3 lo(-0.4, 0.1, -0.5), hi(0.6, 1.1, 1.0);
    const double exact = 1.5;
    const Cluster slab(with_walls(tube(lo, hi, 3), {make_slab(Vec3::UnitZ(), -0.5, 1.0)}));
    ASSERT_EQ(slab.n_bodies(), 1);
    EXPECT_EQ(slab.bodies()[0].lids.size(), 2u);
    EXPECT_NEAR(body_volumes(slab)[0], exact, 1e-14);
    for (int v = 0; v < slab.n_vertices(); ++v) {
        const double z = slab.position(v).z();
        EXPECT_EQ(slab.vertex_freedom(v), (z == -0.5 || z == 1.0) ? 2 : 3);
    }
    // The slab given with the opposite normal, and as two separate planes.
    const Cluster flipped(with_walls(tube(lo, hi, 3), {make_slab(-Vec3::UnitZ(), -1.0, 0.5)}));
    EXPECT_NEAR(body_volumes(flipped)[0], exact, 1e-14);
    const Cluster planes(
        with_walls(tube(lo, hi, 3), {floor_plane(-0.5), make_plane(Vec3(0, 0, -3), -1.0)}));
    EXPECT_EQ(planes.bodies()[0].lids.size(), 2u);
    EXPECT_NEAR(body_volumes(planes)[0], exact, 1e-14);
}

TEST(Lids, BodyInTheCornerOfTwoWalls) {
    // The unit cube without its faces x = 0 and z = 0: one loop of free edges that runs over
    // both planes, so the lid is the L-shaped union of the two missing faces.
    const Cluster c(corner_box(Vec3(1, 1, 1), 1));
    EXPECT_NEAR(body_volumes(c)[0], 1.0, 1e-14);
    EXPECT_NEAR(c.initial_volumes()[0], 1.0, 1e-14);
}

// ---------------------------------------------------------------------------------------------
// PositionBasis

// A cup standing on the sphere wall |x| = 1 from outside, its rim on the circle z = z0: the
// sphere's cap above z0 pokes into the cup and is not in the body. The lid is the sphere patch
// inside the rim (Wall::fan_flux of the sphere wall), so the body's volume is that of the same
// cup on the plane z = z0 less the cap segment pi h^2 (3 - h) / 3, h = 1 - z0, up to the rim
// polygon's O(K^-2) (its geodesic arcs against the circle).
TEST(Lids, SphereWallLidIsTheSpherePatchInsideTheRim) {
    const double z0 = 0.6, rho = std::sqrt(1 - z0 * z0), h = 1 - z0;
    const double segment = M_PI * h * h * (3 - h) / 3;
    double previous = INFINITY;
    for (int K : {32, 64, 128}) {
        const ClusterSpec s = cup(rho, 1.0, 4, K, z0);
        const double on_plane = body_volumes(Cluster(with_walls(s, {floor_plane(z0)})))[0];
        const double on_sphere =
            body_volumes(Cluster(with_walls(s, {make_sphere_wall(Vec3::Zero(), 1)})))[0];
        const double error = std::abs(on_plane - on_sphere - segment);
        EXPECT_LT(error, 0.25 * segment * 64.0 / (K * K)) << "K = " << K;
        if (K > 32) EXPECT_LT(error, 0.3 * previous) << "second order in 1/K";
        previous = error;
    }
}

void expect_tangent_bases(const Cluster& c) {
    const PositionBasis P(c);
    int total = 0;
    for (int v = 0; v < c.n_vertices(); ++v) {
        const int d = P.dim(v);
        EXPECT_EQ(d, c.vertex_freedom(v));
        EXPECT_EQ(P.offset(v), total);
        total += d;
        EXPECT_EQ(P.constrained(v), d < 3);
        const Eigen::MatrixXd T = P.T(v).leftCols(d);
        EXPECT_LT((T.transpose() * T - Eigen::MatrixXd::Identity(d, d)).norm(), 1e-14) << v;
        for (int w : c.vertex_walls(v))
            EXPECT_LT((c.walls()[w]->normal(c.position(v)).transpose() * T).norm(), 1e-14) << v;
    }
    EXPECT_EQ(P.size(), total);
}

TEST(PositionBasis, OrthonormalTangentBases) {
    const Cluster c(corner_box(Vec3(1, 1, 1), 2));
    expect_tangent_bases(c);
    const PositionBasis P(c);
    int sum = 0;
    for (int v = 0; v < c.n_vertices(); ++v)
        sum += c.vertex_freedom(v);
    EXPECT_EQ(P.size(), sum);
    // Freedom 1 in the corner: T is +-y.
    for (int v = 0; v < c.n_vertices(); ++v)
        if (c.vertex_freedom(v) == 1) EXPECT_NEAR(std::abs(P.T(v).col(0).y()), 1.0, 1e-15);

    expect_tangent_bases(Cluster(
        with_walls(tube(Vec3(0, 0, -1), Vec3(1, 1, 1), 2), {make_slab(Vec3(0, 0, 1), -1, 1)})));
    const double Rw = 2, r0 = 0.8;
    const double z0 = -Rw + std::sqrt(Rw * Rw - r0 * r0);
    std::vector<std::array<double, 2>> rings;
    for (int j = 0; j < 4; ++j)
        rings.push_back({r0 * std::cos(M_PI / 2 * j / 4), z0 + r0 * std::sin(M_PI / 2 * j / 4)});
    expect_tangent_bases(Cluster(
        with_walls(revolution(rings, z0 + r0, 12), {make_sphere_wall(Vec3(0, 0, -Rw), Rw)})));
}

TEST(PositionBasis, IdentityWithoutWalls) {
    const Cluster c(test::twin_tetrahedra());
    const PositionBasis P(c);
    EXPECT_EQ(P.size(), 3 * c.n_vertices());
    for (int v = 0; v < c.n_vertices(); ++v) {
        EXPECT_EQ(P.T(v), Eigen::Matrix3d::Identity());
        EXPECT_FALSE(P.constrained(v));
        EXPECT_EQ(P.offset(v), 3 * v);
    }
    Eigen::VectorXd g = Eigen::VectorXd::LinSpaced(3 * c.n_vertices(), -1, 2);
    EXPECT_EQ(P.restrict(g), g);
    EXPECT_EQ(P.displacement(g, 2), g.segment<3>(6));
}

// ---------------------------------------------------------------------------------------------
// Steps

/// The open box on the floor, n x n per face, and the corner box on the floor and x = 0.
Cluster floor_box(int n = 3) {
    return Cluster(with_walls(box(Vec3(-0.5, -0.4, 0), Vec3(0.5, 0.6, 0.8), n, kAll & ~kZlo),
                              {floor_plane()}));
}

class WallTau : public ::testing::TestWithParam<double> {};

// Energy stability (Theorem 3.4 with V_partial^h) and attached vertices exactly on the plane, for
// both flows and every tau. A big MCF step may flatten the box onto the floor: then the step
// must refuse and leave the cluster unchanged.
TEST_P(WallTau, EnergyDecreasesAndVerticesStayOnThePlane) {
    const double tau = GetParam();
    for (Flow flow : {Flow::MeanCurvature, Flow::SurfaceDiffusion}) {
        Cluster c = floor_box();
        std::vector<int> attached;
        for (int v = 0; v < c.n_vertices(); ++v)
            if (!c.vertex_walls(v).empty()) attached.push_back(v);
        ASSERT_EQ(attached.size(), 12u);
        TimeStepper stepper;
        for (int m = 0; m < 3; ++m) {
            const Cluster before = c;
            try {
                const StepReport r = stepper.step(c, flow, tau);
                EXPECT_LE(r.energy, r.energy_before * (1 + 1e-12)) << flow_name(flow) << m;
                EXPECT_LT(r.energy, r.energy_before) << flow_name(flow) << m;
            } catch (const GeometryError& e) {
                EXPECT_EQ(flow, Flow::MeanCurvature) << e.what();
                EXPECT_EQ(c.positions(), before.positions());
                EXPECT_EQ(c.time(), before.time());
                break;
            }
            for (int v : attached)
                EXPECT_LT(std::abs(c.position(v).z()), 1e-14) << v;
            EXPECT_LT(wall_drift(c), 1e-14);
            if (tau <= 1e-2)
                for (int v = 0; v < c.n_vertices(); ++v)
                    if (c.vertex_walls(v).empty()) EXPECT_GT(c.position(v).z(), 0) << v;
        }
    }
}
INSTANTIATE_TEST_SUITE_P(Walls, WallTau, ::testing::Values(1e-3, 1e-2, 1e-1, 1.0, 10.0));

TEST(WallSteps, CornerVerticesStayOnBothPlanes) {
    const ClusterSpec s = corner_box(Vec3(1, 1, 1), 2);
    for (int run = 0; run < 4; ++run) {
        const Flow flow = run % 2 ? Flow::SurfaceDiffusion : Flow::MeanCurvature;
        const bool project = run >= 2;
        Cluster c(s);
        TimeStepper stepper;
        for (int m = 0; m < 3; ++m) {
            const StepReport r = stepper.step(c, flow, 0.01, project);
            EXPECT_LT(r.energy, r.energy_before);
        }
        for (int v = 0; v < c.n_vertices(); ++v) {
            const Vec3 x0 = s.vertices[v], x = c.position(v);
            if (x0.x() == 0 && x0.z() == 0) {
                EXPECT_LT(std::abs(x.x()) + std::abs(x.z()), 1e-14) << v;
            } else if (x0.x() == 0) {
                EXPECT_LT(std::abs(x.x()), 1e-14) << v;
            } else if (x0.z() == 0) {
                EXPECT_LT(std::abs(x.z()), 1e-14) << v;
            }
        }
    }
}

/// Half an ellipsoid with semi-axes (a, a, c) standing on the floor z = 0: J rings, K per ring.
ClusterSpec dome(double a, double c, int J, int K) {
    std::vector<std::array<double, 2>> rings;
    for (int j = 0; j < J; ++j)
        rings.push_back({a * std::cos(M_PI / 2 * j / J), c * std::sin(M_PI / 2 * j / J)});
    return with_walls(revolution(rings, c, K), {floor_plane()});
}

// SD conserves the volume to first order: with chi = 1 in (3.11a), sum m_v omega_v . dX_v = 0
// (one surface, no triple lines, so 1 is in W^h; up to the solver's tolerance: lagged
// factorisations are refined by GMRES to a relative residual of about 1e-11). The volume with
// its lid then changes at second order only: on the open box, whose sharp edges move a lot,
// as much as the closed box's does; on a smooth dome by a tiny fraction of the first-order
// scale sum m_v |dX_v| (MCF, for contrast, changes it by about that scale).
TEST(WallSteps, SurfaceDiffusionConservesVolumeOnTheFloor) {
    for (int shape = 0; shape < 3; ++shape) {
        const bool walls = shape < 2, smooth = shape == 1;
        Cluster c = smooth  ? Cluster(dome(1.0, 0.6, 8, 32))
                    : walls ? floor_box(4)
                            : Cluster(box(Vec3(-0.5, -0.4, 0), Vec3(0.5, 0.6, 0.8), 4));
        const Cluster start = c;
        TimeStepper stepper;
        double total_change = 0;
        for (int m = 0; m < 5; ++m) {
            const Cluster before = c;
            const PairGeometry g = pair_geometry(before);
            const StepReport r = stepper.step(c, Flow::SurfaceDiffusion, 1e-4);
            double flux = 0, scale = 0;
            for (int v = 0; v < c.n_vertices(); ++v) {
                const Vec3 d = c.position(v) - before.position(v);
                flux += g.mass[v] * g.omega[v].dot(d);
                scale += g.mass[v] * d.norm();
            }
            EXPECT_LT(std::abs(flux), 1e-8 * scale) << shape << " " << m;
            EXPECT_LE(r.energy, r.energy_before) << shape << " " << m;
            EXPECT_EQ(r.volumes, body_volumes(c));
            const double change = r.volumes[0] - body_volumes(before)[0];
            if (smooth) EXPECT_LT(std::abs(change), 1e-2 * scale) << m;
            total_change += change;
        }
        double moved = 0;
        for (int v = 0; v < c.n_vertices(); ++v)
            moved = std::max(moved, (c.position(v) - start.position(v)).norm());
        EXPECT_GT(moved, 1e-3) << shape; // it did evolve
        const double loss = std::abs(total_change) / body_volumes(start)[0];
        if (smooth)
            EXPECT_LT(loss, 1e-4);
        else
            EXPECT_LT(loss, 2e-2) << shape; // second order: the box with or without its floor
    }
    // For contrast, MCF on the dome changes the volume at first order.
    Cluster c(dome(1.0, 0.6, 8, 32));
    const Cluster before = c;
    const PairGeometry g = pair_geometry(before);
    TimeStepper stepper;
    const StepReport r = stepper.step(c, Flow::MeanCurvature, 1e-4);
    double scale = 0;
    for (int v = 0; v < c.n_vertices(); ++v)
        scale += g.mass[v] * (c.position(v) - before.position(v)).norm();
    EXPECT_GT(std::abs(r.volumes[0] - body_volumes(before)[0]), 0.3 * scale);
}

/// Two unit cubes side by side on the floor, [0,1]^3 and [1,2]x[0,1]^2, without their bottoms:
/// surface 1 = the first cube's four outer faces, 2 = the second's, 3 = the shared face x = 1.
/// The triple line (the shared face's top and vertical edges) ends on the floor at two points.
ClusterSpec two_cubes_on_the_floor(int n) {
    SpecBuilder b;
    const Vec3 dx(1, 0, 0), dy(0, 1, 0), dz(0, 0, 1), a(0, 0, 0), c(1, 0, 0);
    b.quad_grid(0, a, dz, dy, n);      // x = 0
    b.quad_grid(0, a, dx, dz, n);      // y = 0
    b.quad_grid(0, a + dy, dz, dx, n); // y = 1
    b.quad_grid(0, a + dz, dx, dy, n); // z = 1
    b.quad_grid(1, c + dx, dy, dz, n); // x = 2
    b.quad_grid(1, c, dx, dz, n);
    b.quad_grid(1, c + dy, dz, dx, n);
    b.quad_grid(1, c + dz, dx, dy, n);
    b.quad_grid(2, c, dy, dz, n); // the shared face
    ClusterSpec s = std::move(b.spec);
    s.bodies = {{0, 2}, {1, 2}};
    s.walls = {floor_plane()};
    return s;
}

TEST(WallSteps, TwoBodiesWithATripleLineEndingOnTheFloor) {
    const ClusterSpec spec = two_cubes_on_the_floor(3);
    {
        const Cluster c(spec);
        ASSERT_EQ(c.triple_lines().size(), 1u);
        EXPECT_FALSE(c.triple_lines()[0].closed);
        EXPECT_EQ(c.bodies()[0].lids.size(), 1u);
        EXPECT_EQ(c.bodies()[1].lids.size(), 1u);
        EXPECT_NEAR(body_volumes(c)[0], 1.0, 1e-14);
        EXPECT_NEAR(body_volumes(c)[1], 1.0, 1e-14);
        // The line's ends are on the floor, with two directions to move in.
        for (int v : {c.triple_lines()[0].vertices.front(), c.triple_lines()[0].vertices.back()}) {
            EXPECT_EQ(c.position(v).z(), 0.0);
            EXPECT_EQ(c.vertex_freedom(v), 2);
        }
    }
    for (Flow flow : {Flow::MeanCurvature, Flow::SurfaceDiffusion}) {
        Cluster c(spec);
        TimeStepper stepper;
        for (int m = 0; m < 4; ++m) {
            const StepReport r = stepper.step(c, flow, 1e-3);
            EXPECT_LT(r.energy, r.energy_before) << flow_name(flow) << m;
            if (flow == Flow::SurfaceDiffusion) {
                EXPECT_LT(r.volume_loss, 5e-2) << m;
            }
        }
        for (int v = 0; v < c.n_vertices(); ++v)
            if (!c.vertex_walls(v).empty()) {
                EXPECT_LT(std::abs(c.position(v).z()), 1e-14) << v;
            } else {
                EXPECT_GT(c.position(v).z(), 0) << v;
            }
        // The triangulations of the two cubes are not mirror images: no exact symmetry, but
        // the two bodies stay alike.
        const std::vector<double> V = body_volumes(c);
        EXPECT_NEAR(V[0], V[1], 1e-2);
    }
}

/// Dense A (3n x 3n), B = blockdiag sum m omega omega^T, N (3n x pairs), A_s (pairs x pairs) and
/// T (3n x P.size()) built from scratch.
struct DenseSystem {
    Eigen::MatrixXd A, B, N, As, T;
    Eigen::VectorXd X;
};

DenseSystem dense_system(const Cluster& c) {
    const int n = 3 * c.n_vertices(), np = c.n_pairs();
    DenseSystem d;
    d.A = Eigen::MatrixXd::Zero(n, n);
    d.B = Eigen::MatrixXd::Zero(n, n);
    d.N = Eigen::MatrixXd::Zero(n, np);
    d.As = Eigen::MatrixXd::Zero(np, np);
    for (int i = 0; i < c.n_surfaces(); ++i)
        for (const Tri& t : c.surface(i).triangles) {
            const auto K = local_stiffness(c.position(t[0]), c.position(t[1]), c.position(t[2]));
            const Vec3 a2 = area_vector2(c.positions(), t);
            for (int a = 0; a < 3; ++a) {
                d.N.block<3, 1>(3 * t[a], c.pair_index(t[a], i)) += a2 / 6.0;
                for (int b = 0; b < 3; ++b) {
                    d.A.block<3, 3>(3 * t[a], 3 * t[b]) +=
                        c.surface(i).sigma * K(a, b) * Eigen::Matrix3d::Identity();
                    d.As(c.pair_index(t[a], i), c.pair_index(t[b], i)) += K(a, b);
                }
            }
        }
    const PairGeometry g = pair_geometry(c);
    for (int v = 0; v < c.n_vertices(); ++v)
        for (int k = c.pair_begin(v); k < c.pair_begin(v + 1); ++k)
            d.B.block<3, 3>(3 * v, 3 * v) += g.mass[k] * g.omega[k] * g.omega[k].transpose();
    // T from the wall normals directly (not from PositionBasis): any orthonormal basis of the
    // tangent space gives the same displacement.
    std::vector<Eigen::MatrixXd> Tv(c.n_vertices());
    int cols = 0;
    for (int v = 0; v < c.n_vertices(); ++v) {
        Eigen::MatrixXd Nv(3, 0);
        for (int w : c.vertex_walls(v)) {
            Nv.conservativeResize(3, Nv.cols() + 1);
            Nv.col(Nv.cols() - 1) = c.walls()[w]->normal(c.position(v));
        }
        // Projector onto the orthogonal complement of the normals, then its range.
        Eigen::Matrix3d Pr = Eigen::Matrix3d::Identity();
        if (Nv.cols() > 0)
            Pr -= Nv * (Nv.transpose() * Nv).completeOrthogonalDecomposition().pseudoInverse() *
                  Nv.transpose();
        Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(Pr);
        Eigen::MatrixXd basis(3, 0);
        for (int k = 0; k < 3; ++k)
            if (es.eigenvalues()[k] > 0.5) {
                basis.conservativeResize(3, basis.cols() + 1);
                basis.col(basis.cols() - 1) = es.eigenvectors().col(k);
            }
        Tv[v] = basis;
        cols += static_cast<int>(basis.cols());
    }
    d.T = Eigen::MatrixXd::Zero(n, cols);
    for (int v = 0, col = 0; v < c.n_vertices(); col += static_cast<int>(Tv[v].cols()), ++v)
        d.T.block(3 * v, col, 3, Tv[v].cols()) = Tv[v];
    d.X.resize(n);
    for (int v = 0; v < c.n_vertices(); ++v)
        d.X.segment<3>(3 * v) = c.position(v);
    return d;
}

ClusterSpec corner_box_with_sigma() {
    ClusterSpec s = corner_box(Vec3(1, 0.8, 1.2), 2);
    s.surfaces[0].sigma = 1.3;
    return s;
}

TEST(WallSteps, MeanCurvatureStepMatchesDenseReducedSolve) {
    for (const ClusterSpec& spec :
         {corner_box_with_sigma(),
          with_walls(box(Vec3(0, 0, 0), Vec3(1, 1, 1), 2, kAll & ~kZlo), {floor_plane()})}) {
        Cluster c(spec);
        const Cluster before = c;
        const double tau = 0.02;
        const DenseSystem d = dense_system(c);
        const Eigen::MatrixXd M = d.T.transpose() * (d.A + d.B / tau) * d.T;
        const Eigen::VectorXd y = M.ldlt().solve(-d.T.transpose() * d.A * d.X);
        const Eigen::VectorXd dX = d.T * y;
        const PositionBasis P(c);
        EXPECT_EQ(P.size(), d.T.cols());
        TimeStepper stepper;
        const StepReport r = stepper.step(c, Flow::MeanCurvature, tau);
        EXPECT_EQ(r.unknowns, P.size());
        for (int v = 0; v < c.n_vertices(); ++v)
            EXPECT_LT((c.position(v) - before.position(v) - dX.segment<3>(3 * v)).norm(), 1e-12)
                << v;
    }
}

TEST(WallSteps, SurfaceDiffusionStepMatchesDenseReducedSolve) {
    Cluster c(corner_box_with_sigma());
    const Cluster before = c;
    const double tau = 0.05;
    const DenseSystem d = dense_system(c);
    const KappaBasis Zb = kappa_basis(c);
    const int np = c.n_pairs(), m = Zb.n_reduced, n = static_cast<int>(d.T.cols());
    Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(np, m);
    for (int k = 0; k < np; ++k)
        for (int x = Zb.start[k]; x < Zb.start[k + 1]; ++x)
            Z(k, Zb.col[x]) = Zb.val[x];
    Eigen::MatrixXd S(n + m, n + m);
    S << d.T.transpose() * d.A * d.T, d.T.transpose() * d.N * Z,
        Z.transpose() * d.N.transpose() * d.T, -tau * Z.transpose() * d.As * Z;
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n + m);
    rhs.head(n) = -d.T.transpose() * d.A * d.X;
    const Eigen::VectorXd sol = S.fullPivLu().solve(rhs);
    const Eigen::VectorXd dX = d.T * sol.head(n);
    TimeStepper stepper;
    stepper.step(c, Flow::SurfaceDiffusion, tau);
    for (int v = 0; v < c.n_vertices(); ++v)
        EXPECT_LT((c.position(v) - before.position(v) - dX.segment<3>(3 * v)).norm(), 1e-10) << v;
}

/// A hemisphere of radius r0 standing on the sphere wall |x - (0, 0, -Rw)| = Rw: its rim ring
/// lies on the wall (up to round-off), one body closed by a lid on the wall.
ClusterSpec drop_on_sphere(double Rw = 2, double r0 = 0.8, int J = 5, int K = 16) {
    const double z0 = -Rw + std::sqrt(Rw * Rw - r0 * r0);
    std::vector<std::array<double, 2>> rings;
    for (int j = 0; j < J; ++j)
        rings.push_back({r0 * std::cos(M_PI / 2 * j / J), z0 + r0 * std::sin(M_PI / 2 * j / J)});
    ClusterSpec s = revolution(rings, z0 + r0, K);
    s.walls = {make_sphere_wall(Vec3(0, 0, -Rw), Rw)};
    return s;
}

TEST(WallSteps, DriftOffASphereWallAndItsProjection) {
    const double Rw = 2;
    for (Flow flow : {Flow::MeanCurvature, Flow::SurfaceDiffusion}) {
        Cluster c(drop_on_sphere(Rw));
        EXPECT_TRUE(c.has_walls());
        EXPECT_LT(wall_drift(c), 1e-14);
        std::vector<int> attached;
        for (int v = 0; v < c.n_vertices(); ++v)
            if (!c.vertex_walls(v).empty()) attached.push_back(v);
        EXPECT_EQ(attached.size(), 16u);
        Cluster p = c;
        TimeStepper s1, s2;
        // From vertices on the sphere, a move d in its tangent plane ends sqrt(Rw^2 + d^2) - Rw
        // off the sphere: the drift of the linearised constraint, second order in d.
        const Cluster start = c;
        const StepReport r = s1.step(c, flow, 1e-3);
        EXPECT_LE(r.energy, r.energy_before * (1 + 1e-12));
        double worst = 0;
        for (int v : attached) {
            const double d = (c.position(v) - start.position(v)).norm();
            const double off = std::sqrt(Rw * Rw + d * d) - Rw;
            EXPECT_NEAR(c.walls()[0]->distance(c.position(v)), off, 1e-14 + 1e-9 * off) << v;
            worst = std::max(worst, off);
        }
        EXPECT_NEAR(r.wall_drift, worst, 1e-14 + 1e-9 * worst);
        EXPECT_GT(r.wall_drift, 1e-9) << flow_name(flow);
        EXPECT_EQ(r.wall_drift, wall_drift(c));
        // Projected: on the sphere up to round-off, step after step; the stepper projects only
        // the attached vertices.
        for (int m = 0; m < 3; ++m) {
            const Cluster before = p;
            const StepReport q = s2.step(p, flow, 1e-3, true);
            EXPECT_LT(q.wall_drift, 1e-13);
            EXPECT_LT(wall_drift(p), 1e-13);
            if (m == 0)
                for (int v = 0; v < c.n_vertices(); ++v)
                    if (c.vertex_walls(v).empty())
                        EXPECT_EQ(p.position(v), c.position(v)) << v;
                    else
                        EXPECT_LT((p.position(v) - c.position(v)).norm(), 1e-3) << v;
        }
        for (int m = 0; m < 2; ++m) {
            const StepReport q = s1.step(c, flow, 1e-3);
            EXPECT_GT(q.wall_drift, 0);
            EXPECT_LT(q.wall_drift, 1e-2);
        }
    }
}

// A step that fails anywhere must leave the cluster unchanged (TimeStepper::step's contract):
// also when a function wall fails.
TEST(WallSteps, FailingFunctionWallWithProjectionLeavesTheClusterUnchanged) {
    bool fail = false;
    auto F = [&](const Vec3& x) {
        if (fail) throw InvalidInput("F failed");
        return x.z();
    };
    ClusterSpec s = box(Vec3::Zero(), Vec3(1, 1, 1), 2, kAll & ~kZlo);
    s.walls = {make_function_wall(
        F, [](const Vec3&) { return Vec3(0, 0, 1); }, "floor")};
    Cluster c(s);
    TimeStepper stepper;
    stepper.step(c, Flow::MeanCurvature, 1e-2); // works while F does
    const Cluster before = c;
    fail = true;
    EXPECT_THROW(stepper.step(c, Flow::MeanCurvature, 1e-2, true), InvalidInput);
    EXPECT_EQ(c.positions(), before.positions());
    EXPECT_EQ(c.time(), before.time());
}

TEST(WallSteps, FailingFunctionWallLeavesTheClusterUnchanged) {
    bool fail = false;
    auto F = [&](const Vec3& x) {
        if (fail) throw InvalidInput("F failed");
        return x.z();
    };
    ClusterSpec s = box(Vec3::Zero(), Vec3(1, 1, 1), 2, kAll & ~kZlo);
    // An analytic gradient: the tangent bases need no F, so F is first called after the solve.
    s.walls = {make_function_wall(
        F, [](const Vec3&) { return Vec3(0, 0, 1); }, "floor")};
    Cluster c(s);
    TimeStepper stepper;
    const Cluster before = c;
    fail = true;
    EXPECT_THROW(stepper.step(c, Flow::MeanCurvature, 1e-2), InvalidInput);
    EXPECT_EQ(c.positions(), before.positions());
    EXPECT_EQ(c.time(), before.time());
}

// ---------------------------------------------------------------------------------------------
// drop_wall_lids

TEST(DropWallLids, RemovesTheFacetsOnTheWall) {
    const int n = 3;
    ClusterSpec s = box(Vec3(0, 0, 0), Vec3(1, 1, 1), n);
    const std::size_t vertices = s.vertices.size(), facets = s.surfaces[0].triangles.size();
    s.walls = {floor_plane()};
    const std::vector<int> kept = drop_wall_lids(s);
    EXPECT_EQ(kept, std::vector<int>{0});
    EXPECT_EQ(s.surfaces[0].triangles.size(), facets - 2 * n * n);
    EXPECT_EQ(s.vertices.size(), vertices - (n - 1) * (n - 1)); // the bottom's inner vertices
    for (const Tri& t : s.surfaces[0].triangles) {
        int on_floor = 0;
        for (int v : t)
            on_floor += s.vertices[v].z() == 0;
        EXPECT_LT(on_floor, 3);
    }
    const Cluster c(s);
    EXPECT_TRUE(c.has_walls());
    EXPECT_EQ(c.boundary_edges().size(), 4u * n);
    EXPECT_NEAR(body_volumes(c)[0], 1.0, 1e-14);
}

TEST(DropWallLids, DropsEmptySurfacesAndRenumbersBodies) {
    // Face k of the box is surface k: x-, x+, y-, y+, z-, z+. A closed box of six surfaces is
    // not a valid cluster (edges of two surfaces) but drop_wall_lids does not validate.
    ClusterSpec s = box(Vec3(0, 0, 0), Vec3(1, 2, 1), 2, kAll, true);
    ASSERT_EQ(s.surfaces.size(), 6u);
    s.surfaces[5].sigma = 2.5;
    s.bodies = {{0, 1, 2, 3, 4, 5}, {4}};
    // The floor z = 0 and the wall x = 1.
    s.walls = {floor_plane(), make_plane(Vec3::UnitX(), 1)};
    const std::vector<int> kept = drop_wall_lids(s);
    EXPECT_EQ(kept, (std::vector<int>{0, 2, 3, 5}));
    ASSERT_EQ(s.surfaces.size(), 4u);
    EXPECT_EQ(s.surfaces[3].sigma, 2.5);
    EXPECT_EQ(s.bodies[0], (std::vector<int>{0, 1, 2, 3}));
    EXPECT_TRUE(s.bodies[1].empty());
    // Vertices renumbered by first use and all used.
    std::vector<int> used(s.vertices.size(), 0);
    for (const auto& surface : s.surfaces)
        for (const Tri& t : surface.triangles)
            for (int v : t)
                used[v] = 1;
    for (int u : used)
        EXPECT_EQ(u, 1);
    EXPECT_EQ(s.surfaces[0].triangles[0][0], 0);
}

TEST(DropWallLids, OnlyFacetsWithAllCornersOnOneWall) {
    ClusterSpec s = box(Vec3(0, 0, 0), Vec3(1, 1, 1), 1);
    // The diagonal plane x = y holds two edges of the box and corners of many facets, but no
    // facet entirely: nothing is dropped.
    s.walls = {make_plane(Vec3(1, -1, 0), 0)};
    const std::size_t facets = s.surfaces[0].triangles.size(), vertices = s.vertices.size();
    drop_wall_lids(s);
    EXPECT_EQ(s.surfaces[0].triangles.size(), facets);
    EXPECT_EQ(s.vertices.size(), vertices);
}

// ---------------------------------------------------------------------------------------------
// Contact angles

// The contact angle of a film standing perpendicularly on the floor, the cup's side, converges
// to 90 degrees as the mesh is refined (the quadratic fit: here the error falls by about 8 per
// halving of h).
TEST(ContactAngles, CylinderStandingOnAPlaneMeetsItAtNinetyDegrees) {
    double previous = 0;
    for (int f : {1, 2, 4}) {
        const int K = 24 * f;
        const Cluster c(with_walls(cup(1.0, 1.0, 6 * f, K), {floor_plane()}));
        const AngleStats a = contact_angles(c);
        EXPECT_EQ(a.count, K);
        EXPECT_NEAR(a.min, 90, 0.7 / (f * f));
        EXPECT_NEAR(a.max, 90, 0.7 / (f * f));
        EXPECT_NEAR(a.young_error, std::max(90 - a.min, a.max - 90), 1e-12);
        EXPECT_NEAR(a.mean, (a.min + a.max) / 2, 1e-9); // by symmetry every vertex sees the same
        if (f > 1) EXPECT_LT(a.young_error, previous / 4) << f;
        previous = a.young_error;
        EXPECT_LT(wall_drift(c), 1e-15);
        const Report r = make_report(c);
        EXPECT_EQ(r.contact_angles.count, K);
        EXPECT_EQ(r.contact_angles.min, a.min);
        EXPECT_EQ(r.wall_drift, wall_drift(c));
    }
}

TEST(ContactAngles, RoundTubeInASlabMeetsBothPlanesAtNinetyDegrees) {
    const int K = 48;
    std::vector<std::array<double, 2>> rings;
    for (int j = 0; j <= 16; ++j)
        rings.push_back({1.0, -1.0 + 2.0 * j / 16});
    const Cluster c(with_walls(revolution(rings, NAN, K), {make_slab(Vec3::UnitZ(), -1, 1)}));
    for (int v = 0; v < c.n_vertices(); ++v)
        EXPECT_EQ(c.vertex_freedom(v), std::abs(c.position(v).z()) == 1 ? 2 : 3);
    const AngleStats a = contact_angles(c);
    EXPECT_EQ(a.count, 2 * K);
    EXPECT_NEAR(a.min, 90, 0.2);
    EXPECT_NEAR(a.max, 90, 0.2);
}

TEST(ContactAngles, BoxTubeInASlabMeetsBothPlanesAtNinetyDegrees) {
    for (int n : {4, 8}) {
        const Cluster c(
            with_walls(tube(Vec3(0, 0, -1), Vec3(1, 1, 1), n), {make_slab(Vec3::UnitZ(), -1, 1)}));
        const AngleStats a = contact_angles(c);
        EXPECT_EQ(a.count, 8 * n);
        EXPECT_NEAR(a.min, 90, 1.0);
        EXPECT_NEAR(a.max, 90, 1.0);
    }
}

// Second-order convergence to the known angle on cones, rising and overhanging.
TEST(ContactAngles, ConesMeetThePlaneAtTheirSlope) {
    double previous = 0;
    for (int f : {1, 2, 4}) {
        const int K = 48 * f, m = 6 * f;
        // Narrowing upwards at 45 degrees: the outward normal is 45 degrees from +z.
        const AngleStats narrow =
            contact_angles(Cluster(with_walls(frustum(1.0, 0.4, 0.6, m, K), {floor_plane()})));
        EXPECT_EQ(narrow.count, K);
        EXPECT_NEAR(narrow.min, 45, 0.4 / (f * f));
        EXPECT_NEAR(narrow.max, 45, 0.4 / (f * f));
        EXPECT_NEAR(narrow.young_error, 90 - narrow.min, 1e-12);
        const double error = std::abs(narrow.mean - 45);
        if (f > 1) EXPECT_LT(error, previous / 3) << f;
        previous = error;
    }
    const int K = 96;
    // Widening upwards, rising at 60 degrees from the floor (rho = 1 + z / tan 60): the outward
    // normal points out and down, 90 + 30 = 120 degrees from +z.
    const double H = 0.8, R1 = 1.0 + H / std::tan(M_PI / 3);
    const AngleStats wide =
        contact_angles(Cluster(with_walls(frustum(1.0, R1, H, 12, K), {floor_plane()})));
    EXPECT_EQ(wide.count, K);
    EXPECT_NEAR(wide.min, 120, 0.3);
    EXPECT_NEAR(wide.max, 120, 0.3);
    // The plane with the opposite normal measures the supplement.
    const AngleStats flipped = contact_angles(
        Cluster(with_walls(frustum(1.0, 0.4, 0.6, 12, K), {make_plane(-Vec3::UnitZ(), 0)})));
    EXPECT_NEAR(flipped.mean, 135, 0.3);
}

TEST(ContactAngles, CurvedFilmOnAPlane) {
    // The unit sphere cut by the plane z = -0.5: the film meets the plane where its outward
    // normal is (sqrt(3)/2 r, -1/2), 120 degrees from +z.
    const int J = 12, K = 64;
    const double phi0 = -M_PI / 6; // latitude of z = -0.5
    std::vector<std::array<double, 2>> rings;
    for (int j = 0; j < J; ++j) {
        const double phi = phi0 + (M_PI / 2 - phi0) * j / J;
        rings.push_back({std::cos(phi), std::sin(phi)});
    }
    const Cluster c(with_walls(revolution(rings, 1.0, K), {floor_plane(-0.5)}));
    const AngleStats a = contact_angles(c);
    EXPECT_EQ(a.count, K);
    EXPECT_NEAR(a.min, 120, 0.3);
    EXPECT_NEAR(a.max, 120, 0.3);
}

TEST(ContactAngles, FilmOnASphereWallUsesTheWallNormalThere) {
    // The hemisphere of radius 0.8 on the sphere wall of radius 2: at its rim the film's normal
    // is horizontal and the wall's normal is (0.8, 0, sqrt(4 - 0.64)) / 2: acos(0.4) degrees.
    const Cluster c(drop_on_sphere(2, 0.8, 12, 64));
    const AngleStats a = contact_angles(c);
    const double exact = std::acos(0.4) * 180 / M_PI;
    EXPECT_EQ(a.count, 64);
    EXPECT_NEAR(a.min, exact, 0.3);
    EXPECT_NEAR(a.max, exact, 0.3);
}

TEST(ContactAngles, NoneWithoutWalls) {
    const Cluster c(test::icosphere(1));
    EXPECT_EQ(contact_angles(c).count, 0);
    EXPECT_EQ(wall_drift(c), 0.0);
    const Report r = make_report(c);
    EXPECT_EQ(r.contact_angles.count, 0);
    EXPECT_EQ(r.wall_drift, 0.0);
}

} // namespace
} // namespace froth
