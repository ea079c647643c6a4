// Junction topology derived from triangles: triple lines, o^k, body signs, validation errors.
#include "core/errors.h"
#include "geometry/geometry.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace froth {
namespace {

TEST(Topology, TwinTetrahedraHaveOneClosedTripleLine) {
    Cluster c(test::twin_tetrahedra());
    EXPECT_EQ(c.junction_edges().size(), 3u);
    ASSERT_EQ(c.triple_lines().size(), 1u);
    EXPECT_TRUE(c.triple_lines()[0].closed);
    EXPECT_EQ(c.triple_lines()[0].vertices.size(), 3u);
    EXPECT_TRUE(c.quadruple_points().empty());
}

// o_j = +1 iff surface j's facet traverses a -> b: check against the facets directly.
TEST(Topology, OrientationCoefficientsFollowFacetOrder) {
    Cluster c(test::twin_tetrahedra());
    for (const JunctionEdge& e : c.junction_edges())
        for (int j = 0; j < 3; ++j) {
            int found = 0;
            for (const Tri& t : c.surface(e.surfaces[j]).triangles)
                for (int k = 0; k < 3; ++k) {
                    if (t[k] == e.a && t[(k + 1) % 3] == e.b) found = +1;
                    if (t[k] == e.b && t[(k + 1) % 3] == e.a) found = -1;
                }
            EXPECT_EQ(e.o[j], found);
        }
}

// The defining property of o^k (seed Fig. 1): the pairs (o_j nu_j, mu_j) of the three films
// all have the same orientation about the junction edge.
TEST(Topology, OrientedNormalConormalPairsAgree) {
    Cluster c(test::twin_tetrahedra());
    const auto& X = c.positions();
    for (const JunctionEdge& e : c.junction_edges()) {
        const Vec3 t = X[e.b] - X[e.a];
        double sign[3];
        for (int j = 0; j < 3; ++j) {
            Vec3 nu;
            for (const Tri& f : c.surface(e.surfaces[j]).triangles)
                if (std::count(f.begin(), f.end(), e.a) && std::count(f.begin(), f.end(), e.b))
                    nu = area_vector2(X, f).normalized();
            const Vec3 d = X[e.a] - X[e.opposite[j]];
            const Vec3 mu = (d - d.dot(t.normalized()) * t.normalized()).normalized();
            sign[j] = t.dot((e.o[j] * nu).cross(mu));
        }
        EXPECT_GT(sign[0] * sign[1], 0);
        EXPECT_GT(sign[0] * sign[2], 0);
    }
}

TEST(Topology, BodiesAreOrientedOutwardWithExactVolumes) {
    Cluster c(test::twin_tetrahedra());
    const auto V = body_volumes(c);
    ASSERT_EQ(V.size(), 2u);
    // base triangle area 1/2, heights 1: V = 1/6 each.
    EXPECT_NEAR(V[0], 1.0 / 6.0, 1e-15);
    EXPECT_NEAR(V[1], 1.0 / 6.0, 1e-15);
    // The wall is shared, so it has opposite signs in the two bodies.
    int wall_sign[2] = {0, 0};
    for (int b = 0; b < 2; ++b)
        for (const BodyFace& f : c.bodies()[b].faces)
            if (f.surface == 2) wall_sign[b] = f.sign;
    EXPECT_EQ(wall_sign[0], -wall_sign[1]);
}

TEST(Topology, IcosphereVolumeIsTranslationInvariant) {
    Cluster c(test::icosphere(2));
    const double v0 = body_volumes(c)[0];
    auto X = c.positions();
    for (Vec3& x : X) x += Vec3(3, -7, 11);
    c.set_positions(X);
    EXPECT_NEAR(body_volumes(c)[0], v0, 1e-12);
    EXPECT_LT(v0, 4.0 * M_PI / 3.0); // inscribed polyhedron
    EXPECT_GT(v0, 0.95 * 4.0 * M_PI / 3.0);
}

template <class E> void expect_error(ClusterSpec spec, const std::string& text) {
    try {
        Cluster c(std::move(spec));
        FAIL() << "no error, expected: " << text;
    } catch (const E& e) {
        EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
    }
}

TEST(Validation, EdgeInFourSurfaces) {
    ClusterSpec s = test::twin_tetrahedra();
    s.vertices.push_back({0.3, 0.3, 2});
    s.surfaces.push_back({{{1, 0, 5}}, 1.0}); // a fourth sheet on edge 1-2
    s.bodies.clear();
    expect_error<TopologyError>(s, "shared by 4 facets");
}

TEST(Validation, ZeroAreaFacet) {
    ClusterSpec s = test::twin_tetrahedra();
    s.vertices[3] = {0.5, 0.5, 0}; // on the line through vertices 1 and 2
    s.vertices[3] = 0.5 * (s.vertices[1] + s.vertices[2]);
    expect_error<GeometryError>(s, "zero area");
}

TEST(Validation, FreeBoundaryEdge) {
    ClusterSpec s = test::icosphere(0);
    s.surfaces[0].triangles.pop_back();
    s.bodies.clear();
    expect_error<TopologyError>(s, "free boundary edge");
}

TEST(Validation, InconsistentOrientation) {
    ClusterSpec s = test::icosphere(0);
    std::swap(s.surfaces[0].triangles[0][0], s.surfaces[0].triangles[0][1]);
    expect_error<TopologyError>(s, "not consistently oriented");
}

TEST(Validation, EdgeInTwoSurfaces) {
    ClusterSpec s = test::icosphere(0);
    s.surfaces.push_back({{s.surfaces[0].triangles.back()}, 1.0});
    s.surfaces[0].triangles.pop_back();
    s.bodies.clear();
    expect_error<TopologyError>(s, "shared by exactly two surfaces");
}

TEST(Validation, BodyNotClosed) {
    ClusterSpec s = test::twin_tetrahedra();
    s.bodies = {{0}};
    expect_error<TopologyError>(s, "body 1 is not closed");
}

TEST(Validation, NonPositiveSigma) {
    ClusterSpec s = test::twin_tetrahedra();
    s.surfaces[1].sigma = 0;
    expect_error<InvalidInput>(s, "surface 2 has sigma");
}

} // namespace
} // namespace froth
