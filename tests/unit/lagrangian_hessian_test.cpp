// The Hessian of minimize's Lagrangian (assembly/lagrangian_hessian.h) against central
// differences of its gradient, on twin tetrahedra (two bodies, a triple line) and an icosphere,
// moved off symmetry so that no block vanishes by accident.
#include "assembly/lagrangian_hessian.h"
#include "geometry/geometry.h"
#include "test_meshes.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include <random>
#include <vector>

namespace froth {
namespace {

/// d (sum sigma area - sum_b p_b V_b) / d X at X: the area's gradient sigma nu x e_i / 2 per
/// corner, the volumes' from geometry.h.
Eigen::VectorXd lagrangian_gradient(const Cluster& c, const std::vector<Vec3>& X,
                                    const std::vector<double>& p) {
    Eigen::VectorXd g = Eigen::VectorXd::Zero(3 * c.n_vertices());
    for (const Surface& s : c.surfaces())
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const auto x = s.corners(X, f);
            const Vec3 nu = (x[1] - x[0]).cross(x[2] - x[0]).normalized();
            for (int i = 0; i < 3; ++i)
                g.segment<3>(3 * s.triangles[f][i]) +=
                    0.5 * s.sigma * nu.cross(x[(i + 2) % 3] - x[(i + 1) % 3]);
        }
    const Eigen::MatrixXd G = body_volume_gradients(c, X);
    for (std::size_t b = 0; b < p.size(); ++b)
        g -= p[b] * G.col(b);
    return g;
}

void expect_hessian_is_derivative(Cluster c, const std::vector<double>& p) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> jitter(-0.05, 0.05);
    std::vector<Vec3> X = c.positions();
    for (Vec3& x : X)
        x += Vec3(jitter(random), jitter(random), jitter(random));
    c.set_positions(X);
    const Eigen::MatrixXd H(lagrangian_hessian(c, p));
    ASSERT_EQ(H.rows(), 3 * c.n_vertices());
    EXPECT_LE((H - H.transpose()).cwiseAbs().maxCoeff(), 1e-14 * H.norm()) << "symmetric";
    const double h = 1e-6;
    for (int k = 0; k < 3 * c.n_vertices(); ++k) {
        std::vector<Vec3> plus = X, minus = X;
        plus[k / 3][k % 3] += h, minus[k / 3][k % 3] -= h;
        const Eigen::VectorXd column =
            (lagrangian_gradient(c, plus, p) - lagrangian_gradient(c, minus, p)) / (2 * h);
        EXPECT_LE((H.col(k) - column).cwiseAbs().maxCoeff(), 1e-7 * (1 + column.norm()))
            << "column " << k;
    }
}

TEST(LagrangianHessian, TwinTetrahedraIsTheGradientsDerivative) {
    expect_hessian_is_derivative(Cluster(test::twin_tetrahedra()), {1.3, -0.7});
}

TEST(LagrangianHessian, IcosphereIsTheGradientsDerivative) {
    expect_hessian_is_derivative(Cluster(test::icosphere(1)), {2.0});
}

// A translation changes neither area nor volume: H annihilates it.
TEST(LagrangianHessian, TranslationsAreInItsKernel) {
    const Cluster c(test::twin_tetrahedra());
    const Eigen::MatrixXd H(lagrangian_hessian(c, {1.3, -0.7}));
    for (int d = 0; d < 3; ++d) {
        Eigen::VectorXd t = Eigen::VectorXd::Zero(H.cols());
        for (int v = 0; v < c.n_vertices(); ++v)
            t[3 * v + d] = 1;
        EXPECT_LE((H * t).norm(), 1e-13 * H.norm()) << "direction " << d;
    }
}

} // namespace
} // namespace froth
