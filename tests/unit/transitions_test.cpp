// Topological transitions (mesh/transitions.h): the pop of a vanishing cell.
#include "core/errors.h"
#include "expect_error.h"
#include "geometry/geometry.h"
#include "mesh/transitions.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace froth {
namespace {

/// A bubble of radius r inside one of radius 1: body 1 the shell between them, body 2 the
/// inner ball; surface 1 the outer sphere, surface 2 the inner one.
ClusterSpec nested_spheres(double r) {
    ClusterSpec s = test::icosphere(2, 1.0);
    const ClusterSpec inner = test::icosphere(1, r);
    const int n = static_cast<int>(s.vertices.size());
    s.vertices.insert(s.vertices.end(), inner.vertices.begin(), inner.vertices.end());
    ClusterSpec::Surface in = inner.surfaces[0];
    for (Tri& t : in.triangles)
        for (int& v : t) v += n;
    s.surfaces.push_back(in);
    s.bodies = {{0, 1}, {1}};
    return s;
}

void expect_topology_error(const std::function<void()>& f, const std::vector<std::string>& parts) {
    test::expect_error<TopologyError>(f, parts);
}

// One neighbouring cell: the inner bubble goes without a trace, the shell becomes the ball.
TEST(PopBody, BubbleInsideACellLeavesNothing) {
    const Cluster c(nested_spheres(0.3));
    const double shell = body_volumes(c)[0];
    TransitionRecord record;
    const Cluster r = pop_body(c, 1, &record);
    EXPECT_EQ(record.kind, "pop body");
    EXPECT_EQ(record.body, 1);
    EXPECT_EQ(record.neighbours, 1);
    EXPECT_NE(record.where.find("body 2"), std::string::npos);
    EXPECT_EQ(r.n_bodies(), 1);
    EXPECT_EQ(r.n_surfaces(), 1);
    EXPECT_EQ(r.n_vertices(), c.n_vertices() - 42);     // the inner icosphere's 42, and no P
    EXPECT_EQ(record.removed_vertices, 42);
    EXPECT_EQ(record.removed_facets, 80);
    EXPECT_LT((record.point).norm(), 1e-12);             // the inner sphere's centre
    // The shell takes the bubble's volume; its reference stays, its target is the new volume.
    const double ball = body_volumes(r)[0];
    EXPECT_NEAR(ball, shell + body_volumes(c)[1], 1e-12);
    EXPECT_DOUBLE_EQ(r.initial_volumes()[0], c.initial_volumes()[0]);
    EXPECT_DOUBLE_EQ(r.target_volumes()[0], ball);
    // The energy is the outer sphere's alone.
    EXPECT_NEAR(energy(r), energy(Cluster(test::icosphere(2, 1.0))), 1e-12);
    EXPECT_LT(energy(r), energy(c));
    // The old cluster is untouched.
    EXPECT_EQ(c.n_bodies(), 2);
}

TEST(PopBody, KeepsTensionsTimeAndLaterBodiesShiftDown) {
    ClusterSpec s = nested_spheres(0.3);
    s.surfaces[0].sigma = 2.5;
    s.bodies = {{1}, {0, 1}}; // the inner ball first this time
    Cluster c(std::move(s));
    c.set_time(0.75);
    const Cluster r = pop_body(c, 0);
    ASSERT_EQ(r.n_bodies(), 1);
    EXPECT_DOUBLE_EQ(r.surface(0).sigma, 2.5);
    EXPECT_DOUBLE_EQ(r.time(), 0.75);
    EXPECT_DOUBLE_EQ(r.initial_volumes()[0], c.initial_volumes()[1]);
}

TEST(PopBody, RefusesWhatCannotPop) {
    const Cluster sphere(test::icosphere(1));
    expect_topology_error([&] { pop_body(sphere, 0); }, {"body 1", "all the cluster has"});
    test::expect_invalid([&] { pop_body(sphere, 1); }, {"body 2", "does not exist"});
    test::expect_invalid([&] { pop_body(sphere, -1); }, {"body 0", "does not exist"});
    // The shell around the inner bubble has two neighbours' worth of films but its collapse
    // would take the inner bubble's films with it.
    const Cluster nested(nested_spheres(0.3));
    expect_topology_error([&] { pop_body(nested, 0); }, {"body 1"});
    // Collapsing one of two tetrahedra leaves the other without films.
    const Cluster twins(test::twin_tetrahedra());
    expect_topology_error([&] { pop_body(twins, 0); }, {"body 1", "body 2", "without films"});
}

TEST(PopBody, RefusesFixedVertices) {
    ClusterSpec s = nested_spheres(0.3);
    s.fixed = {static_cast<int>(s.vertices.size()) - 1}; // a vertex of the inner bubble
    const Cluster c(std::move(s));
    expect_topology_error([&] { pop_body(c, 1); }, {"body 2", "fixed vertex"});
}

} // namespace
} // namespace froth
