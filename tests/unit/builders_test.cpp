// gmsh builders (double bubble, sphere, fragment), read_msh and write_msh.
// Links: froth::builders froth::io GTest::gtest_main.

#include "builders/fragment.h"
#include "builders/gmsh_builder.h"
#include "core/errors.h"
#include "io/msh_reader.h"
#include "io/msh_writer.h"
#include "mesh/cluster.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <unistd.h>

namespace {

using froth::Cluster;

// Body volume by the divergence theorem, with the body's own face signs.
double body_volume(const Cluster& c, int b) {
    double v = 0;
    for (const froth::BodyFace& f : c.bodies()[b].faces)
        for (const froth::Tri& t : c.surface(f.surface).triangles)
            v += f.sign * c.position(t[0]).dot(c.position(t[1]).cross(c.position(t[2]))) / 6;
    return v;
}

std::string temp_path(const std::string& name) {
    return (std::filesystem::temp_directory_path() /
            ("froth_builders_" + std::to_string(::getpid()) + "_" + name))
        .string();
}

void check_double_bubble(double h) {
    froth::DoubleBubbleOptions o;
    o.h = h;
    o.sigma = {1.0, 2.0, 2.5}; // distinct, and each below the sum of the other two
    Cluster c(froth::build_double_bubble(o));
    ASSERT_EQ(c.n_surfaces(), 3);
    EXPECT_EQ(c.n_bodies(), 2);
    EXPECT_EQ(c.triple_lines().size(), 1u);
    EXPECT_TRUE(c.triple_lines()[0].closed);
    EXPECT_EQ(c.surface(0).sigma, 1.0);
    EXPECT_EQ(c.surface(2).sigma, 2.5);
    const double third = 2 * std::numbers::pi / 3;
    for (int b = 0; b < 2; ++b)
        EXPECT_NEAR(body_volume(c, b), third, 0.02 * third) << "body " << b + 1;
    // documented order: surface 1 below the wall, surface 2 above, surface 3 the flat wall
    for (int v : c.surface(0).vertices)
        EXPECT_LE(c.position(v).z(), 1e-9);
    for (int v : c.surface(1).vertices)
        EXPECT_GE(c.position(v).z(), -1e-9);
    for (int v : c.surface(2).vertices)
        EXPECT_NEAR(c.position(v).z(), 0.0, 1e-9);
    // body 1 = lower {1, 3}, body 2 = upper {2, 3}
    ASSERT_EQ(c.bodies()[0].faces.size(), 2u);
    EXPECT_EQ(c.bodies()[0].faces[0].surface, 0);
    EXPECT_EQ(c.bodies()[1].faces[0].surface, 1);
}

TEST(DoubleBubble, CoarseIsValid) {
    check_double_bubble(0.2);
}

TEST(DoubleBubble, DefaultSizeIsValid) {
    check_double_bubble(0.08);
    Cluster c(froth::build_double_bubble({}));
    EXPECT_GE(c.n_vertices(), 2500);
    EXPECT_LE(c.n_vertices(), 3600);
}

TEST(DoubleBubble, OffCentreSplitGivesUnequalBubbles) {
    froth::DoubleBubbleOptions o;
    o.h = 0.1;
    o.split = 0.5;
    Cluster c(froth::build_double_bubble(o));
    EXPECT_EQ(c.triple_lines().size(), 1u);
    // cap of height 0.5: pi h^2 (3 - h) / 3
    const double cap = std::numbers::pi * 0.25 * 2.5 / 3;
    EXPECT_NEAR(body_volume(c, 1), cap, 0.03 * cap);
    EXPECT_NEAR(body_volume(c, 0), 4 * std::numbers::pi / 3 - cap, 0.02 * 4);
}

TEST(DoubleBubble, BadOptionsThrowInvalidInput) {
    auto build = [](double h, double split, double sigma) {
        froth::DoubleBubbleOptions o;
        o.h = h;
        o.split = split;
        o.sigma[1] = sigma;
        return froth::build_double_bubble(o);
    };
    EXPECT_THROW(build(-1, 0, 1), froth::InvalidInput);
    EXPECT_THROW(build(0, 0, 1), froth::InvalidInput);
    EXPECT_THROW(build(std::nan(""), 0, 1), froth::InvalidInput);
    EXPECT_THROW(build(0.001, 0, 1), froth::InvalidInput);
    EXPECT_THROW(build(2, 0, 1), froth::InvalidInput);
    EXPECT_THROW(build(0.1, 0.95, 1), froth::InvalidInput);
    EXPECT_THROW(build(0.1, 0, 0), froth::InvalidInput);
    EXPECT_THROW(build(0.1, 0, -1), froth::InvalidInput);
    try {
        build(-1, 0, 1);
    } catch (const froth::InvalidInput& e) {
        EXPECT_EQ(std::string(e.what()), "double_bubble: h must be positive, got -1");
    }
}

TEST(Sphere, VolumeWithinOnePercent) {
    Cluster c(froth::build_sphere({}));
    ASSERT_EQ(c.n_surfaces(), 1);
    ASSERT_EQ(c.n_bodies(), 1);
    EXPECT_TRUE(c.triple_lines().empty());
    const double v = 4 * std::numbers::pi / 3;
    EXPECT_NEAR(body_volume(c, 0), v, 0.01 * v);
}

TEST(Sphere, RadiusAndCentre) {
    froth::SphereOptions o;
    o.R = 2;
    o.h = 0.2;
    o.center = froth::Vec3(1, -2, 3);
    Cluster c(froth::build_sphere(o));
    for (const froth::Vec3& x : c.positions())
        EXPECT_NEAR((x - o.center).norm(), 2.0, 1e-6);
    const double v = 4 * std::numbers::pi * 8 / 3;
    EXPECT_NEAR(body_volume(c, 0), v, 0.01 * v);
}

TEST(Sphere, BadOptionsThrowInvalidInput) {
    froth::SphereOptions o;
    o.R = -1;
    EXPECT_THROW(froth::build_sphere(o), froth::InvalidInput);
    o.R = 1;
    o.h = 0;
    EXPECT_THROW(froth::build_sphere(o), froth::InvalidInput);
    o.h = 0.1;
    o.center = froth::Vec3(0, INFINITY, 0);
    EXPECT_THROW(froth::build_sphere(o), froth::InvalidInput);
}

TEST(Msh, RoundTripKeepsCountsAndVolumes) {
    froth::DoubleBubbleOptions o;
    o.h = 0.15;
    o.sigma = {1, 1, 1};
    Cluster a(froth::build_double_bubble(o));
    const std::string path = temp_path("roundtrip.msh");
    froth::write_msh(a, path);
    Cluster b(froth::read_msh(path));
    std::remove(path.c_str());
    EXPECT_EQ(b.n_vertices(), a.n_vertices());
    EXPECT_EQ(b.n_facets(), a.n_facets());
    ASSERT_EQ(b.n_surfaces(), a.n_surfaces());
    for (int s = 0; s < a.n_surfaces(); ++s)
        EXPECT_EQ(b.surface(s).triangles.size(), a.surface(s).triangles.size());
    ASSERT_EQ(b.n_bodies(), 2);
    EXPECT_EQ(b.triple_lines().size(), 1u);
    for (int k = 0; k < 2; ++k)
        EXPECT_NEAR(body_volume(b, k), body_volume(a, k), 1e-12);
    for (int v = 0; v < a.n_vertices(); ++v)
        EXPECT_EQ(b.position(v), a.position(v));
}

// Writes the double bubble c as MSH 4.1 with surface 1 cut into two gmsh entities (x < 0 and
// x >= 0, by facet centroid), the second one with reversed triangles, both in physical
// surface 1: what a CAD seam does to a film. All nodes sit in one block of entity 1.
void write_split_double_bubble(const Cluster& c, const std::string& path) {
    std::vector<froth::Tri> part[2];
    for (froth::Tri t : c.surface(0).triangles) {
        const double x = c.position(t[0]).x() + c.position(t[1]).x() + c.position(t[2]).x();
        if (x >= 0) std::swap(t[1], t[2]);
        part[x >= 0].push_back(t);
    }
    const std::vector<froth::Tri>* blocks[4] = {&part[0], &part[1], &c.surface(1).triangles,
                                                &c.surface(2).triangles};
    const int physical[4] = {1, 1, 2, 3};
    std::ofstream f(path);
    f.precision(17);
    f << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 4 2\n";
    for (int e = 0; e < 4; ++e)
        f << e + 1 << " -1 -1 -1 1 1 1 1 " << physical[e] << " 0\n";
    f << "1 -1 -1 -1 1 1 1 1 1 3 1 2 4\n2 -1 -1 -1 1 1 1 1 2 2 3 4\n$EndEntities\n";
    f << "$Nodes\n1 " << c.n_vertices() << " 1 " << c.n_vertices() << "\n2 1 0 " << c.n_vertices()
      << "\n";
    for (int v = 0; v < c.n_vertices(); ++v)
        f << v + 1 << "\n";
    for (const froth::Vec3& x : c.positions())
        f << x[0] << ' ' << x[1] << ' ' << x[2] << "\n";
    f << "$EndNodes\n$Elements\n4 " << c.n_facets() << " 1 " << c.n_facets() << "\n";
    int tag = 0;
    for (int e = 0; e < 4; ++e) {
        f << "2 " << e + 1 << " 2 " << blocks[e]->size() << "\n";
        for (const froth::Tri& t : *blocks[e])
            f << ++tag << ' ' << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << "\n";
    }
    f << "$EndElements\n";
}

TEST(Msh, PhysicalSurfaceOfSeveralEntitiesIsMergedAndOriented) {
    froth::DoubleBubbleOptions o;
    o.h = 0.15;
    Cluster a(froth::build_double_bubble(o));
    const std::string path = temp_path("split.msh");
    write_split_double_bubble(a, path);
    froth::ClusterSpec spec = froth::read_msh(path);
    std::remove(path.c_str());
    ASSERT_EQ(spec.surfaces.size(), 3u);
    EXPECT_EQ(spec.surfaces[0].triangles.size(), a.surface(0).triangles.size());
    ASSERT_EQ(spec.bodies.size(), 2u);
    EXPECT_EQ(spec.bodies[0], (std::vector<int>{0, 2}));
    EXPECT_EQ(spec.bodies[1], (std::vector<int>{1, 2}));
    Cluster b(std::move(spec)); // throws if surface 1 is not consistently oriented
    EXPECT_EQ(b.triple_lines().size(), 1u);
    for (int k = 0; k < 2; ++k)
        EXPECT_NEAR(body_volume(b, k), body_volume(a, k), 1e-12);
}

TEST(Msh, MissingFileThrowsIoError) {
    EXPECT_THROW(froth::read_msh(temp_path("does_not_exist.msh")), froth::IoError);
    try {
        froth::read_msh("no/such/dir/x.msh");
    } catch (const froth::IoError& e) {
        EXPECT_EQ(
            std::string(e.what()).rfind("read: cannot open 'no/such/dir/x.msh': No such file", 0),
            0u)
            << e.what();
    }
}

TEST(Msh, GarbageFilesThrowIoError) {
    const std::string garbage = temp_path("garbage.msh");
    std::ofstream(garbage) << "this is not a mesh {{{\n";
    EXPECT_THROW(froth::read_msh(garbage), froth::IoError);
    const std::string truncated = temp_path("truncated.msh");
    std::ofstream(truncated)
        << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n1 3 1 3\n2 1 0 3\n1\n";
    EXPECT_THROW(froth::read_msh(truncated), froth::IoError);
    const std::string empty = temp_path("empty.msh");
    std::ofstream(empty) << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
    EXPECT_THROW(froth::read_msh(empty), froth::IoError);
    for (const std::string& p : {garbage, truncated, empty})
        std::remove(p.c_str());
}

TEST(Msh, UnwritablePathThrowsIoError) {
    Cluster c(froth::build_sphere({1.0, 0.5, froth::Vec3::Zero()}));
    EXPECT_THROW(froth::write_msh(c, "/proc/froth_cannot_write_here.msh"), froth::IoError);
}

} // namespace

// ---- fragment (builders/fragment.h) ----------------------------------------------------------

namespace {

using froth::Solid;
using froth::SolidKind;

Solid ball(froth::Vec3 c, double r) {
    Solid s;
    s.kind = SolidKind::ball;
    s.center = c;
    s.r = r;
    return s;
}

Solid box(froth::Vec3 min, froth::Vec3 size) {
    Solid s;
    s.kind = SolidKind::box;
    s.min = min;
    s.size = size;
    return s;
}

froth::FragmentOptions fragment_of(std::vector<Solid> solids, double h) {
    froth::FragmentOptions o;
    o.solids = std::move(solids);
    o.h = h;
    return o;
}

// Volume of the union of balls {(center, r)} by exact x-intervals on a midpoint grid in (y, z):
// an independent reference for the bodies "solid minus the solids before it".
double union_volume(const std::vector<std::pair<froth::Vec3, double>>& balls, int n = 600) {
    froth::Vec3 lo = froth::Vec3::Constant(1e300), hi = -lo;
    for (auto [c, r] : balls) {
        lo = lo.cwiseMin(c - froth::Vec3::Constant(r));
        hi = hi.cwiseMax(c + froth::Vec3::Constant(r));
    }
    const double dy = (hi.y() - lo.y()) / n, dz = (hi.z() - lo.z()) / n;
    double v = 0;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
            const double y = lo.y() + (i + 0.5) * dy, z = lo.z() + (j + 0.5) * dz;
            std::vector<std::pair<double, double>> iv;
            for (auto [c, r] : balls) {
                const double q = r * r - (y - c.y()) * (y - c.y()) - (z - c.z()) * (z - c.z());
                if (q > 0) iv.emplace_back(c.x() - std::sqrt(q), c.x() + std::sqrt(q));
            }
            std::sort(iv.begin(), iv.end());
            double end = -1e300;
            for (auto [a, b] : iv) {
                v += std::max(0.0, b - std::max(a, end)) * dy * dz;
                end = std::max(end, b);
            }
        }
    return v;
}

std::string fragment_error(const froth::FragmentOptions& o) {
    try {
        froth::build_fragment(o);
    } catch (const froth::InvalidInput& e) {
        return e.what();
    }
    return "no InvalidInput";
}

} // namespace

// dependencies.md §3 "three_spheres": b1 = A, b2 = B\A, b3 = C\(A u B).
TEST(Fragment, ThreeOverlappingBallsGiveThreeBodiesAndTwoQuadruplePoints) {
    const froth::Vec3 a(0, 0, 0), b(1, 0, 0), c(0.5, 0.8, 0);
    Cluster cl(froth::build_fragment(fragment_of({ball(a, 1), ball(b, 1), ball(c, 1)}, 0.12)));
    EXPECT_EQ(cl.n_bodies(), 3);
    EXPECT_EQ(cl.n_surfaces(), 6); // pairs (0,1) (0,2) (0,3) (1,2) (1,3) (2,3)
    EXPECT_EQ(cl.triple_lines().size(), 4u);
    EXPECT_EQ(cl.quadruple_points().size(), 2u);
    const double v1 = union_volume({{a, 1}}), v12 = union_volume({{a, 1}, {b, 1}}),
                 v123 = union_volume({{a, 1}, {b, 1}, {c, 1}});
    EXPECT_NEAR(body_volume(cl, 0), v1, 0.015 * v1);
    EXPECT_NEAR(body_volume(cl, 1), v12 - v1, 0.015 * (v12 - v1));
    EXPECT_NEAR(body_volume(cl, 2), v123 - v12, 0.02 * (v123 - v12));
    // the two quadruple points lie on all three spheres
    for (int q : cl.quadruple_points())
        for (const froth::Vec3& centre : {a, b, c})
            EXPECT_NEAR((cl.position(q) - centre).norm(), 1.0, 1e-6);
}

// A box with a ball over the middle of its top face: the ball's body is the half ball above it.
TEST(Fragment, BoxWithBallOnAFace) {
    Cluster cl(froth::build_fragment(
        fragment_of({box({-1, -1, -1}, {2, 2, 2}), ball({0, 0, 1}, 0.6)}, 0.1)));
    ASSERT_EQ(cl.n_surfaces(), 3);
    EXPECT_EQ(cl.n_bodies(), 2);
    EXPECT_EQ(cl.triple_lines().size(), 1u);
    EXPECT_TRUE(cl.quadruple_points().empty());
    EXPECT_NEAR(body_volume(cl, 0), 8.0, 1e-9); // flat faces: the mesh is exact
    const double half = 2 * std::numbers::pi * 0.216 / 3;
    EXPECT_NEAR(body_volume(cl, 1), half, 0.015 * half);
    // order by region pair: 1 = (outside, box), 2 = (outside, ball), 3 = (box, ball)
    for (int v : cl.surface(2).vertices)
        EXPECT_NEAR(cl.position(v).z(), 1.0, 1e-9);
    for (int v : cl.surface(1).vertices)
        EXPECT_GE(cl.position(v).z(), 1.0 - 1e-9);
}

// Seed §5.1.3: two 2x1x1 cuboids and two unit cubes stacked: 9 surfaces, 8 triple lines,
// 4 quadruple points; flat faces, so the volumes are exact.
TEST(Fragment, QuadrupleBubbleOfBoxes) {
    froth::FragmentOptions o = fragment_of({box({0, 0, 0}, {2, 1, 1}), box({0, 0, 1}, {1, 1, 1}),
                                            box({1, 0, 1}, {1, 1, 1}), box({0, 0, 2}, {2, 1, 1})},
                                           0.2);
    o.sigma_of[4] = 1.5; // surface 5 = (body 1, body 2)
    Cluster cl(froth::build_fragment(o));
    EXPECT_EQ(cl.n_surfaces(), 9);
    EXPECT_EQ(cl.triple_lines().size(), 8u);
    EXPECT_EQ(cl.quadruple_points().size(), 4u);
    const double expected[4] = {2, 1, 1, 2};
    for (int b = 0; b < 4; ++b)
        EXPECT_NEAR(body_volume(cl, b), expected[b], 1e-9) << "body " << b + 1;
    EXPECT_EQ(cl.surface(4).sigma, 1.5);
    EXPECT_EQ(cl.surface(3).sigma, 1.0);
    for (int v : cl.surface(4).vertices) { // the wall between the bottom cuboid and cube 1
        EXPECT_NEAR(cl.position(v).z(), 1.0, 1e-9);
        EXPECT_LE(cl.position(v).x(), 1.0 + 1e-9);
    }
}

// Seed §5.1.2: three analytic 120-degree wedges of the unit ball.
TEST(Fragment, TripleBubbleFromWedges) {
    std::vector<Solid> wedges;
    for (int k = 0; k < 3; ++k) {
        Solid w = ball({0, 0, 0}, 1);
        w.angle = 2 * std::numbers::pi / 3;
        w.rotate_angle = 2 * std::numbers::pi * k / 3;
        wedges.push_back(w);
    }
    Cluster cl(froth::build_fragment(fragment_of(wedges, 0.15)));
    EXPECT_EQ(cl.n_surfaces(), 6);
    EXPECT_EQ(cl.triple_lines().size(), 4u);
    EXPECT_EQ(cl.quadruple_points().size(), 2u);
    const double third = 4 * std::numbers::pi / 9;
    for (int b = 0; b < 3; ++b)
        EXPECT_NEAR(body_volume(cl, b), third, 0.01 * third);
    // body 1 = {1, 4, 5}: its lune and the walls at azimuth 120 and 0 degrees
    ASSERT_EQ(cl.bodies()[0].faces.size(), 3u);
    EXPECT_EQ(cl.bodies()[0].faces[0].surface, 0);
    EXPECT_EQ(cl.bodies()[0].faces[1].surface, 3);
    EXPECT_EQ(cl.bodies()[0].faces[2].surface, 4);
}

// The torus bubble of seed §5.1.1: ball |x| <= 2 and the torus R = 2, r = 1 outside it. The
// CAD volumes are 32 pi / 3 and 25.95632 (by quadrature of the tube cross-section).
TEST(Fragment, TorusBubbleVolumes) {
    Solid torus;
    torus.kind = SolidKind::torus;
    torus.R = 2;
    torus.r = 1;
    Cluster cl(froth::build_fragment(fragment_of({ball({0, 0, 0}, 2), torus}, 0.2)));
    EXPECT_EQ(cl.n_surfaces(), 4);
    EXPECT_EQ(cl.triple_lines().size(), 2u);
    EXPECT_TRUE(cl.quadruple_points().empty());
    const double ball_v = 32 * std::numbers::pi / 3, torus_v = 25.95632;
    EXPECT_NEAR(body_volume(cl, 0), ball_v, 0.01 * ball_v);
    EXPECT_NEAR(body_volume(cl, 1), torus_v, 0.01 * torus_v);
    EXPECT_NEAR(body_volume(cl, 0) / body_volume(cl, 1), 1.29103, 0.01 * 1.29103);
    // surfaces 1, 2 = lower and upper caps (same pair, ordered by height)
    EXPECT_LT(cl.position(cl.surface(0).vertices[0]).z(), 0);
    EXPECT_GT(cl.position(cl.surface(1).vertices[0]).z(), 0);
}

TEST(Fragment, TransformsAndLocalSize) {
    Solid e = ball({0, 0, 0}, 1);
    e.scale = froth::Vec3(1, 1, 2); // an ellipsoid, then moved
    e.translate = froth::Vec3(5, 0, 0);
    Cluster ce(froth::build_fragment(fragment_of({e}, 0.1)));
    const double ve = 8 * std::numbers::pi / 3;
    EXPECT_NEAR(body_volume(ce, 0), ve, 0.01 * ve);
    for (const froth::Vec3& x : ce.positions())
        EXPECT_NEAR(std::pow(x.x() - 5, 2) + x.y() * x.y() + x.z() * x.z() / 4, 1.0, 1e-3);

    // A finer h on the second ball refines its films only: the first ball's cap stays coarse.
    Solid fine = ball({1.5, 0, 0}, 1);
    fine.h = 0.06;
    Cluster coarse(
        froth::build_fragment(fragment_of({ball({0, 0, 0}, 1), ball({1.5, 0, 0}, 1)}, 0.15)));
    Cluster local(froth::build_fragment(fragment_of({ball({0, 0, 0}, 1), fine}, 0.15)));
    const auto n_tri = [](const Cluster& c, int s) { return c.surface(s).triangles.size(); };
    EXPECT_GT(n_tri(local, 1), 4 * n_tri(coarse, 1)); // ball 2's cap: (0.15 / 0.06)^2 = 6.25
    EXPECT_LT(n_tri(local, 0), 1.5 * n_tri(coarse, 0));
}

TEST(Fragment, AutomaticSizeAimsAtTheVertexCount) {
    froth::FragmentOptions o = fragment_of({ball({0, 0, 0}, 1), ball({1, 0, 0}, 1)}, 0);
    o.h.reset();
    o.default_vertices = 3000;
    Cluster c(froth::build_fragment(o));
    EXPECT_NEAR(c.n_vertices(), 3000, 300);
}

TEST(Fragment, ErrorsNameTheSolid) {
    EXPECT_EQ(fragment_error(fragment_of({ball({0, 0, 0}, 1), ball({1, 0, 0}, 0)}, 0.2)),
              "fragment: solids[2] (ball): radius r must be positive, got 0");
    EXPECT_EQ(fragment_error(fragment_of({box({0, 0, 0}, {1, -1, 1})}, 0.2)),
              "fragment: solids[1] (box): size must be positive in x, y and z, got {1, -1, 1}");
    EXPECT_EQ(fragment_error(fragment_of({ball({0, 0, 0}, 1), ball({0.2, 0, 0}, 0.5)}, 0.2)),
              "fragment: solids[2] (ball) lies inside the solids before it: its body would be "
              "empty");
    EXPECT_EQ(fragment_error(
                  fragment_of({ball({0, 0, 0}, 1), ball({1, 0, 0}, 1), ball({5, 0, 0}, 1)}, 0.3)),
              "fragment: solids[3] (ball) touches no other solid: a cluster must be connected");
    EXPECT_EQ(fragment_error(fragment_of({ball({0, 0, 0}, 1)}, 0.001)),
              "fragment: h = 0.001 gives about 15079645 vertices, more than 400000; use a larger "
              "h (h >= 0.00620136)");
    EXPECT_EQ(fragment_error(fragment_of({ball({0, 0, 0}, 1)}, 3)),
              "fragment: h = 3 is larger than the cluster (extent 2); use h <= 2");
    EXPECT_EQ(fragment_error(fragment_of({ball({0, 0, 0}, 1)}, -1)),
              "fragment: h must be positive, got -1");
    EXPECT_EQ(fragment_error(fragment_of({}, 0.1)), "fragment: no solids");
    Solid t;
    t.kind = SolidKind::torus;
    t.R = 1;
    t.r = 1;
    EXPECT_EQ(fragment_error(fragment_of({t}, 0.1)),
              "fragment: solids[1] (torus): tube radius r = 1 must be smaller than the major "
              "radius R = 1");
    froth::FragmentOptions o = fragment_of({ball({0, 0, 0}, 1)}, 0.3);
    o.sigma_of[2] = 2;
    EXPECT_EQ(fragment_error(o),
              "fragment: sigma[3] names surface 3, but the cluster has only 1 surface");
    o.sigma_of.clear();
    o.sigma = 0;
    EXPECT_EQ(fragment_error(o), "fragment: sigma must be positive, got 0");
}

// latitude = {lo, hi}: the band of the ball between two latitudes, closed by flat disks. The
// upper half ball {0, pi/2} is one film (dome and disk, one region pair) of volume 2 pi r^3 / 3.
TEST(Fragment, BallLatitudeBand) {
    constexpr double pi = std::numbers::pi;
    Solid half = ball({0, 0, 1}, 1);
    half.latitude_lo = 0;
    half.latitude_hi = pi / 2;
    Cluster c(froth::build_fragment(fragment_of({half}, 0.1)));
    EXPECT_EQ(c.n_surfaces(), 1);
    EXPECT_EQ(c.n_bodies(), 1);
    EXPECT_NEAR(body_volume(c, 0), 2 * pi / 3, 0.01 * 2 * pi / 3);
    int on_disk = 0;
    for (const froth::Vec3& x : c.positions()) {
        EXPECT_GE(x.z(), 1 - 1e-9);
        EXPECT_LE((x - froth::Vec3(0, 0, 1)).norm(), 1 + 1e-9);
        on_disk += std::abs(x.z() - 1) < 1e-9;
    }
    EXPECT_GT(on_disk, 50); // the disk is meshed: (pi / 0.1^2) / 1.2 ~ 260 vertices

    // A zone between z = r sin(lo) and z = r sin(hi): V = pi (r^2 (z2 - z1) - (z2^3 - z1^3) / 3).
    Solid zone = ball({0, 0, 0}, 2);
    zone.latitude_lo = -pi / 6;
    zone.latitude_hi = pi / 4;
    Cluster cz(froth::build_fragment(fragment_of({zone}, 0.15)));
    const double z1 = 2 * std::sin(-pi / 6), z2 = 2 * std::sin(pi / 4);
    const double vz = pi * (4 * (z2 - z1) - (z2 * z2 * z2 - z1 * z1 * z1) / 3);
    EXPECT_NEAR(body_volume(cz, 0), vz, 0.01 * vz);
    for (const froth::Vec3& x : cz.positions()) {
        EXPECT_GE(x.z(), z1 - 1e-9);
        EXPECT_LE(x.z(), z2 + 1e-9);
    }

    // Round-off past pi/2 (Lua's -math.pi / 2 and math.pi / 2) is the whole ball.
    Solid whole = ball({0, 0, 0}, 1);
    whole.latitude_lo = -pi / 2 * (1 + 1e-15);
    whole.latitude_hi = pi / 2 * (1 + 1e-15);
    EXPECT_NEAR(body_volume(Cluster(froth::build_fragment(fragment_of({whole}, 0.15))), 0),
                4 * pi / 3, 0.02 * 4 * pi / 3);
}

TEST(Fragment, BallLatitudeErrors) {
    const auto with = [](double lo, double hi) {
        Solid s = ball({0, 0, 0}, 1);
        s.latitude_lo = lo;
        s.latitude_hi = hi;
        return fragment_error(fragment_of({s}, 0.2));
    };
    EXPECT_EQ(with(0.5, 0.5), "fragment: solids[1] (ball): latitude {lo, hi} must satisfy -pi/2 "
                              "<= lo < hi <= pi/2 (radians), got {0.5, 0.5}");
    EXPECT_EQ(with(1, 0), "fragment: solids[1] (ball): latitude {lo, hi} must satisfy -pi/2 <= "
                          "lo < hi <= pi/2 (radians), got {1, 0}");
    EXPECT_EQ(with(-2, 0), "fragment: solids[1] (ball): latitude {lo, hi} must satisfy -pi/2 <= "
                           "lo < hi <= pi/2 (radians), got {-2, 0}");
    EXPECT_EQ(with(0, 1.6), "fragment: solids[1] (ball): latitude {lo, hi} must satisfy -pi/2 <= "
                            "lo < hi <= pi/2 (radians), got {0, 1.6}");
    EXPECT_EQ(with(0, std::numeric_limits<double>::quiet_NaN()),
              "fragment: solids[1] (ball): latitude must be finite, got {0, nan}");
}
