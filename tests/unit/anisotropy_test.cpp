// Anisotropies of the class (1.15): presets (1.17)/(5.6)/Figs. 2-3, gamma', gamma* (1.16) and the
// element matrices of (1.24a,b) (numerics.md "Anisotropy"). Invariants and finite differences,
// no golden numbers except closed forms.
#include "anisotropy/anisotropy.h"
#include "assembly/stiffness.h"
#include "core/errors.h"

#include "expect_error.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <type_traits>

namespace froth {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using Tri = std::array<Vector3d, 3>;

struct Named {
    std::string name;
    Anisotropy gamma;
};

std::vector<Named> all_presets() {
    Matrix3d G;
    G << 2.0, 0.3, -0.1, 0.3, 1.0, 0.2, -0.1, 0.2, 0.5;
    return {
        {"isotropic(1.7)", Anisotropy::isotropic(1.7)},
        {"ellipsoidal", Anisotropy::ellipsoidal(G)},
        {"l1(0.1)", Anisotropy::l1(0.1)},
        {"l1(0.01)", Anisotropy::l1(0.01)},
        {"hexagonal", Anisotropy::hexagonal()},
        {"fig3_left", Anisotropy::fig3_left()},
        {"fig3_right", Anisotropy::fig3_right()},
    };
}

std::vector<Named> r1_presets() {
    std::vector<Named> out;
    for (auto& n : all_presets())
        if (n.gamma.r() == 1.0) out.push_back(n);
    return out;
}

Vector3d random_vector(std::mt19937& rng, double scale = 1.0) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    return scale * Vector3d(u(rng), u(rng), u(rng));
}

// A random triangle with all angles above 15 degrees.
Tri random_triangle(std::mt19937& rng) {
    for (;;) {
        Tri x = {random_vector(rng, 2.0), random_vector(rng, 2.0), random_vector(rng, 2.0)};
        double min_angle = 180.0;
        for (int a = 0; a < 3; ++a) {
            const Vector3d u = x[(a + 1) % 3] - x[a], v = x[(a + 2) % 3] - x[a];
            min_angle = std::min(min_angle, std::acos(u.normalized().dot(v.normalized())) * 180.0 /
                                                std::numbers::pi);
        }
        if (min_angle > 15.0) return x;
    }
}

using Vector9d = Eigen::Matrix<double, 9, 1>;

// The triangle's corners as one 9-vector (x_0, x_1, x_2), the element matrices' ordering.
Vector9d stacked(const Tri& x) {
    Vector9d X;
    for (int a = 0; a < 3; ++a) X.segment<3>(3 * a) = x[a];
    return X;
}

Vector3d unit_normal(const Tri& x) { return (x[1] - x[0]).cross(x[2] - x[0]).normalized(); }

// Central difference of f (a function of the triangle) in coordinate k of the 9-vector; the
// result has f's type (evaluated: no Eigen expression may outlive f's temporaries).
template <class F, class R = std::decay_t<std::invoke_result_t<const F&, const Tri&>>>
R central_difference(const F& f, const Tri& x, int k, double h) {
    Tri xp = x, xm = x;
    xp[k / 3][k % 3] += h;
    xm[k / 3][k % 3] -= h;
    return (f(xp) - f(xm)) / (2 * h);
}

using test::expect_invalid;

// --- presets ---------------------------------------------------------------------------------

TEST(AnisotropyPresets, IsotropicIsSigmaTimesNorm) {
    const Anisotropy g = Anisotropy::isotropic(1.7);
    EXPECT_TRUE(g.is_isotropic());
    std::mt19937 rng(1);
    for (int i = 0; i < 20; ++i) {
        const Vector3d p = random_vector(rng, 3.0);
        EXPECT_NEAR(g.gamma(p), 1.7 * p.norm(), 1e-14 * p.norm());
        EXPECT_LT((g.gamma_prime(p) - 1.7 * p.normalized()).norm(), 1e-14);
        EXPECT_NEAR(g.gamma_star(p), p.norm() / 1.7, 1e-13 * p.norm());
    }
    EXPECT_FALSE(Anisotropy::l1(0.1).is_isotropic());
}

// (5.6) written out term by term must agree with (1.17) at the angles of Fig. 2 left.
TEST(AnisotropyPresets, L1MatchesEquation56) {
    std::mt19937 rng(2);
    for (double eps : {0.5, 0.1, 0.01}) {
        const Anisotropy g = Anisotropy::l1(eps);
        EXPECT_EQ(g.n_terms(), 3);
        EXPECT_EQ(g.r(), 1.0);
        for (int i = 0; i < 20; ++i) {
            const Vector3d p = random_vector(rng);
            double ref = 0.0;
            for (int j = 0; j < 3; ++j)
                ref += std::sqrt(eps * eps * p.squaredNorm() + p[j] * p[j] * (1 - eps * eps));
            EXPECT_NEAR(g.gamma(p), ref, 1e-14);
        }
    }
}

// Every (1.17) term is eps^2 I + (1 - eps^2) a a^T with a the first row of R(theta); the rows
// below are worked out by hand from R1, R2, R3 of the seed, independently of the code.
TEST(AnisotropyPresets, NearlyCrystallineMeansSeveralTermsOneNeedleLike) {
    EXPECT_TRUE(Anisotropy::l1(0.199).nearly_crystalline()); // the limit 0.2 itself is round-off
    EXPECT_TRUE(Anisotropy::l1(0.01).nearly_crystalline());
    EXPECT_TRUE(Anisotropy::hexagonal().nearly_crystalline());
    EXPECT_TRUE(Anisotropy::fig3_left().nearly_crystalline());
    EXPECT_TRUE(Anisotropy::fig3_right().nearly_crystalline());
    EXPECT_FALSE(Anisotropy::l1(0.21).nearly_crystalline());
    EXPECT_FALSE(Anisotropy::isotropic(2.0).nearly_crystalline());
    EXPECT_FALSE(Anisotropy::from_angles(0.01, {Vector3d::Zero()}).nearly_crystalline());
    EXPECT_FALSE(Anisotropy::ellipsoidal(Eigen::Vector3d(1, 0.01, 0.01).asDiagonal()).nearly_crystalline());
}

TEST(AnisotropyPresets, TermsAreTheRotatedDiagonalOf117) {
    const double s = std::sqrt(0.5), h = std::sqrt(3.0) / 2;
    const double eps = 1e-2;
    struct Case {
        Anisotropy g;
        double r;
        std::vector<Vector3d> a;
    };
    const std::vector<Case> cases = {
        {Anisotropy::hexagonal(eps), 1.0, {{1, 0, 0}, {0.5, 0, h}, {-0.5, 0, h}, {0, 1, 0}}},
        {Anisotropy::fig3_left(eps), 30.0, {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}},
        {Anisotropy::fig3_right(eps),
         30.0,
         {{1, 0, 0}, {0, 0, 1}, {s, s, 0}, {s, -s, 0}, {0, -s, s}, {0, s, s}}},
    };
    for (const Case& c : cases) {
        ASSERT_EQ(c.g.n_terms(), static_cast<int>(c.a.size()));
        EXPECT_EQ(c.g.r(), c.r);
        for (int l = 0; l < c.g.n_terms(); ++l) {
            const Matrix3d ref =
                eps * eps * Matrix3d::Identity() + (1 - eps * eps) * c.a[l] * c.a[l].transpose();
            EXPECT_LT((c.g.G(l) - ref).norm(), 1e-14) << "term " << l + 1;
            // (1.24a): Gt = det(G)^(1/2) G^-1.
            EXPECT_LT((c.g.G_tilde(l) * c.g.G(l) -
                       std::sqrt(c.g.G(l).determinant()) * Matrix3d::Identity())
                          .norm(),
                      1e-13);
        }
    }
}

// --- gamma -----------------------------------------------------------------------------------

TEST(AnisotropyGamma, HomogeneousEvenAndConvex) {
    std::mt19937 rng(3);
    for (const Named& n : all_presets()) {
        const Anisotropy& g = n.gamma;
        EXPECT_EQ(g.gamma(Vector3d::Zero()), 0.0);
        for (int i = 0; i < 50; ++i) {
            const Vector3d p = random_vector(rng), q = random_vector(rng);
            const double lambda = 0.01 + 10.0 * std::abs(p[0]);
            EXPECT_GT(g.gamma(p), 0.0) << n.name;
            EXPECT_NEAR(g.gamma(lambda * p), lambda * g.gamma(p), 1e-13 * lambda * g.gamma(p))
                << n.name;
            EXPECT_NEAR(g.gamma(-p), g.gamma(p), 1e-14 * g.gamma(p)) << n.name;
            // convexity (and, with homogeneity, the triangle inequality)
            for (double t : {0.25, 0.5, 0.9})
                EXPECT_LE(g.gamma(t * p + (1 - t) * q),
                          t * g.gamma(p) + (1 - t) * g.gamma(q) + 1e-14)
                    << n.name;
            EXPECT_LE(g.gamma(p + q), g.gamma(p) + g.gamma(q) + 1e-14) << n.name;
            // the Hessian is positive semidefinite with p in its kernel
            const Matrix3d H = g.gamma_hessian(p);
            const Eigen::SelfAdjointEigenSolver<Matrix3d> eig(H);
            EXPECT_GE(eig.eigenvalues().minCoeff(), -1e-9 * eig.eigenvalues().maxCoeff()) << n.name;
            EXPECT_LT((H * p).norm(), 1e-9 * H.norm() * p.norm()) << n.name;
        }
    }
}

TEST(AnisotropyGamma, PrimeMatchesCentralDifferences) {
    std::mt19937 rng(4);
    const double h = 1e-6;
    for (const Named& n : all_presets()) {
        const Anisotropy& g = n.gamma;
        double worst = 0.0, worst_hess = 0.0;
        for (int i = 0; i < 30; ++i) {
            const Vector3d p = random_vector(rng).normalized();
            const Vector3d d = g.gamma_prime(p);
            const Matrix3d H = g.gamma_hessian(p);
            for (int k = 0; k < 3; ++k) {
                const Vector3d e = h * Vector3d::Unit(k);
                const double fd = (g.gamma(p + e) - g.gamma(p - e)) / (2 * h);
                worst = std::max(worst, std::abs(d[k] - fd));
                const Vector3d fd2 = (g.gamma_prime(p + e) - g.gamma_prime(p - e)) / (2 * h);
                worst_hess = std::max(worst_hess, (H.col(k) - fd2).norm() / (1.0 + H.norm()));
            }
            // Euler: gamma'(p) . p = gamma(p); degree 0 homogeneity
            EXPECT_NEAR(d.dot(p), g.gamma(p), 1e-13 * g.gamma(p)) << n.name;
            EXPECT_LT((g.gamma_prime(7.5 * p) - d).norm(), 1e-13 * d.norm()) << n.name;
        }
        // measured: at most 1e-9 (gamma') and 4.4e-9 (gamma'') over the presets
        EXPECT_LT(worst, 1e-8) << n.name;
        EXPECT_LT(worst_hess, 1e-7) << n.name;
    }
}

TEST(AnisotropyGamma, LaggedWeightsReproduceGamma) {
    // sum_l w_l gamma_l(nu) = gamma(nu) for w_l = (gamma_l/gamma)^(r-1); all w_l = 1 for r = 1.
    std::mt19937 rng(5);
    for (const Named& n : all_presets()) {
        const Vector3d nu = random_vector(rng).normalized();
        const std::vector<double> w = n.gamma.term_weights(nu);
        double s = 0.0;
        for (int l = 0; l < n.gamma.n_terms(); ++l) {
            s += w[l] * n.gamma.gamma_term(l, nu);
            if (n.gamma.r() == 1.0) EXPECT_EQ(w[l], 1.0);
        }
        EXPECT_NEAR(s, n.gamma.gamma(nu), 1e-14) << n.name;
    }
}

TEST(AnisotropyGamma, WeightGradientsMatchCentralDifferences) {
    // dw_l/dp of the (3.9) weights, at unit and non-unit p (homogeneous of degree -1).
    std::mt19937 rng(6);
    const double h = 1e-7;
    for (const Named& n : all_presets()) {
        const Anisotropy& g = n.gamma;
        double worst = 0.0;
        for (int i = 0; i < 20; ++i) {
            const Vector3d p = random_vector(rng).normalized() * (i % 2 ? 2.5 : 1.0);
            const std::vector<Vector3d> d = g.term_weight_gradients(p);
            ASSERT_EQ(static_cast<int>(d.size()), g.n_terms());
            for (int k = 0; k < 3; ++k) {
                const Vector3d e = h * Vector3d::Unit(k);
                const std::vector<double> wp = g.term_weights(p + e), wm = g.term_weights(p - e);
                for (int l = 0; l < g.n_terms(); ++l)
                    worst = std::max(worst, std::abs(d[l][k] - (wp[l] - wm[l]) / (2 * h)));
            }
            for (int l = 0; l < g.n_terms(); ++l) {
                if (g.r() == 1.0) EXPECT_EQ(d[l].norm(), 0.0) << n.name;
                EXPECT_NEAR(d[l].dot(p), 0.0, 1e-12 * (1 + d[l].norm())) << n.name; // degree 0
            }
        }
        // the r = 30 weights switch within a few degrees: gradients up to ~50, FD error ~1e-6
        EXPECT_LT(worst, 1e-5) << n.name;
    }
}

// --- gamma* ----------------------------------------------------------------------------------

TEST(AnisotropyStar, ClosedFormsForOneTerm) {
    Matrix3d G;
    G << 2.0, 0.3, -0.1, 0.3, 1.0, 0.2, -0.1, 0.2, 0.5;
    const Anisotropy g = Anisotropy::ellipsoidal(G);
    std::mt19937 rng(6);
    for (int i = 0; i < 20; ++i) {
        const Vector3d q = random_vector(rng, 2.0);
        EXPECT_NEAR(g.gamma_star(q), std::sqrt(q.dot(G.inverse() * q)), 1e-13 * q.norm());
    }
    // Table 1's G = diag(1, eps^2, eps^2): gamma*(q) = sqrt(q1^2 + (q2^2 + q3^2)/eps^2).
    const Anisotropy t1 = Anisotropy::ellipsoidal(Vector3d(1, 0.01, 0.01).asDiagonal());
    EXPECT_NEAR(t1.gamma_star(Vector3d(0.3, 0.4, 0.0)), std::sqrt(0.09 + 0.16 / 0.01), 1e-12);
    EXPECT_EQ(g.gamma_star(Vector3d::Zero()), 0.0);
}

TEST(AnisotropyStar, AxisValuesOfTheL1Family) {
    // By symmetry gamma'(e1) is parallel to e1, so gamma*(e1) = 1 / gamma(e1):
    // 1/(1 + 2 eps) for (5.6), (1 + 2 eps^30)^(-1/30) for Fig. 3 left.
    for (double eps : {0.1, 0.01}) {
        EXPECT_NEAR(Anisotropy::l1(eps).gamma_star(Vector3d(0, 0, 2)), 2.0 / (1 + 2 * eps), 1e-13);
        EXPECT_NEAR(Anisotropy::l1(eps, 30).gamma_star(Vector3d(0, -1, 0)),
                    std::pow(1 + 2 * std::pow(eps, 30), -1.0 / 30), 1e-13);
    }
}

// Brute force: the largest (q . p)/gamma(p) over a Fibonacci sphere of 200000 points, then three
// times over a 201 x 201 tangent grid around the best point so far, each 50x finer. A lower
// bound for gamma*(q) (every value is attained).
double brute_star(const Anisotropy& g, const Vector3d& q) {
    const int n = 200000;
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    double best = -1.0;
    Vector3d bp;
    for (int i = 0; i < n; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / n;
        const double rho = std::sqrt(1.0 - z * z);
        const Vector3d p(rho * std::cos(golden * i), rho * std::sin(golden * i), z);
        const double v = q.dot(p) / g.gamma(p);
        if (v > best) best = v, bp = p;
    }
    double span = 2.0 * std::sqrt(4.0 * std::numbers::pi / n);
    for (int level = 0; level < 3; ++level, span /= 50.0) {
        const Vector3d c = bp, t1 = c.unitOrthogonal(), t2 = c.cross(t1);
        for (int i = -100; i <= 100; ++i)
            for (int j = -100; j <= 100; ++j) {
                const Vector3d p = c + span * (i * t1 + j * t2) / 100.0;
                const double v = q.dot(p) / g.gamma(p);
                if (v > best) best = v, bp = p;
            }
    }
    return best;
}

TEST(AnisotropyStar, AgreesWithBruteForceOverTheSphere) {
    std::mt19937 rng(7);
    for (const Named& n : all_presets()) {
        double worst = 0.0;
        for (int i = 0; i < 3; ++i) {
            const Vector3d q = random_vector(rng).normalized();
            const double star = n.gamma.gamma_star(q);
            const double brute = brute_star(n.gamma, q);
            // brute is attained, so gamma* >= brute; and brute is close from below.
            EXPECT_GE(star, brute * (1 - 1e-13)) << n.name;
            worst = std::max(worst, (star - brute) / star);
        }
        EXPECT_LT(worst, 1e-12) << n.name; // measured: at most 4.7e-14 (l1(0.01))
    }
}

TEST(AnisotropyStar, CahnHoffmannAndFenchel) {
    std::mt19937 rng(8);
    for (const Named& n : all_presets()) {
        const Anisotropy& g = n.gamma;
        for (int i = 0; i < 200; ++i) {
            // gamma'(p) lies on the boundary of the Wulff shape: gamma*(gamma'(p)) = 1.
            const Vector3d p = random_vector(rng);
            EXPECT_NEAR(g.gamma_star(g.gamma_prime(p)), 1.0, 1e-12) << n.name;
            // the maximiser p* of (1.16) has gamma'(p*) parallel to q with ratio gamma*(q),
            // and q . p <= gamma(p) gamma*(q) for every p (Fenchel).
            const Vector3d q = random_vector(rng, 3.0);
            Vector3d pstar;
            const double s = g.gamma_star(q, &pstar);
            EXPECT_NEAR(pstar.norm(), 1.0, 1e-14);
            EXPECT_LT((s * g.gamma_prime(pstar) - q).norm(), 1e-11 * q.norm()) << n.name;
            EXPECT_NEAR(q.dot(pstar), g.gamma(pstar) * s, 1e-12 * q.norm()) << n.name;
            for (int k = 0; k < 5; ++k) {
                const Vector3d pp = random_vector(rng);
                EXPECT_LE(q.dot(pp), g.gamma(pp) * s * (1 + 1e-13)) << n.name;
            }
            // homogeneity of gamma*
            EXPECT_NEAR(g.gamma_star(2.5 * q), 2.5 * s, 1e-12 * s) << n.name;
        }
    }
}

// --- element matrices ------------------------------------------------------------------------

// For r = 1: M X = grad_X [gamma(nu)|sigma|] by central differences in all 9 coordinates, for
// every r = 1 preset on random non-degenerate triangles (issue 5's required unit test).
// For r = 30 the same holds with the weights lagged at the triangle's own normal.
TEST(AnisotropyElement, MatrixTimesPositionsIsTheEnergyGradient) {
    std::mt19937 rng(9);
    const double h = 1e-6;
    for (const Named& n : all_presets()) {
        double worst = 0.0;
        for (int t = 0; t < 5; ++t) {
            const Tri x = random_triangle(rng);
            const Vector3d nu = unit_normal(x);
            const ElementMatrix M =
                n.gamma.r() == 1.0 ? element_matrix(n.gamma, x) : element_matrix(n.gamma, x, nu);
            const Vector9d X = stacked(x);
            const auto energy = [&](const Tri& z) { return element_energy(n.gamma, z); };
            Vector9d fd;
            for (int k = 0; k < 9; ++k) fd[k] = central_difference(energy, x, k, h);
            worst = std::max(worst, (M * X - fd).cwiseAbs().maxCoeff() / fd.cwiseAbs().maxCoeff());
            // E is homogeneous of degree 2 in X: X . grad E = 2 E.
            EXPECT_NEAR(X.dot(M * X), 2 * element_energy(n.gamma, x),
                        1e-12 * element_energy(n.gamma, x))
                << n.name;
        }
        EXPECT_LT(worst, 1e-8) << n.name; // measured: at most 5.4e-10 (fig3_right)
    }
}

// Newton's method for (3.9): d/dy [M(nu(y)) y] = M(nu(y)) + weight_jacobian(x, y), M built on
// the triangle x with its weights at the normal of y, checked by central differences in y.
TEST(AnisotropyElement, WeightJacobianIsTheDerivativeOfTheLaggedWeights) {
    std::mt19937 rng(11);
    const double h = 1e-7;
    for (const Named& n : all_presets()) {
        double worst = 0.0;
        for (int t = 0; t < 5; ++t) {
            const Tri x = random_triangle(rng);
            Tri y = x;
            for (Vector3d& v : y) v += random_vector(rng, 0.1);
            const auto action = [&](const Tri& z) {
                const Vector3d nu = unit_normal(z);
                return Vector9d(element_matrix(n.gamma, x, nu) * stacked(z));
            };
            const Vector3d nu_y = unit_normal(y);
            const ElementMatrix J = element_matrix(n.gamma, x, nu_y) + weight_jacobian(n.gamma, x, y);
            for (int k = 0; k < 9; ++k) {
                const Vector9d fd = central_difference(action, y, k, h);
                worst = std::max(worst, (J.col(k) - fd).cwiseAbs().maxCoeff() / (1 + J.norm()));
            }
            if (n.gamma.r() == 1.0) EXPECT_EQ(weight_jacobian(n.gamma, x, y).norm(), 0.0);
        }
        EXPECT_LT(worst, 1e-6) << n.name;
    }
}

TEST(AnisotropyElement, SymmetricSemidefiniteWithTranslationsInTheKernel) {
    std::mt19937 rng(10);
    for (const Named& n : all_presets()) {
        for (int t = 0; t < 5; ++t) {
            const Tri x = random_triangle(rng);
            const ElementMatrix M = element_matrix(n.gamma, x, random_vector(rng).normalized());
            EXPECT_LT((M - M.transpose()).cwiseAbs().maxCoeff(), 1e-14 * M.norm()) << n.name;
            const Eigen::SelfAdjointEigenSolver<ElementMatrix> eig(M);
            EXPECT_GE(eig.eigenvalues().minCoeff(), -1e-12 * eig.eigenvalues().maxCoeff())
                << n.name;
            EXPECT_GT(eig.eigenvalues().maxCoeff(), 0.0) << n.name;
            for (int d = 0; d < 3; ++d) {
                Eigen::Matrix<double, 9, 1> T = Eigen::Matrix<double, 9, 1>::Zero();
                for (int a = 0; a < 3; ++a)
                    T[3 * a + d] = 1.0;
                EXPECT_LT((M * T).norm(), 1e-13 * M.norm()) << n.name << " translation " << d;
            }
        }
    }
}

TEST(AnisotropyElement, AreaInTheGtMetricIsGammaLTimesArea) {
    std::mt19937 rng(11);
    for (const Named& n : all_presets())
        for (int t = 0; t < 5; ++t) {
            const Tri x = random_triangle(rng);
            const Vector3d c = (x[1] - x[0]).cross(x[2] - x[0]);
            const Vector3d nu = c.normalized();
            const double area = 0.5 * c.norm();
            const Vector3d e1 = x[0] - x[2], e2 = x[1] - x[0];
            for (int l = 0; l < n.gamma.n_terms(); ++l) {
                const Matrix3d& Gt = n.gamma.G_tilde(l);
                const double A = 0.5 * std::sqrt(e1.dot(Gt * e1) * e2.dot(Gt * e2) -
                                                 std::pow(e1.dot(Gt * e2), 2));
                EXPECT_NEAR(A, n.gamma.gamma_term(l, nu) * area, 1e-9 * A) << n.name;
            }
        }
}

TEST(AnisotropyElement, IsotropicIsSigmaTimesTheP1Stiffness) {
    std::mt19937 rng(12);
    const Tri x = random_triangle(rng);
    const ElementMatrix M = element_matrix(Anisotropy::isotropic(1.3), x);
    const Matrix3d K = local_stiffness(x[0], x[1], x[2]);
    for (int a = 0; a < 3; ++a)
        for (int b = 0; b < 3; ++b)
            EXPECT_LT((M.block<3, 3>(3 * a, 3 * b) - 1.3 * K(a, b) * Matrix3d::Identity()).norm(),
                      1e-13 * M.norm());
    EXPECT_NEAR(element_energy(Anisotropy::isotropic(1.3), x),
                1.3 * 0.5 * (x[1] - x[0]).cross(x[2] - x[0]).norm(), 1e-14);
}

TEST(AnisotropyElement, DegenerateTriangleAndMissingNormalAreErrors) {
    const Tri flat = {Vector3d(0, 0, 0), Vector3d(1, 1, 1), Vector3d(2, 2, 2)};
    EXPECT_THROW(element_matrix(Anisotropy::l1(0.1), flat), GeometryError);
    const Tri x = {Vector3d(0, 0, 0), Vector3d(1, 0, 0), Vector3d(0, 1, 0)};
    EXPECT_THROW(element_matrix(Anisotropy::fig3_left(), x), InvalidInput); // r = 30 needs nu*
}

// --- invalid input ---------------------------------------------------------------------------

TEST(AnisotropyInput, InvalidDefinitionsAreClearErrors) {
    Matrix3d asym = Matrix3d::Identity();
    asym(0, 1) = 0.5;
    expect_invalid(
        [&] {
            Anisotropy({Matrix3d::Identity(), asym});
        },
        {"term 2", "not symmetric", "0.5"});
    const Matrix3d indef = Vector3d(1, -2, 1).asDiagonal();
    expect_invalid([&] { Anisotropy({indef}); }, {"term 1", "not positive definite", "-2"});
    expect_invalid([&] { Anisotropy({Matrix3d::Zero()}); }, {"term 1", "positive definite"});
    Matrix3d nan = Matrix3d::Identity();
    nan(2, 2) = std::nan("");
    expect_invalid([&] { Anisotropy({nan}); }, {"term 1", "non-finite"});
    expect_invalid([&] { Anisotropy({Matrix3d::Identity()}, 0.5); }, {"r must", "0.5"});
    expect_invalid([&] { Anisotropy({Matrix3d::Identity()}, std::nan("")); }, {"r must", "nan"});
    expect_invalid([&] { Anisotropy(std::vector<Matrix3d>{}); }, {"L = 0"});
    expect_invalid([] { Anisotropy::l1(0.0); }, {"eps", "0"});
    expect_invalid([] { Anisotropy::hexagonal(-0.1); }, {"eps", "-0.1"});
    expect_invalid([] { Anisotropy::from_angles(0.1, {}); }, {"L = 0"});
    expect_invalid([] { Anisotropy::l1(0.1, 0.9); }, {"r must", "0.9"});
    expect_invalid([] { Anisotropy::isotropic(0.0); }, {"sigma", "0"});
    expect_invalid([] { Anisotropy::isotropic(1).gamma_prime(Vector3d::Zero()); }, {"non-zero"});
}

} // namespace
} // namespace froth
