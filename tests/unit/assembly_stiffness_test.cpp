// Invariants of the P1 stiffness (numerics.md §4): they hold on every mesh, no golden numbers.
#include "assembly/stiffness.h"
#include "geometry/geometry.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

namespace froth {
namespace {

TEST(LocalStiffness, SymmetricRowsSumToZero) {
    const Eigen::Matrix3d K = local_stiffness({0, 0, 0}, {2, 0.1, 0}, {0.3, 1, 0.5});
    EXPECT_LT((K - K.transpose()).norm(), 1e-15);
    EXPECT_LT((K * Eigen::Vector3d::Ones()).norm(), 1e-14);
    EXPECT_GT(K.diagonal().minCoeff(), 0.0);
}

TEST(LocalStiffness, DirichletEnergyOfCoordinateIsArea) {
    // u = x on the flat triangle (0,0),(2,0),(0,1): |grad u|^2 = 1 over area 1.
    const Eigen::Matrix3d K = local_stiffness({0, 0, 0}, {2, 0, 0}, {0, 1, 0});
    const Eigen::Vector3d u(0, 2, 0);
    EXPECT_NEAR(u.dot(K * u), 1.0, 1e-14);
}

// A X equals the gradient of E = sum sigma_i |Gamma_i|, checked by central differences at
// every coordinate of a cluster with a triple line and unequal tensions.
TEST(Stiffness, AXIsTheEnergyGradient) {
    ClusterSpec spec = test::twin_tetrahedra();
    spec.surfaces[0].sigma = 1.0, spec.surfaces[1].sigma = 1.3, spec.surfaces[2].sigma = 0.7;
    Cluster c(spec);
    const Eigen::VectorXd AX = apply_stiffness(c, c.positions());
    const double h = 1e-6;
    for (int v = 0; v < c.n_vertices(); ++v)
        for (int d = 0; d < 3; ++d) {
            auto X = c.positions();
            X[v][d] += h;
            Cluster plus = c;
            plus.set_positions(X);
            X[v][d] -= 2 * h;
            Cluster minus = c;
            minus.set_positions(X);
            const double fd = (energy(plus) - energy(minus)) / (2 * h);
            EXPECT_NEAR(AX[3 * v + d], fd, 1e-8) << "vertex " << v << " coordinate " << d;
        }
}

TEST(Stiffness, DiagonalIsTheAssembledOnes) {
    ClusterSpec spec = test::twin_tetrahedra();
    spec.surfaces[0].sigma = 1.0, spec.surfaces[1].sigma = 1.3, spec.surfaces[2].sigma = 0.7;
    Cluster c(spec);
    SparseBuilder M;
    assemble_scalar_stiffness(c, Eigen::VectorXd::Zero(c.n_vertices()), M);
    const Eigen::VectorXd assembled = Eigen::VectorXd(M.finish().diagonal());
    const Eigen::VectorXd d = stiffness_diagonal(c);
    ASSERT_EQ(d.size(), c.n_vertices());
    for (int v = 0; v < c.n_vertices(); ++v)
        EXPECT_NEAR(d[v], assembled[v], 1e-14) << "vertex " << v;
}

/// Three flat fins at 120 degrees meeting along the z axis (a triple line of one edge): the
/// fins' normals lie in the xy plane, so the line's direction is z (the fins' top and bottom
/// edges slant, so the line's vertices are no facet's symmetric corner).
TEST(Geometry, LineDirectionIsTheLines) {
    ClusterSpec s;
    s.vertices = {{0, 0, 0}, {0, 0, 1}};
    for (int i = 0; i < 3; ++i) {
        const double a = 2 * M_PI * i / 3 + 0.1;
        s.vertices.push_back({std::cos(a), std::sin(a), -0.2});
        s.vertices.push_back({std::cos(a), std::sin(a), 1.3});
        const int p = 2 + 2 * i, q = 3 + 2 * i;
        s.surfaces.push_back({{{0, p, q}, {0, q, 1}}, 1.0});
    }
    s.fixed = {0, 1, 2, 3, 4, 5, 6, 7}; // wires all round: the fins' free edges
    Cluster c(s);
    const PairGeometry g = pair_geometry(c);
    for (int v : {0, 1}) {
        const Vec3 t = line_direction(c, g, v);
        EXPECT_NEAR(std::abs(t.z()), 1.0, 1e-12) << "line vertex " << v;
    }
    for (int v = 2; v < c.n_vertices(); ++v)
        EXPECT_TRUE(line_direction(c, g, v).isZero()) << "film vertex " << v;
}

TEST(Stiffness, TranslationsAreInTheKernel) {
    Cluster c(test::icosphere(2));
    std::vector<Vec3> ones(c.n_vertices(), Vec3(1.0, -2.0, 0.5));
    EXPECT_LT(apply_stiffness(c, ones).norm(), 1e-12);
}

} // namespace
} // namespace froth
