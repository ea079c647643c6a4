// Topology watch: crossing facets (CGAL), vanishing bodies, quadruple-point angles.
#include "anisotropy/anisotropy.h"
#include "checks/self_intersection.h"
#include "geometry/geometry.h"
#include "run/evolve.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>

namespace froth {
namespace {

/// Two icospheres of radius 1 whose centres are `distance` apart, as one cluster.
ClusterSpec two_spheres(double distance) {
    ClusterSpec a = test::icosphere(2), b = test::icosphere(2);
    const int n = static_cast<int>(a.vertices.size());
    for (Vec3& x : b.vertices) a.vertices.push_back(x + Vec3(distance, 0, 0));
    for (Tri& t : b.surfaces[0].triangles)
        for (int& v : t) v += n;
    a.surfaces.push_back(b.surfaces[0]);
    a.bodies = {{0}, {1}};
    return a;
}

TEST(SelfIntersection, FindsCrossingSpheresOnly) {
    if (!self_intersection_available()) GTEST_SKIP() << "built without CGAL";
    EXPECT_TRUE(find_self_intersections(Cluster(test::icosphere(2))).empty());
    EXPECT_TRUE(find_self_intersections(Cluster(two_spheres(2.5))).empty());
    const auto crossings = find_self_intersections(Cluster(two_spheres(1.5)), 5);
    ASSERT_EQ(crossings.size(), 5u);
    EXPECT_NE(crossings[0].a.surface, crossings[0].b.surface);
}

TEST(TopologyWatch, CrossingStopsTheRunAndKeepsTheLastStateWithout) {
    if (!self_intersection_available()) GTEST_SKIP() << "built without CGAL";
    Cluster c(two_spheres(1.5));
    const auto start = c.positions();
    TimeStepper stepper;
    EvolveOptions o;
    o.flow = Flow::SurfaceDiffusion, o.tau = 1e-4, o.steps = 20;
    o.watch.self_intersection_every = 5;
    const EvolveResult r = evolve(c, stepper, o);
    ASSERT_TRUE(r.event.has_value());
    EXPECT_EQ(r.event->kind, "self-intersection");
    EXPECT_EQ(r.steps, 5);
    EXPECT_EQ(c.positions(), start) << "the initial state was the last one checked";
    EXPECT_EQ(c.time(), 0.0);
    EXPECT_NE(r.stop_reason.find("topology: "), std::string::npos);
}

// A sphere under MCF vanishes at t = R^2/4: the watch must stop the run just before.
TEST(TopologyWatch, ShrinkingSphereVanishesNearItsExtinctionTime) {
    Cluster c(test::icosphere(3));
    TimeStepper stepper;
    EvolveOptions o;
    o.flow = Flow::MeanCurvature, o.tau = 1e-3, o.duration = 0.5;
    const EvolveResult r = evolve(c, stepper, o);
    ASSERT_TRUE(r.event.has_value());
    EXPECT_EQ(r.event->kind, "vanishing body");
    EXPECT_NEAR(r.event->t, 0.25, 0.01);
    EXPECT_GT(body_volumes(c)[0], 0.0); // a valid state is kept
}

TEST(TopologyWatch, CanBeSwitchedOff) {
    Cluster c(test::icosphere(2));
    TimeStepper stepper;
    EvolveOptions o;
    o.flow = Flow::MeanCurvature, o.tau = 0.05, o.steps = 4;
    o.watch.enabled = false;
    const EvolveResult r = evolve(c, stepper, o);
    EXPECT_FALSE(r.event.has_value());
    EXPECT_EQ(r.stop_reason, "steps done");
}

/// The unit icosphere with one facet flattened: its third corner moved next to the midpoint of
/// the opposite edge, so that the facet's two other angles are `degrees` (its edges stay long).
Cluster sphere_with_thin_facet(double degrees) {
    ClusterSpec s = test::icosphere(2);
    const Tri t = s.surfaces[0].triangles[0];
    const Vec3 a = s.vertices[t[0]], b = s.vertices[t[1]], c = s.vertices[t[2]];
    const Vec3 mid = 0.5 * (a + b), ab = b - a;
    const Vec3 across = (c - mid - (c - mid).dot(ab) / ab.squaredNorm() * ab).normalized();
    s.vertices[t[2]] = mid + std::tan(degrees * M_PI / 180) * 0.5 * ab.norm() * across;
    return Cluster(std::move(s));
}

// Nearly crystalline films keep thin facets along their Wulff edges (0.2-0.9 degrees in the
// seed's Figs. 17-19): on their surfaces the collapsing-facet limit is a tenth of the default.
TEST(TopologyWatch, CollapsingFacetLimitIsATenthOnNearlyCrystallineSurfaces) {
    const TopologyWatch watch{WatchOptions{}}; // min_facet_angle 0.5
    auto kind = [&](Cluster c) {
        const auto e = watch.check(c, 1);
        return e ? e->kind : std::string("none");
    };
    auto with = [](Cluster c, Anisotropy g) {
        c.set_anisotropy(0, std::make_shared<const Anisotropy>(std::move(g)));
        return c;
    };
    EXPECT_EQ(kind(sphere_with_thin_facet(1.0)), "none");
    EXPECT_EQ(kind(sphere_with_thin_facet(0.2)), "collapsing facet");
    EXPECT_EQ(kind(with(sphere_with_thin_facet(0.2), Anisotropy::l1(0.01))), "none");
    EXPECT_EQ(kind(with(sphere_with_thin_facet(0.2), Anisotropy::hexagonal())), "none");
    EXPECT_EQ(kind(with(sphere_with_thin_facet(0.02), Anisotropy::l1(0.01))), "collapsing facet");
    // l1 with eps = 0.3 is not nearly crystalline, nor is one needle-like term (an ellipsoid).
    EXPECT_EQ(kind(with(sphere_with_thin_facet(0.2), Anisotropy::l1(0.3))), "collapsing facet");
    EXPECT_EQ(kind(with(sphere_with_thin_facet(0.2),
                        Anisotropy::from_angles(0.01, {Vec3::Zero()}))), "collapsing facet");
}

// A regular tetrahedron cut into four cells from its centre: 10 straight triple lines meet
// at 5 quadruple points. At the centre the lines make arccos(-1/3) pairwise; at a corner
// the smallest angle is between the edge to the centre and an outer edge, arccos(sqrt(2/3)).
TEST(QuadruplePoints, AnglesOfStraightLinesAreExact) {
    ClusterSpec s;
    s.vertices = {{0, 0, 0}, {1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    const int A = 1, B = 2, C = 3, D = 4;
    for (auto [p, q] : {std::pair{A, B}, {A, C}, {A, D}, {B, C}, {B, D}, {C, D}})
        s.surfaces.push_back({{{0, p, q}}, 1.0}); // inner films
    for (Tri t : {Tri{A, C, B}, Tri{A, B, D}, Tri{A, D, C}, Tri{B, C, D}})
        s.surfaces.push_back({{t}, 1.0}); // outer faces
    Cluster c(s);
    EXPECT_EQ(c.quadruple_points().size(), 5u);
    EXPECT_EQ(c.triple_lines().size(), 10u);
    const AngleStats q = quadruple_point_angles(c);
    EXPECT_EQ(q.count, 30);
    EXPECT_NEAR(q.max, std::acos(-1.0 / 3.0) * 180 / M_PI, 1e-9);
    EXPECT_NEAR(q.min, std::acos(std::sqrt(2.0 / 3.0)) * 180 / M_PI, 1e-9);
}

} // namespace
} // namespace froth
