// d V_b / d X (geometry.h): the dense and sparse forms agree, a body's column lives on its own
// films' vertices, the gradient is the volume's derivative, and PositionBasis::restrict of the
// sparse matrix is the dense restriction column by column (walls' tangent bases included).
#include "assembly/position_basis.h"
#include "geometry/geometry.h"
#include "test_meshes.h"
#include "wall_meshes.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <vector>

namespace froth {
namespace {

using wall_test::cup;
using wall_test::corner_box;
using wall_test::floor_plane;
using wall_test::with_walls;

void expect_sparse_matches_dense(const Cluster& c) {
    const Eigen::MatrixXd dense = body_volume_gradients(c);
    const Eigen::SparseMatrix<double> sparse = sparse_body_volume_gradients(c, c.positions());
    ASSERT_EQ(sparse.rows(), dense.rows());
    ASSERT_EQ(sparse.cols(), dense.cols());
    EXPECT_LE((Eigen::MatrixXd(sparse) - dense).cwiseAbs().maxCoeff(), 1e-15 * dense.norm());
    const PositionBasis P(c);
    const Eigen::MatrixXd reduced(P.restrict(sparse));
    ASSERT_EQ(reduced.rows(), P.size());
    for (int b = 0; b < c.n_bodies(); ++b)
        EXPECT_LE((reduced.col(b) - P.restrict(Eigen::VectorXd(dense.col(b)))).norm(),
                  1e-15 * dense.norm());
}

TEST(VolumeGradients, TwinTetrahedraSparseIsDenseAndLocal) {
    const Cluster c(test::twin_tetrahedra());
    expect_sparse_matches_dense(c);
    const Eigen::SparseMatrix<double> G = sparse_body_volume_gradients(c, c.positions());
    // vertex 3 is the upper tetrahedron's apex, vertex 4 the lower one's
    for (int d = 0; d < 3; ++d) {
        EXPECT_EQ(G.coeff(3 * 3 + d, 1), 0.0);
        EXPECT_EQ(G.coeff(3 * 4 + d, 0), 0.0);
    }
    EXPECT_EQ(G.nonZeros(), 2 * 4 * 3); // four vertices of three coordinates per body
}

TEST(VolumeGradients, AreTheVolumesDerivatives) {
    const Cluster c(test::twin_tetrahedra());
    const Eigen::MatrixXd G = body_volume_gradients(c);
    const double h = 1e-6;
    for (int v = 0; v < c.n_vertices(); ++v)
        for (int d = 0; d < 3; ++d) {
            std::vector<Vec3> plus = c.positions(), minus = c.positions();
            plus[v][d] += h, minus[v][d] -= h;
            const std::vector<double> Vp = body_volumes(c, plus), Vm = body_volumes(c, minus);
            for (int b = 0; b < c.n_bodies(); ++b)
                EXPECT_NEAR(G(3 * v + d, b), (Vp[b] - Vm[b]) / (2 * h), 1e-9)
                    << "vertex " << v << " coordinate " << d << " body " << b;
        }
}

// A lid (the cup's open rim on the floor) and vertices on one and on two walls.
TEST(VolumeGradients, SparseMatchesDenseWithLidsAndWalls) {
    expect_sparse_matches_dense(Cluster(with_walls(cup(1.0, 1.0, 4, 12), {floor_plane()})));
    expect_sparse_matches_dense(Cluster(corner_box(Vec3(1, 0.8, 0.6), 3)));
}

} // namespace
} // namespace froth
