// One-step properties of the schemes: energy decrease for any tau (Theorems 3.2, 3.4), volume
// conservation of surface diffusion, the sparse solves against dense solves, the W^h basis.
#include "assembly/kappa_basis.h"
#include "core/errors.h"
#include "flows/stepper.h"
#include "test_meshes.h"

#include <Eigen/Dense>
#include <gtest/gtest.h>

namespace froth {
namespace {

TEST(KappaBasis, OrthonormalAndInTheNullSpaceOfTheJunctionRows) {
    Cluster c(test::twin_tetrahedra());
    const KappaBasis Z = kappa_basis(c);
    Eigen::MatrixXd D = Eigen::MatrixXd::Zero(c.n_pairs(), Z.n_reduced);
    for (int k = 0; k < c.n_pairs(); ++k)
        for (int x = Z.start[k]; x < Z.start[k + 1]; ++x) D(k, Z.col[x]) = Z.val[x];
    EXPECT_LT((D.transpose() * D - Eigen::MatrixXd::Identity(Z.n_reduced, Z.n_reduced)).norm(),
              1e-12);
    for (const JunctionEdge& e : c.junction_edges())
        for (int v : {e.a, e.b}) {
            Eigen::RowVectorXd row = Eigen::RowVectorXd::Zero(c.n_pairs());
            for (int j = 0; j < 3; ++j) row[c.pair_index(v, e.surfaces[j])] = e.o[j];
            EXPECT_LT((row * D).norm(), 1e-12);
        }
    // 3 junction vertices keep 2 of 3 values each, the 2 apexes keep 1: 3*2 + 2 = 8.
    EXPECT_EQ(Z.n_reduced, 8);
}

TEST(Stepper, RejectsBadTauAndUnknownFlow) {
    Cluster c(test::icosphere(1));
    TimeStepper stepper;
    EXPECT_THROW(stepper.step(c, Flow::MeanCurvature, 0.0), InvalidInput);
    EXPECT_THROW(stepper.step(c, Flow::MeanCurvature, -1.0), InvalidInput);
    EXPECT_THROW(stepper.step(c, Flow::MeanCurvature, NAN), InvalidInput);
    EXPECT_THROW(parse_flow("willmore"), InvalidInput);
    EXPECT_EQ(c.time(), 0.0);
}

class AnyTau : public ::testing::TestWithParam<double> {};

// Unconditional stability: E(X^{m+1}) <= E(X^m) for every tau, for both flows, on a cluster
// with a triple line and unequal tensions.
TEST_P(AnyTau, EnergyDecreasesForBothFlows) {
    for (Flow flow : {Flow::MeanCurvature, Flow::SurfaceDiffusion}) {
        ClusterSpec spec = test::twin_tetrahedra();
        spec.surfaces[2].sigma = 1.4;
        Cluster c(spec);
        TimeStepper stepper;
        for (int m = 0; m < 3; ++m) {
            // A big MCF step may shrink the whole cluster to (nearly) a point: then the next
            // step must refuse with a clear error and leave the cluster as it was.
            const Cluster before = c;
            try {
                const StepReport r = stepper.step(c, flow, GetParam());
                EXPECT_LE(r.energy, r.energy_before * (1 + 1e-12)) << flow_name(flow) << m;
            } catch (const GeometryError& e) {
                EXPECT_EQ(flow, Flow::MeanCurvature) << e.what();
                const std::string what = e.what();
                EXPECT_TRUE(what.find("collapsed") != std::string::npos ||
                            what.find("would vanish") != std::string::npos)
                    << what;
                EXPECT_EQ(c.positions(), before.positions());
                break;
            }
        }
    }
}
INSTANTIATE_TEST_SUITE_P(Stepper, AnyTau, ::testing::Values(1e-3, 1e-1, 1.0, 10.0));

// Surface diffusion conserves the enclosed volume to first order in dX (Remark 2.1 and 3.1):
// on a sphere with small steps the loss is second order and tiny.
TEST(Stepper, SurfaceDiffusionNearlyConservesVolume) {
    Cluster c(test::icosphere(2));
    TimeStepper stepper;
    StepReport r;
    for (int m = 0; m < 5; ++m) r = stepper.step(c, Flow::SurfaceDiffusion, 1e-4);
    EXPECT_LT(r.volume_loss, 1e-5);
    EXPECT_LT(r.energy, energy(Cluster(test::icosphere(2))));
}

// The sparse solution of one MCF step solves the dense normal equations (4.6b) built here
// from scratch, independently of the pattern assembler.
TEST(Stepper, MeanCurvatureStepMatchesDenseSolve) {
    Cluster c(test::icosphere(1));
    const Cluster before = c;
    const double tau = 0.01;
    const int n = 3 * c.n_vertices();
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n);
    for (const Tri& t : c.surface(0).triangles) {
        const auto K = local_stiffness(c.position(t[0]), c.position(t[1]), c.position(t[2]));
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                A.block<3, 3>(3 * t[a], 3 * t[b]) += K(a, b) * Eigen::Matrix3d::Identity();
    }
    Eigen::VectorXd X(n);
    for (int v = 0; v < c.n_vertices(); ++v) X.segment<3>(3 * v) = c.position(v);
    const PairGeometry g = pair_geometry(c);
    Eigen::MatrixXd M = A;
    for (int v = 0; v < c.n_vertices(); ++v)
        M.block<3, 3>(3 * v, 3 * v) += g.mass[v] * g.omega[v] * g.omega[v].transpose() / tau;
    const Eigen::VectorXd dX = M.ldlt().solve(-A * X);
    TimeStepper stepper;
    stepper.step(c, Flow::MeanCurvature, tau);
    for (int v = 0; v < c.n_vertices(); ++v)
        EXPECT_LT((c.position(v) - before.position(v) - dX.segment<3>(3 * v)).norm(), 1e-12);
}

// One SD step against the dense saddle point (3.6a,b) built here from scratch, facet by facet,
// and solved by full-pivot LU; W^h enters through the basis Z (tested above).
TEST(Stepper, SurfaceDiffusionStepMatchesDenseSolve) {
    ClusterSpec spec = test::twin_tetrahedra();
    spec.surfaces[1].sigma = 1.5;
    Cluster c(spec);
    const Cluster before = c;
    const double tau = 0.05;
    const int n = 3 * c.n_vertices(), np = c.n_pairs();
    const KappaBasis Zb = kappa_basis(c);
    Eigen::MatrixXd Z = Eigen::MatrixXd::Zero(np, Zb.n_reduced);
    for (int k = 0; k < np; ++k)
        for (int x = Zb.start[k]; x < Zb.start[k + 1]; ++x) Z(k, Zb.col[x]) = Zb.val[x];
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(n, n), As = Eigen::MatrixXd::Zero(np, np);
    Eigen::MatrixXd N = Eigen::MatrixXd::Zero(n, np);
    for (int i = 0; i < c.n_surfaces(); ++i)
        for (const Tri& t : c.surface(i).triangles) {
            const auto K = local_stiffness(c.position(t[0]), c.position(t[1]), c.position(t[2]));
            const Vec3 a2 = area_vector2(c.positions(), t);
            for (int a = 0; a < 3; ++a) {
                // <kappa nu, eta>^h: each corner gets |sigma|/3 nu_sigma
                N.block<3, 1>(3 * t[a], c.pair_index(t[a], i)) += a2 / 6.0;
                for (int b = 0; b < 3; ++b) {
                    A.block<3, 3>(3 * t[a], 3 * t[b]) +=
                        c.surface(i).sigma * K(a, b) * Eigen::Matrix3d::Identity();
                    As(c.pair_index(t[a], i), c.pair_index(t[b], i)) += K(a, b);
                }
            }
        }
    const int m = Zb.n_reduced;
    Eigen::MatrixXd S(n + m, n + m);
    S << A, N * Z, Z.transpose() * N.transpose(), -tau * Z.transpose() * As * Z;
    Eigen::VectorXd X(n), rhs = Eigen::VectorXd::Zero(n + m);
    for (int v = 0; v < c.n_vertices(); ++v) X.segment<3>(3 * v) = c.position(v);
    rhs.head(n) = -A * X;
    const Eigen::VectorXd sol = S.fullPivLu().solve(rhs);
    TimeStepper stepper;
    stepper.set_exact_volumes(false); // the seed's scheme (3.6)/(3.8) is under test
    stepper.step(c, Flow::SurfaceDiffusion, tau);
    for (int v = 0; v < c.n_vertices(); ++v)
        EXPECT_LT((c.position(v) - before.position(v) - sol.segment<3>(3 * v)).norm(), 1e-10);
}

// On a sphere, kappa from MCF is about -2/R and the radius shrinks like R^2 = R0^2 - 4t.
TEST(Stepper, SphereShrinksUnderMeanCurvatureFlow) {
    Cluster c(test::icosphere(3));
    TimeStepper stepper;
    for (int m = 0; m < 10; ++m) stepper.step(c, Flow::MeanCurvature, 0.005);
    double r2 = 0;
    for (const Vec3& x : c.positions()) r2 += x.squaredNorm() / c.n_vertices();
    EXPECT_NEAR(r2, 1.0 - 4 * 0.05, 0.01);
}

} // namespace
} // namespace froth
