// Wulff shapes and Frank diagrams (src/wulff/): closed forms for ellipsoidal and isotropic
// gamma, convergence as the directions fill the sphere, the exact properties of the half-space
// polytope W_h (support values, E = 3 r^2 |W_h|, W inside W_h), the Cahn–Hoffmann check, the
// nearly crystalline presets, and the option errors. Every shape is also built into a Cluster.
#include "wulff/wulff.h"

#include "core/errors.h"
#include "geometry/geometry.h"
#include "wulff/sphere_sampling.h"

#include "expect_error.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <numbers>
#include <string>

namespace froth {
namespace {

using Eigen::Matrix3d;

Matrix3d skew_G() {
    Matrix3d G;
    G << 2.0, 0.3, -0.1, 0.3, 1.0, 0.2, -0.1, 0.2, 0.5;
    return G;
}

/// Volume and energy sum_t gamma(nu_t) |t| of the one-surface spec, from its triangles.
struct Measures {
    double volume = 0.0, energy = 0.0;
};

Measures measure(const ClusterSpec& s, const Anisotropy& gamma) {
    Measures m;
    for (const Tri& t : s.surfaces.at(0).triangles) {
        const Vec3& a = s.vertices[t[0]];
        const Vec3& b = s.vertices[t[1]];
        const Vec3& c = s.vertices[t[2]];
        const Vec3 n2 = (b - a).cross(c - a); // 2 |t| nu
        m.volume += a.dot(b.cross(c)) / 6.0;
        m.energy += 0.5 * gamma.gamma(n2);
    }
    return m;
}

/// Builds the engine's cluster (validation: closed, oriented, no zero-area facet) and returns
/// its body volume.
double cluster_volume(const ClusterSpec& s) {
    const Cluster c{ClusterSpec(s)};
    EXPECT_EQ(c.n_bodies(), 1);
    EXPECT_EQ(c.n_surfaces(), 1);
    EXPECT_TRUE(c.triple_lines().empty());
    return body_volumes(c).at(0);
}

CahnHoffmannCheck check(const Anisotropy& gamma, const ClusterSpec& s, double scale = 1.0) {
    return cahn_hoffmann_check(gamma, s.vertices, s.surfaces.at(0).triangles, scale);
}

WulffOptions level(int k, bool facets = true) {
    WulffOptions o;
    o.subdivisions = k;
    o.facet_directions = facets;
    return o;
}

using test::expect_invalid;

// --- sphere samplings ------------------------------------------------------------------------

TEST(WulffSampling, IcosphereCountsClosedAndHoldsTheAxes) {
    for (int k = 0; k <= 4; ++k) {
        const TriangleSurface s = icosphere(k);
        const int n = 10 * (1 << (2 * k)) + 2;
        ASSERT_EQ(static_cast<int>(s.vertices.size()), n);
        EXPECT_EQ(static_cast<int>(s.triangles.size()), 20 * (1 << (2 * k)));
        for (const Vec3& v : s.vertices)
            EXPECT_NEAR(v.norm(), 1.0, 1e-15);
        ClusterSpec spec{s.vertices, {{s.triangles, 1.0}}, {{0}}, {}};
        EXPECT_GT(cluster_volume(spec), 0.6 * 4.0 / 3.0 * std::numbers::pi);
        if (k == 0) continue;
        for (int d = 0; d < 3; ++d) {
            int found = 0;
            for (const Vec3& v : s.vertices)
                found += std::abs(std::abs(v[d]) - 1.0) < 1e-15;
            EXPECT_EQ(found, 2) << "axis " << d << " at level " << k;
        }
    }
}

TEST(WulffSampling, FacetDirectionsOfTheL1PresetAreAxesAndCubeDiagonals) {
    const std::vector<Vec3> f = facet_directions(Anisotropy::l1(0.01));
    EXPECT_EQ(f.size(), 6u + 8u); // +-e_i (axes and cross products) and (+-1, +-1, +-1)/sqrt 3
    for (const Vec3& p : f) {
        EXPECT_NEAR(p.norm(), 1.0, 1e-14);
        const Vec3 a = p.cwiseAbs();
        const bool axis = std::abs(a.maxCoeff() - 1.0) < 1e-12;
        const bool diagonal = (a - Vec3::Constant(1.0 / std::sqrt(3.0))).norm() < 1e-12;
        EXPECT_TRUE(axis || diagonal) << p.transpose();
    }
    EXPECT_TRUE(facet_directions(Anisotropy::isotropic(2.0)).empty());
    EXPECT_TRUE(facet_directions(Anisotropy::ellipsoidal(skew_G())).empty());
    EXPECT_GT(facet_directions(Anisotropy::hexagonal()).size(), 8u);
}

// --- Wulff shape: ellipsoidal gamma, W = { q . G^-1 q <= 1 } -------------------------------

TEST(WulffShape, EllipsoidVolumeConvergesFromAbove) {
    if (!wulff_shape_available()) GTEST_SKIP() << "built without CGAL";
    const Matrix3d G = skew_G();
    const Anisotropy gamma = Anisotropy::ellipsoidal(G);
    const double exact = 4.0 / 3.0 * std::numbers::pi * std::sqrt(G.determinant());
    double previous = 1.0;
    for (int k = 1; k <= 5; ++k) {
        const auto start = std::chrono::steady_clock::now();
        const ClusterSpec s = wulff_shape(gamma, level(k));
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        const double V = cluster_volume(s);
        const double err = (V - exact) / exact;
        std::printf("  ellipsoid level %d: %zu vertices, %zu facets, volume error %.3e (%.1f ms)\n",
                    k, s.vertices.size(), s.surfaces[0].triangles.size(), err, ms);
        EXPECT_NEAR(measure(s, gamma).volume, V, 1e-12 * V);
        EXPECT_GT(err, 0.0) << "W_h circumscribes W";
        if (k >= 2) EXPECT_LT(err, previous / 3.0) << "second order in the spacing";
        previous = err;
    }
    EXPECT_LT(previous, 5e-4);
}

TEST(WulffShape, EllipsoidVerticesLieOutsideWAndSupportValuesAreGamma) {
    if (!wulff_shape_available()) GTEST_SKIP() << "built without CGAL";
    const Matrix3d G = skew_G();
    const Matrix3d Ginv = G.inverse();
    const Anisotropy gamma = Anisotropy::ellipsoidal(G);
    const ClusterSpec s = wulff_shape(gamma, level(3));
    double max_gamma_star = 0.0;
    for (const Vec3& v : s.vertices) {
        const double gs = std::sqrt(v.dot(Ginv * v)); // gamma*(q) of an ellipsoidal gamma
        EXPECT_GE(gs, 1.0 - 1e-13);
        max_gamma_star = std::max(max_gamma_star, gs);
    }
    EXPECT_LT(max_gamma_star, 1.03); // the overshoot of the corners, O(spacing^2)
    // The support function of W_h at every plane direction p_k is exactly gamma(p_k) (W inside
    // W_h gives >=, the half-space gives <=).
    for (const Vec3& p : icosphere(3).vertices) {
        double h = -1e300;
        for (const Vec3& v : s.vertices)
            h = std::max(h, v.dot(p));
        EXPECT_NEAR(h, gamma.gamma(p), 1e-14);
    }
}

TEST(WulffShape, EnergyIsThreeTimesVolumeAndScalesWithR) {
    if (!wulff_shape_available()) GTEST_SKIP() << "built without CGAL";
    const Anisotropy gamma = Anisotropy::ellipsoidal(skew_G());
    const Measures one = measure(wulff_shape(gamma, level(3)), gamma);
    EXPECT_NEAR(one.energy, 3.0 * one.volume, 1e-13 * one.energy);
    for (double r : {0.25, 1.7, 40.0}) {
        WulffOptions o = level(3);
        o.scale = r;
        const Measures m = measure(wulff_shape(gamma, o), gamma);
        EXPECT_NEAR(m.volume, r * r * r * one.volume, 1e-13 * m.volume);
        EXPECT_NEAR(m.energy, 3.0 * r * r * one.volume, 1e-13 * m.energy); // E = 3 r^2 |W_h|
    }
}

TEST(WulffShape, CahnHoffmannPointsAreInsideAndConvergeToTheBoundary) {
    if (!wulff_shape_available()) GTEST_SKIP() << "built without CGAL";
    const Anisotropy gamma = Anisotropy::ellipsoidal(skew_G());
    double previous = 1.0;
    for (int k = 2; k <= 4; ++k) {
        const ClusterSpec s = wulff_shape(gamma, level(k));
        const auto start = std::chrono::steady_clock::now();
        const CahnHoffmannCheck c = check(gamma, s);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
                .count();
        std::printf("  ellipsoid level %d: Cahn-Hoffmann distance %.3e, outside %.1e, support "
                    "%.1e, energy defect %.1e (%.1f ms)\n",
                    k, c.max_distance, c.max_outside, c.max_support_error, c.energy_defect, ms);
        EXPECT_EQ(c.samples, 1000);
        EXPECT_LT(c.max_outside, 1e-13);
        EXPECT_LT(c.max_support_error, 1e-12);
        EXPECT_LT(c.energy_defect, 1e-14);
        EXPECT_LT(c.max_distance, previous / 3.0);
        previous = c.max_distance;
    }
    EXPECT_LT(previous, 2e-3);
    // A polytope that does not contain W fails: W_h shrunk by 0.9, checked against W.
    WulffOptions o = level(3);
    o.scale = 0.9;
    const CahnHoffmannCheck shrunk = check(gamma, wulff_shape(gamma, o));
    EXPECT_GT(shrunk.max_outside, 0.05);
    EXPECT_GT(shrunk.max_support_error, 0.05);
}

TEST(WulffShape, IsotropicIsANearSphereOfRadiusSigma) {
    if (!wulff_shape_available()) GTEST_SKIP() << "built without CGAL";
    const double sigma = 1.7;
    const ClusterSpec s = wulff_shape(Anisotropy::isotropic(sigma), level(4));
    double lo = 1e300, hi = 0.0;
    for (const Vec3& v : s.vertices)
        lo = std::min(lo, v.norm()), hi = std::max(hi, v.norm());
    EXPECT_GE(lo, sigma * (1.0 - 1e-14));
    EXPECT_LT(hi, sigma * 1.002);
    const double exact = 4.0 / 3.0 * std::numbers::pi * sigma * sigma * sigma;
    EXPECT_NEAR(cluster_volume(s), exact, 2e-3 * exact);
}

TEST(WulffShape, FibonacciDirectionsWork) {
    if (!wulff_shape_available()) GTEST_SKIP() << "built without CGAL";
    const Matrix3d G = skew_G();
    const Anisotropy gamma = Anisotropy::ellipsoidal(G);
    const double exact = 4.0 / 3.0 * std::numbers::pi * std::sqrt(G.determinant());
    WulffOptions o;
    o.directions = 2000;
    const ClusterSpec s = wulff_shape(gamma, o);
    const double err = (cluster_volume(s) - exact) / exact;
    EXPECT_GT(err, 0.0);
    EXPECT_LT(err, 3e-3);
    EXPECT_LT(check(gamma, s).max_outside, 1e-13);
}

// --- nearly crystalline presets --------------------------------------------------------------

// (5.6), Fig. 2 left: gamma(p) = sum_j [eps^2 |p|^2 + p_j^2 (1 - eps^2)]^(1/2) >= |p|_1, so
// the cube [-1, 1]^3 lies in W; W_h lies in the box of its axis planes q_j <= gamma(e_j) =
// 1 + 2 eps. Hence 8 < |W_h| < 8 (1 + 2 eps)^3: W -> the cube as eps -> 0.
TEST(WulffShape, L1ApproachesTheCube) {
    if (!wulff_shape_available()) GTEST_SKIP() << "built without CGAL";
    double previous = 1e300;
    for (double eps : {0.1, 0.03, 0.01, 0.003, 0.001}) {
        const ClusterSpec s = wulff_shape(Anisotropy::l1(eps), level(5));
        const double V = cluster_volume(s);
        const double box = 8.0 * std::pow(1.0 + 2.0 * eps, 3);
        std::printf("  l1(%g): volume %.6f (cube 8, box %.6f), %zu vertices\n", eps, V, box,
                    s.vertices.size());
        EXPECT_GT(V, 8.0);
        EXPECT_LT(V, box);
        EXPECT_LT(V - 8.0, previous);
        previous = V - 8.0;
        double h = 0.0; // the top facet is at gamma(e_z) = 1 + 2 eps exactly
        for (const Vec3& v : s.vertices)
            h = std::max(h, v.z());
        EXPECT_NEAR(h, 1.0 + 2.0 * eps, 1e-14);
    }
    EXPECT_LT(previous, 0.05);
}

// Without the facet directions a sampling that misses e_z overshoots the top facet.
TEST(WulffShape, FacetDirectionsPutFacetsAtTheirSupportValue) {
    if (!wulff_shape_available()) GTEST_SKIP() << "built without CGAL";
    const Anisotropy gamma = Anisotropy::l1(0.01);
    WulffOptions o;
    o.directions = 1000;
    auto top = [&](bool facets) {
        o.facet_directions = facets;
        double h = 0.0;
        for (const Vec3& v : wulff_shape(gamma, o).vertices)
            h = std::max(h, v.z());
        return h;
    };
    EXPECT_NEAR(top(true), gamma.gamma(Vec3::UnitZ()), 1e-14);
    EXPECT_GT(top(false), gamma.gamma(Vec3::UnitZ()) + 1e-4);
}

TEST(WulffShape, EveryPresetGivesAValidCircumscribingPolytope) {
    if (!wulff_shape_available()) GTEST_SKIP() << "built without CGAL";
    const std::vector<std::pair<std::string, Anisotropy>> presets = {
        {"l1(0.01)", Anisotropy::l1(0.01)},       {"l1(0.01, r = 30)", Anisotropy::l1(0.01, 30)},
        {"hexagonal", Anisotropy::hexagonal()},   {"fig3_left", Anisotropy::fig3_left()},
        {"fig3_right", Anisotropy::fig3_right()}, {"l1(1e-3)", Anisotropy::l1(1e-3)},
    };
    for (const auto& [name, gamma] : presets) {
        for (int k : {2, 4}) {
            SCOPED_TRACE(name + " level " + std::to_string(k));
            const ClusterSpec s = wulff_shape(gamma, level(k));
            const double V = cluster_volume(s);
            const Measures m = measure(s, gamma);
            EXPECT_NEAR(m.volume, V, 1e-12 * V);
            EXPECT_NEAR(m.energy, 3.0 * V, 1e-12 * m.energy);
            const CahnHoffmannCheck c = check(gamma, s);
            std::printf("  %s level %d: %zu vertices, volume %.5f, CH distance %.2e, outside "
                        "%.1e, support %.1e\n",
                        name.c_str(), k, s.vertices.size(), V, c.max_distance, c.max_outside,
                        c.max_support_error);
            EXPECT_LT(c.max_outside, 1e-13);
            // Per triangle, the normal of a tiny triangle near a rounded corner carries the
            // round-off of its coordinates over its size; the area-weighted defect does not.
            EXPECT_LT(c.max_support_error, 1e-10);
            EXPECT_LT(c.energy_defect, 1e-13);
            if (k != 2) continue;
            for (const Vec3& v : s.vertices)
                EXPECT_GE(gamma.gamma_star(v), 1.0 - 1e-12);
        }
    }
}

// Far below the seed's eps = 1e-2 the vertices of W_h are no longer resolved in double
// precision (the rounded corners of l1(1e-6) are ~1e-12 wide): the result is then either a valid
// circumscribing polytope or a GeometryError, never a folded surface.
TEST(WulffShape, NearlyCrystallineBeyondDoublePrecisionFailsLoudly) {
    if (!wulff_shape_available()) GTEST_SKIP() << "built without CGAL";
    const Anisotropy gamma = Anisotropy::l1(1e-6);
    int built = 0;
    for (int k = 3; k <= 5; ++k) {
        try {
            const ClusterSpec s = wulff_shape(gamma, level(k));
            const CahnHoffmannCheck c = check(gamma, s);
            EXPECT_LT(c.max_support_error, 1e-10);
            EXPECT_LT(c.max_outside, 1e-10);
            EXPECT_GT(cluster_volume(s), 8.0);
            ++built;
        } catch (const GeometryError& e) {
            EXPECT_NE(std::string(e.what()).find("wulff_shape: "), std::string::npos);
        }
    }
    EXPECT_GE(built, 1); // level 3 resolves
}

// --- Frank diagram ---------------------------------------------------------------------------

TEST(FrankDiagram, VerticesOnTheUnitLevelSetAndEllipsoidVolume) {
    const Matrix3d G = skew_G();
    const Anisotropy gamma = Anisotropy::ellipsoidal(G);
    const double exact = 4.0 / 3.0 * std::numbers::pi / std::sqrt(G.determinant());
    double previous = 1.0;
    for (int k = 1; k <= 5; ++k) {
        const ClusterSpec s = frank_diagram(gamma, k);
        for (const Vec3& v : s.vertices)
            EXPECT_NEAR(gamma.gamma(v), 1.0, 1e-15);
        const double err = (exact - cluster_volume(s)) / exact;
        std::printf("  Frank diagram level %d: volume error %.3e\n", k, err);
        EXPECT_GT(err, 0.0) << "inscribed in the convex F";
        if (k >= 2) EXPECT_LT(err, previous / 3.0);
        previous = err;
    }
    EXPECT_LT(previous, 1e-3);
}

TEST(FrankDiagram, EveryPresetGivesAValidCluster) {
    for (const Anisotropy& gamma :
         {Anisotropy::isotropic(0.5), Anisotropy::l1(0.01), Anisotropy::hexagonal(),
          Anisotropy::fig3_left(), Anisotropy::fig3_right()}) {
        const ClusterSpec s = frank_diagram(gamma, 3);
        EXPECT_GT(cluster_volume(s), 0.0);
        for (const Vec3& v : s.vertices)
            EXPECT_NEAR(gamma.gamma(v), 1.0, 1e-15);
    }
}

// --- errors ----------------------------------------------------------------------------------

TEST(WulffErrors, OptionsOutOfRangeNameTheOptionAndValue) {
    const Anisotropy gamma = Anisotropy::isotropic();
    expect_invalid([&] { wulff_shape(gamma, level(-1)); }, {"wulff_shape", "subdivisions", "-1"});
    expect_invalid([&] { wulff_shape(gamma, level(8)); }, {"subdivisions", "0..7", "8"});
    for (int n : {0, 19, 200001}) {
        WulffOptions o;
        o.directions = n;
        expect_invalid([&] { wulff_shape(gamma, o); }, {"directions", std::to_string(n)});
    }
    for (double r : {0.0, -1.0, std::nan(""), HUGE_VAL}) {
        WulffOptions o;
        o.scale = r;
        expect_invalid([&] { wulff_shape(gamma, o); }, {"wulff_shape", "scale"});
    }
    expect_invalid([&] { frank_diagram(gamma, -1); }, {"frank_diagram", "subdivisions", "-1"});
    expect_invalid([&] { frank_diagram(gamma, 8); }, {"frank_diagram", "subdivisions", "8"});
    const ClusterSpec f = frank_diagram(gamma, 1);
    expect_invalid([&] { cahn_hoffmann_check(gamma, f.vertices, {}, 1.0); },
                   {"cahn_hoffmann_check", "no triangles"});
    expect_invalid(
        [&] {
            cahn_hoffmann_check(gamma, f.vertices, {{0, 1, 999}}, 1.0);
        },
        {"cahn_hoffmann_check", "vertex 1000"});
    expect_invalid([&] { cahn_hoffmann_check(gamma, f.vertices, f.surfaces[0].triangles, -2.0); },
                   {"cahn_hoffmann_check", "scale", "-2"});
    expect_invalid([&] { cahn_hoffmann_check(gamma, f.vertices, f.surfaces[0].triangles, 1.0, 0); },
                   {"cahn_hoffmann_check", "samples", "0"});
}

TEST(WulffErrors, WithoutCgalWulffShapeSaysSo) {
    if (wulff_shape_available()) GTEST_SKIP() << "built with CGAL";
    try {
        wulff_shape(Anisotropy::isotropic());
        ADD_FAILURE() << "no error";
    } catch (const Error& e) {
        EXPECT_NE(std::string(e.what()).find("without CGAL"), std::string::npos) << e.what();
    }
}

} // namespace
} // namespace froth
