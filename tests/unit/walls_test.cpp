// External boundaries (seed (1.25), (3.10), (3.11); numerics.md §1, §3): the preset and function
// walls, attaching free boundary edges to walls when a cluster is made, lids closing body
// volumes on walls (planes, corners, slabs, sphere patches) and the tangent bases T_v of
// PositionBasis. Every mesh is built by hand (wall_meshes.h; no gmsh). Steps: wall_steps_test.cpp.
#include "assembly/stiffness.h"
#include "assembly/kappa_basis.h"
#include "assembly/position_basis.h"
#include "core/errors.h"
#include "flows/stepper.h"
#include "geometry/geometry.h"
#include "mesh/walls.h"
#include "test_meshes.h"
#include "wall_meshes.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

namespace froth {
namespace {

using namespace wall_test;

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

// The cylinder's lid patches are the triangles of the unrolled cylinder (Wall::fan_flux): a fan
// over the rectangle theta in [t1, t2], s in [0, L] from its centre, rim points on its sides,
// must give the flux of x through the patch, p . int n dA + R^2 (t2 - t1) L, exactly for every
// rim resolution: R A is exact by construction, and p . S sums the flat triangles' vector areas
// to that of the rim polygon, whose chords of the two arcs (translates along the axis, run in
// opposite directions) cancel. The flat fan misses the patch's bulge.
TEST(Lids, CylinderWallLidIsTheCylinderPatch) {
    const Vec3 axis = Vec3(1, 2, 2) / 3;
    const Vec3 e1 = axis.unitOrthogonal(), e2 = axis.cross(e1);
    const double R = 1.5, t1 = 0.3, t2 = 1.4, L = 0.8;
    for (const Vec3& p : {Vec3(0, 0, 0), Vec3(0.4, -1, 2)}) {
        const WallPtr w = make_cylinder_wall(p, axis, R);
        const auto at = [&](double t, double z) {
            return Vec3(p + R * (std::cos(t) * e1 + std::sin(t) * e2) + z * axis);
        };
        // The exact flux: int (p + R n) . n dA = p . int n dA + R area; int n dA over the
        // patch = R L (sin t2 - sin t1) e1 - R L (cos t2 - cos t1) e2.
        const Vec3 n_area = R * L * ((std::sin(t2) - std::sin(t1)) * e1 - (std::cos(t2) - std::cos(t1)) * e2);
        const double exact = p.dot(n_area) + R * R * (t2 - t1) * L;
        for (int K : {4, 8, 16}) {
            std::vector<Vec3> rim; // clockwise in (theta, s): the fan triangles face outward
            for (int k = 0; k < K; ++k) rim.push_back(at(t1, L * k / K));
            for (int k = 0; k < K; ++k) rim.push_back(at(t1 + (t2 - t1) * k / K, L));
            for (int k = 0; k < K; ++k) rim.push_back(at(t2, L - L * k / K));
            for (int k = 0; k < K; ++k) rim.push_back(at(t2 - (t2 - t1) * k / K, 0));
            const Vec3 apex = at(0.5 * (t1 + t2), 0.5 * L);
            double flux = 0, flat = 0;
            for (std::size_t k = 0; k < rim.size(); ++k) {
                const Vec3 &a = rim[k], &b = rim[(k + 1) % rim.size()];
                flux += w->fan_flux(apex, a, b);
                flat += 0.5 * apex.dot(b.cross(a)); // Wall::fan_flux, the flat triangle's
            }
            EXPECT_LT(std::abs(flux - exact), 1e-14 * exact) << "K = " << K;
            EXPECT_GT(std::abs(flat - exact), 1e-3 * exact) << "the flat fan misses the bulge";
        }
    }
}

// ---------------------------------------------------------------------------------------------
// PositionBasis

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

} // namespace
} // namespace froth
