// gmsh builders (double bubble, sphere), read_msh and write_msh.
// Links: froth::builders froth::io GTest::gtest_main.

#include "builders/gmsh_builder.h"
#include "core/errors.h"
#include "io/msh_writer.h"
#include "mesh/cluster.h"

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
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
    o.sigma = {1.0, 2.0, 3.0};
    Cluster c(froth::build_double_bubble(o));
    ASSERT_EQ(c.n_surfaces(), 3);
    EXPECT_EQ(c.n_bodies(), 2);
    EXPECT_EQ(c.triple_lines().size(), 1u);
    EXPECT_TRUE(c.triple_lines()[0].closed);
    EXPECT_EQ(c.surface(0).sigma, 1.0);
    EXPECT_EQ(c.surface(2).sigma, 3.0);
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
