// The anisotropic schemes (3.7)/(3.8) with (3.9) on whole clusters: A_gamma X against the finite-
// difference gradient of the discrete energy, unconditional stability (Theorem 3.2), Newton's
// method for r > 1, mobilities, and the self-similar shrinking Wulff shape of (5.4)/(5.5).
#include "assembly/stiffness.h"
#include "schemes/mean_curvature.h"
#include "schemes/surface_diffusion.h"
#include "core/errors.h"
#include "flows/stepper.h"
#include "geometry/geometry.h"
#include "solvers/sparse_solvers.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <random>
#include <string>

namespace froth {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;

struct Named {
    std::string name;
    std::shared_ptr<const Anisotropy> gamma;
};

std::vector<Named> presets(bool nonlinear) {
    Matrix3d G;
    G << 2.0, 0.3, -0.1, 0.3, 1.0, 0.2, -0.1, 0.2, 0.5;
    auto make = [](Anisotropy a) { return std::make_shared<const Anisotropy>(std::move(a)); };
    if (nonlinear)
        return {{"l1(0.1, r=3)", make(Anisotropy::l1(0.1, 3.0))},
                {"fig3_left", make(Anisotropy::fig3_left())},
                {"fig3_right", make(Anisotropy::fig3_right())}};
    return {{"isotropic(1.7)", make(Anisotropy::isotropic(1.7))},
            {"ellipsoidal", make(Anisotropy::ellipsoidal(G))},
            {"l1(0.1)", make(Anisotropy::l1(0.1))},
            {"l1(0.01)", make(Anisotropy::l1(0.01))},
            {"hexagonal", make(Anisotropy::hexagonal())}};
}

/// Two tetrahedra with jittered vertices, surface 3 of tension 1.3: junction edges, unequal
/// tensions, no symmetry to hide a sign error.
Cluster jittered_twins(unsigned seed) {
    ClusterSpec s = test::twin_tetrahedra();
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-0.05, 0.05);
    for (Vec3& x : s.vertices) x += Vec3(u(rng), u(rng), u(rng));
    s.surfaces[2].sigma = 1.3;
    return Cluster(std::move(s));
}

/// Central differences of energy(c) in every coordinate.
Eigen::VectorXd energy_gradient_fd(Cluster& c, double h) {
    std::vector<Vec3> X = c.positions();
    Eigen::VectorXd g(3 * c.n_vertices());
    for (int v = 0; v < c.n_vertices(); ++v)
        for (int d = 0; d < 3; ++d) {
            std::vector<Vec3> Y = X;
            Y[v][d] += h;
            c.set_positions(Y);
            const double ep = energy(c);
            Y[v][d] -= 2 * h;
            c.set_positions(Y);
            const double em = energy(c);
            g[3 * v + d] = (ep - em) / (2 * h);
        }
    c.set_positions(X);
    return g;
}

void expect_gradient(Cluster& c, const FacetNormals* lagged, const std::string& name) {
    const Eigen::VectorXd AX = apply_stiffness(c, c.positions(), lagged);
    const Eigen::VectorXd fd = energy_gradient_fd(c, 1e-6);
    EXPECT_LT((AX - fd).lpNorm<Eigen::Infinity>(), 1e-6 * fd.lpNorm<Eigen::Infinity>()) << name;
}

TEST(AnisotropicAssembly, AgammaXIsTheEnergyGradientForEveryLinearPreset) {
    // (1.24b): for r = 1, <grad^Gt X, grad^Gt chi>_gamma = d/deps E_gamma(X + eps chi), so the
    // assembled A_gamma X^m must be the gradient of sum_i sigma_i gamma_i(nu)|sigma|.
    for (const Named& p : presets(false)) {
        Cluster c = jittered_twins(7);
        c.set_anisotropy(0, p.gamma);
        c.set_anisotropy(2, p.gamma);
        expect_gradient(c, nullptr, p.name);
    }
}

TEST(AnisotropicAssembly, AgammaXIsTheGradientForRGreaterThanOneAtTheOwnNormals) {
    // With the lagged normals equal to the facets' own, (3.9) is the exact first variation too.
    for (const Named& p : presets(true)) {
        Cluster c = jittered_twins(11);
        for (int i = 0; i < c.n_surfaces(); ++i) c.set_anisotropy(i, p.gamma);
        const FacetNormals own = facet_normals(c, c.positions());
        expect_gradient(c, &own, p.name);
    }
}

TEST(AnisotropicAssembly, IsotropicAnisotropyMatchesTheIsotropicPath) {
    Cluster a = jittered_twins(3), b = jittered_twins(3);
    b.set_anisotropy(1, std::make_shared<const Anisotropy>(Anisotropy::isotropic(2.2)));
    a.set_sigma(1, 2.2); // below 1 + 1.3: the tensions meet the triangle inequality
    EXPECT_NEAR(energy(a), energy(b), 1e-14 * energy(a));
    EXPECT_LT((apply_stiffness(a, a.positions()) - apply_stiffness(b, b.positions()))
                  .lpNorm<Eigen::Infinity>(),
              1e-13);
}

class AnisotropicAnyTau : public ::testing::TestWithParam<double> {};

TEST_P(AnisotropicAnyTau, EnergyDecreasesForBothFlowsAndEveryPreset) {
    // Theorem 3.2: |Gamma^{m+1}|_gamma <= |Gamma^m|_gamma for any tau (3.21a,b).
    const double tau = GetParam();
    for (bool nonlinear : {false, true})
        for (const Named& p : presets(nonlinear))
            for (Flow flow : {Flow::MeanCurvature, Flow::SurfaceDiffusion}) {
                ClusterSpec s = test::icosphere(2);
                for (Vec3& x : s.vertices) x = Vec3(1.3 * x[0], x[1], 0.8 * x[2]);
                Cluster c(std::move(s));
                c.set_anisotropy(0, p.gamma);
                TimeStepper stepper;
                stepper.set_fixed_point({1e-8, 60, tau > 1e-3 ? 1 : 4}); // keep the test fast
                for (int m = 0; m < 3; ++m) {
                    StepReport r;
                    try {
                        r = stepper.step(c, flow, tau);
                    } catch (const GeometryError&) {
                        break; // MCF with tau = 10 shrinks the sphere to a point in one step
                    } catch (const ConvergenceError&) {
                        EXPECT_TRUE(nonlinear && tau > 1e-3) << p.name << " tau " << tau;
                        break; // reported, and the cluster is unchanged (tested below)
                    }
                    EXPECT_LE(r.energy, r.energy_before * (1 + 1e-12))
                        << p.name << " " << flow_name(flow) << " tau " << tau << " step " << m;
                    if (!nonlinear) EXPECT_EQ(r.fixed_point_iterations, 0) << p.name;
                }
            }
}

INSTANTIATE_TEST_SUITE_P(AnisotropicSteps, AnisotropicAnyTau,
                         ::testing::Values(1e-3, 1e-1, 10.0));

TEST(AnisotropicSteps, RGreaterThanOneIteratesToTheTolerance) {
    ClusterSpec s = test::icosphere(2);
    Cluster c(std::move(s));
    c.set_anisotropy(0, std::make_shared<const Anisotropy>(Anisotropy::fig3_left()));
    TimeStepper stepper;
    for (Flow flow : {Flow::MeanCurvature, Flow::SurfaceDiffusion}) {
        const StepReport r = stepper.step(c, flow, 1e-4);
        EXPECT_GE(r.fixed_point_iterations, 2);
        EXPECT_LE(r.fixed_point_change, stepper.fixed_point().tol);
        EXPECT_LE(r.energy, r.energy_before);
    }
}

/// X^m + T z for the solution z of the step's linear system on c (at X^m) with the (3.9)
/// weights at the normals nu: one solve of the lagged (Picard) iteration of §4.2.
std::vector<Vec3> lagged_solve(const Cluster& c, Flow flow, double tau, const FacetNormals& nu) {
    const PairGeometry g = pair_geometry(c);
    const PositionBasis P(c);
    SparseBuilder M;
    Eigen::VectorXd rhs;
    if (flow == Flow::MeanCurvature) {
        assemble_mcf(c, g, P, tau, &nu, M, rhs);
    } else {
        assemble_sd(c, g, kappa_basis(c), P, tau, &nu, M, rhs);
    }
    SparseDirectSolver solver(Factorization::LU, false);
    const Eigen::VectorXd z = solver.solve(M.finish(), rhs);
    std::vector<Vec3> X = c.positions();
    for (int v = 0; v < c.n_vertices(); ++v) X[v] += P.displacement(z, v);
    return X;
}

TEST(AnisotropicSteps, NewtonsSolutionIsAFixedPointOfTheLaggedIteration) {
    // The r > 1 step solves (3.9) with the weights at its own new normals: solving the linear
    // system once more with the weights at nu(X^{m+1}) must give X^{m+1} back. r = 30 at the
    // seed's tau = 1e-3 (Fig. 20), where the plain lagged iteration cycles.
    for (Flow flow : {Flow::MeanCurvature, Flow::SurfaceDiffusion}) {
        Cluster c(test::icosphere(2));
        c.set_anisotropy(0, std::make_shared<const Anisotropy>(Anisotropy::fig3_right()));
        TimeStepper stepper;
        stepper.set_exact_volumes(false); // the seed's scheme (3.6)/(3.8) is under test
        for (int m = 0; m < 3; ++m) {
            const Cluster before = c;
            const StepReport r = stepper.step(c, flow, 1e-3);
            EXPECT_LE(r.energy, r.energy_before) << flow_name(flow);
            EXPECT_LE(r.fixed_point_change, stepper.fixed_point().tol);
            const std::vector<Vec3> again =
                lagged_solve(before, flow, 1e-3, facet_normals(before, c.positions()));
            double err = 0;
            for (int v = 0; v < c.n_vertices(); ++v)
                err = std::max(err, (again[v] - c.position(v)).norm());
            EXPECT_LT(err, 1e-7) << flow_name(flow) << " step " << m; // radius 1
        }
    }
}

TEST(AnisotropicSteps, NonConvergenceIsAnErrorAndLeavesTheClusterUnchanged) {
    Cluster c(test::icosphere(2));
    c.set_anisotropy(0, std::make_shared<const Anisotropy>(Anisotropy::fig3_right()));
    TimeStepper stepper;
    stepper.set_fixed_point({1e-30, 2, 1}); // unreachable
    const std::vector<Vec3> X = c.positions();
    try {
        stepper.step(c, Flow::MeanCurvature, 1e-3);
        ADD_FAILURE() << "expected ConvergenceError";
    } catch (const ConvergenceError& e) {
        EXPECT_NE(std::string(e.what()).find("did not converge in 2 solves"), std::string::npos)
            << e.what();
    }
    EXPECT_EQ(c.positions(), X);
    EXPECT_EQ(c.time(), 0.0);
    EXPECT_THROW(stepper.set_fixed_point({0.0, 10}), InvalidInput);
    EXPECT_THROW(stepper.set_fixed_point({1e-8, 1}), InvalidInput);
}

TEST(AnisotropicSteps, SwitchingAnisotropyBetweenStepsRebuildsThePattern) {
    Cluster c(test::icosphere(2));
    TimeStepper stepper;
    for (Flow flow : {Flow::MeanCurvature, Flow::SurfaceDiffusion}) {
        stepper.step(c, flow, 1e-3);
        c.set_anisotropy(0, std::make_shared<const Anisotropy>(Anisotropy::l1(0.2)));
        const StepReport r = stepper.step(c, flow, 1e-3);
        EXPECT_LE(r.energy, r.energy_before);
        c.set_anisotropy(0, nullptr);
        EXPECT_LE(stepper.step(c, flow, 1e-3).energy, energy(c) * (1 + 1e-12));
    }
}

/// max_v |ratio of the normal displacements of b and a - 2|.
double normal_displacement_ratio_error(const Cluster& c0, const Cluster& a, const Cluster& b) {
    const PairGeometry g = pair_geometry(c0);
    double err = 0;
    for (int v = 0; v < c0.n_vertices(); ++v) {
        const Vec3 n = g.omega[c0.pair_begin(v)].normalized();
        const double da = (a.position(v) - c0.position(v)).dot(n);
        const double db = (b.position(v) - c0.position(v)).dot(n);
        err = std::max(err, std::abs(db / da - 2));
    }
    return err;
}

TEST(Mobility, ConstantBetaScalesTheVelocity) {
    // (3.7a): V = beta kappa_gamma, so with beta = 2 every vertex moves twice as far along its
    // normal to O(tau) (tangential motion is the mesh's own and does not scale).
    ClusterSpec s = test::icosphere(2);
    for (Vec3& x : s.vertices) x[2] *= 0.7;
    const Cluster c0{ClusterSpec(s)};
    Cluster a{ClusterSpec(s)}, b{ClusterSpec(s)};
    b.set_mobility(0, Mobility::constant(2.0));
    TimeStepper sa, sb;
    sa.step(a, Flow::MeanCurvature, 1e-6);
    sb.step(b, Flow::MeanCurvature, 1e-6);
    EXPECT_LT(normal_displacement_ratio_error(c0, a, b), 1e-3);
}

TEST(Mobility, GammaMobilityOfAnIsotropicSurfaceIsSigma) {
    Cluster a(test::icosphere(2)), b(test::icosphere(2));
    a.set_sigma(0, 1.5), b.set_sigma(0, 1.5);
    a.set_mobility(0, Mobility::constant(1.5));
    b.set_mobility(0, Mobility::energy_density());
    TimeStepper sa, sb;
    for (Flow flow : {Flow::MeanCurvature, Flow::SurfaceDiffusion}) {
        sa.step(a, flow, 1e-2), sb.step(b, flow, 1e-2);
        for (int v = 0; v < a.n_vertices(); ++v)
            EXPECT_LT((a.position(v) - b.position(v)).norm(), 1e-12);
    }
}

TEST(Mobility, BadValuesAreErrorsNamingTheSurface) {
    EXPECT_THROW(Mobility::constant(0.0), InvalidInput);
    EXPECT_THROW(Mobility::constant(NAN), InvalidInput);
    Cluster c(test::icosphere(1));
    c.set_mobility(0, Mobility::function([](const Vector3d& nu) { return nu[2]; }, "nu_z"));
    const std::vector<Vec3> X = c.positions();
    TimeStepper stepper;
    try {
        stepper.step(c, Flow::MeanCurvature, 1e-3);
        ADD_FAILURE() << "expected InvalidInput";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("surface 1: the mobility nu_z is"), std::string::npos)
            << e.what();
    }
    EXPECT_EQ(c.positions(), X);
}

TEST(AnisotropicSteps, ClosedWulffShapeShrinksSelfSimilarlyWithBetaGamma) {
    // Soner's solution behind (5.4)/(5.5), for a closed surface: with beta = gamma the boundary
    // of the Wulff shape shrinks as {gamma*(q) = sqrt(1 - 4t)}; for gamma(p) = sqrt(p.Gp),
    // gamma*(q) = sqrt(q.G^-1 q). Every vertex must stay on that level set to O(h^2).
    const Matrix3d G = Eigen::Vector3d(1.0, 0.25, 0.25).asDiagonal();
    ClusterSpec s = test::icosphere(3);
    for (Vec3& x : s.vertices) x = Eigen::Vector3d(1.0, 0.5, 0.5).asDiagonal() * x;
    Cluster c(std::move(s));
    c.set_anisotropy(0, std::make_shared<const Anisotropy>(Anisotropy::ellipsoidal(G)));
    c.set_mobility(0, Mobility::energy_density());
    TimeStepper stepper;
    const double tau = 1e-4;
    for (int m = 0; m < 1000; ++m) stepper.step(c, Flow::MeanCurvature, tau);
    const double expected = std::sqrt(1 - 4 * c.time()); // t = 0.1
    double err = 0;
    for (const Vec3& x : c.positions())
        err = std::max(err, std::abs(std::sqrt(x.dot(G.inverse() * x)) - expected));
    EXPECT_LT(err, 0.01) << "t = " << c.time();
}

} // namespace
} // namespace froth

namespace froth {
namespace {

TEST(EllipsoidDistance, PointsAlongTheNormalAreAtTheirOffset) {
    // y on the ellipsoid, n its unit normal (grad of sum (y_i/a_i)^2): y + s n is at distance
    // |s| for |s| below the smallest radius of curvature.
    const Vec3 a(1.0, 0.5, 0.1);
    std::mt19937 rng(5);
    std::normal_distribution<double> g;
    for (int k = 0; k < 200; ++k) {
        Vec3 u(g(rng), g(rng), g(rng));
        u.normalize();
        const Vec3 y = a.cwiseProduct(u);
        const Vec3 n = u.cwiseQuotient(a).normalized();
        for (double s : {-0.005, 0.0, 0.01, 0.3})
            EXPECT_NEAR(distance_to_ellipsoid(y + s * n, a), std::abs(s), 1e-12)
                << "u = " << u.transpose() << " s = " << s;
    }
    EXPECT_THROW(distance_to_ellipsoid(Vec3(1, 0, 0), Vec3(1, 0, 1)), InvalidInput);
}

} // namespace
} // namespace froth
