// froth's MSH reader (io/msh_reader.h): files gmsh wrote (4.1, 4.1 with parametric nodes, 2.2;
// tests/data/msh, made by gmsh 4.8.4's API: the double bubble geometry of build_double_bubble
// with split 0.3 meshed in 3D at Mesh.MeshSizeMax 0.6, every surface and volume a physical
// group), round trips of froth's own writer, and the malformed and hostile files of issue 17.
#include "core/errors.h"
#include "geometry/geometry.h"
#include "io/msh_reader.h"
#include "io/msh_writer.h"
#include "mesh/cluster.h"
#include "test_meshes.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <numbers>
#include <sstream>
#include <string>

using namespace froth;

namespace {

const std::string kData = FROTH_TEST_DATA "/msh/";

std::string temp_path(const std::string& name) {
    return ::testing::TempDir() + "froth_msh_reader_" + std::to_string(::getpid()) + "_" + name;
}

std::string error_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "(no error)";
}

std::string parse_error(const std::string& text) {
    return error_of([&] { parse_msh(text, "x.msh"); });
}

double cap_volume(double h) {
    return std::numbers::pi * h * h * (3 - h) / 3;
}

TEST(MshReader, GmshFilesOfEveryVersionGiveTheSameCluster) {
    Cluster v41(read_msh(kData + "gmsh_two_volumes_41.msh"));
    Cluster param(read_msh(kData + "gmsh_parametric_41.msh"));
    Cluster v22(read_msh(kData + "gmsh_two_volumes_22.msh"));
    ASSERT_EQ(v41.n_surfaces(), 3);
    EXPECT_EQ(v41.triple_lines().size(), 1u);
    for (const Cluster* c : {&param, &v22}) {
        ASSERT_EQ(c->n_vertices(), v41.n_vertices());
        ASSERT_EQ(c->n_facets(), v41.n_facets());
        for (int v = 0; v < v41.n_vertices(); ++v)
            EXPECT_EQ(c->position(v), v41.position(v));
        for (int s = 0; s < 3; ++s)
            EXPECT_EQ(c->surface(s).triangles, v41.surface(s).triangles);
    }
    // 4.1 carries the volumes' boundaries, so the two bubbles come back (2.2 has none); their
    // volumes are the caps' within the coarse mesh's error (h = 0.6: a few per cent).
    ASSERT_EQ(v41.n_bodies(), 2);
    EXPECT_EQ(param.n_bodies(), 2);
    EXPECT_EQ(v22.n_bodies(), 0);
    const std::vector<double> vol = body_volumes(v41);
    const double exact[2] = {cap_volume(0.7),
                             4 * std::numbers::pi / 3 - cap_volume(0.7)}; // upper, lower
    for (int b = 0; b < 2; ++b)
        EXPECT_NEAR(vol[b] / exact[b], 1.0, 0.06) << b;
    EXPECT_NEAR(vol[0] + vol[1], 4 * std::numbers::pi / 3, 0.06 * 4.2);
}

TEST(MshReader, BinaryFilesAreRefusedWithTheConversionCommand) {
    EXPECT_NE(error_of([] { read_msh(kData + "gmsh_binary_41.msh"); })
                  .find("line 2: binary MSH is not read (save it as ASCII: gmsh -save -format "
                        "msh41 -bin 0)"),
              std::string::npos);
}

TEST(MshReader, FrothsOwnFilesRoundTripExactly) {
    Cluster a(test::twin_tetrahedra());
    const std::string path = temp_path("twin.msh");
    write_msh(a, path);
    Cluster b(read_msh(path));
    std::remove(path.c_str());
    ASSERT_EQ(b.n_vertices(), a.n_vertices());
    for (int v = 0; v < a.n_vertices(); ++v)
        EXPECT_EQ(b.position(v), a.position(v));
    ASSERT_EQ(b.n_bodies(), a.n_bodies());
    EXPECT_EQ(body_volumes(b), body_volumes(a));
}

// One tetrahedron as MSH 4.1, with `nodes` and `element` lines replaceable.
std::string tetrahedron(const std::string& node_header = "1 4 1 4",
                        const std::string& block = "2 1 0 4",
                        const std::string& first_element = "1 1 3 2") {
    return "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Nodes\n" + node_header + "\n" + block +
           "\n1\n2\n3\n4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n$EndNodes\n$Elements\n1 4 1 4\n2 1 2 4\n" +
           first_element + "\n2 1 2 4\n3 1 4 3\n4 2 3 4\n$EndElements\n";
}

TEST(MshReader, TheTetrahedronReads) {
    ClusterSpec spec = parse_msh(tetrahedron(), "x.msh");
    EXPECT_EQ(spec.vertices.size(), 4u);
    ASSERT_EQ(spec.surfaces.size(), 1u);
    EXPECT_EQ(spec.surfaces[0].triangles.size(), 4u);
}

TEST(MshReader, MalformedFilesGiveTheLineAndWhatIsWrong) {
    // issue 17's gmsh crash: the last number of the first element line set to -1
    EXPECT_NE(
        parse_error(tetrahedron("1 4 1 4", "2 1 0 4", "1 1 3 -1"))
            .find("read: 'x.msh' is not a readable mesh: line 19: node tag -1 is out of range"),
        std::string::npos)
        << parse_error(tetrahedron("1 4 1 4", "2 1 0 4", "1 1 3 -1"));
    EXPECT_NE(parse_error(tetrahedron("1 4 1 4", "2 1 0 4", "1 1 3 9"))
                  .find("triangle node 9 has no coordinates"),
              std::string::npos);
    // counts that cannot fit in the file are refused before anything is allocated
    EXPECT_NE(parse_error(tetrahedron("1 2000000000 1 4"))
                  .find("number of nodes 2000000000 cannot fit in the"),
              std::string::npos);
    EXPECT_NE(parse_error(tetrahedron("1 1000000000000 1 4"))
                  .find("number of nodes 1000000000000 is out of range"),
              std::string::npos);
    EXPECT_NE(parse_error(tetrahedron("1 4 1 4", "2 1 0 2000000000")).find("cannot fit"),
              std::string::npos);
    EXPECT_NE(parse_error(tetrahedron("1 5 1 4"))
                  .find("the node blocks hold 4 nodes, not the 5 announced"),
              std::string::npos);
    EXPECT_NE(parse_error(tetrahedron("1 3 1 4")).find("hold more than the 3 nodes announced"),
              std::string::npos);
    std::string t = tetrahedron();
    t.replace(t.find("1 0 0\n"), 6, "1 nan 0\n");
    EXPECT_NE(parse_error(t).find("line 12: expected node coordinate (a finite number), got 'nan'"),
              std::string::npos)
        << parse_error(t);
    t = tetrahedron();
    t.replace(t.find("1 0 0\n"), 6, "1 1e999 0\n");
    EXPECT_NE(parse_error(t).find("got '1e999'"), std::string::npos);
    t = tetrahedron();
    t.replace(t.find("$EndElements"), 12, "");
    EXPECT_NE(parse_error(t).find("unexpected end of file, expected $EndElements"),
              std::string::npos);
    t = tetrahedron();
    t.replace(
        t.find("$Elements"), 9,
        "$Elements\n1 4 1 4\n2 1 2 4\n1 1 2 3\n2 1 2 4\n3 1 4 3\n4 2 3 4\n$EndElements\n$Elements");
    EXPECT_NE(parse_error(t).find("a second $Elements section"), std::string::npos);
    EXPECT_NE(
        parse_error("$MeshFormat\n3.0 0 8\n$EndMeshFormat\n").find("MSH version 3.0 is not read"),
        std::string::npos);
    EXPECT_NE(parse_error("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Foo\n1 2 3\n")
                  .find("section $Foo has no $EndFoo"),
              std::string::npos);
    EXPECT_NE(
        parse_error("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Elements\n1 1 1 1\n2 1 99 1\n1 1 2 3\n")
            .find("element type 99 is not a gmsh element type froth knows"),
        std::string::npos);
    EXPECT_NE(parse_error("this is not a mesh").find("line 1: expected $MeshFormat, got 'this'"),
              std::string::npos);
    EXPECT_EQ(parse_error(""), "read: 'x.msh' has no triangles");
    EXPECT_EQ(parse_error("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"),
              "read: 'x.msh' has no triangles");
}

TEST(MshReader, OnlyRegularFilesWithinTheLimitAreRead) {
    EXPECT_EQ(error_of([] { read_msh("/dev/zero"); }),
              "read: cannot open '/dev/zero': not a regular file");
    const std::string fifo = temp_path("fifo.msh");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_EQ(error_of([&] { read_msh(fifo); }),
              "read: cannot open '" + fifo + "': not a regular file");
    std::remove(fifo.c_str());
    EXPECT_EQ(error_of([] { read_msh(::testing::TempDir()); }).find("Is a directory") !=
                  std::string::npos,
              true);
    EXPECT_NE(error_of([] {
                  read_msh("no/such/dir/x.msh");
              }).find("read: cannot open 'no/such/dir/x.msh': No such file"),
              std::string::npos);
    const std::string path = temp_path("small.msh");
    std::ofstream(path) << tetrahedron();
    MshReadLimits tiny;
    tiny.max_bytes = 100;
    EXPECT_NE(error_of([&] { read_msh(path, tiny); }).find("larger than the limit of 100 bytes"),
              std::string::npos);
    EXPECT_EQ(read_msh(path).surfaces.size(), 1u);
    std::remove(path.c_str());
}

} // namespace
