// Tests of froth_io: OFF/PLY/VTU/PVD writers and the write_cluster dispatch.
#include "core/errors.h"
#include "io/off_ply.h"
#include "io/vtk_writer.h"
#include "io/write.h"
#include "mesh/cluster.h"

#include <gtest/gtest.h>

#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using namespace froth;

namespace {

// Two disjoint tetrahedra: surface 1 and body 1, surface 2 and body 2. Coordinates are chosen
// to need all 17 significant digits.
Cluster two_tetrahedra() {
    ClusterSpec spec;
    const double a = 1.0 / 3.0, b = std::sqrt(2.0), e = 1e-7 * M_PI;
    spec.vertices = {{0.1, -a, e},        {1.0 + a, 0.2, -e},   {0.3, b, 1e-300},
                     {0.25, 0.3, 1.0 + b}, {10.0 + a, 0, 0},     {11.0, 0, 0},
                     {10.0, 1.0 / 7.0, 0}, {10.0, 0, -2.5e10}};
    const std::vector<Tri> tet = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
    for (int k = 0; k < 2; ++k) {
        ClusterSpec::Surface s;
        for (Tri t : tet) s.triangles.push_back({t[0] + 4 * k, t[1] + 4 * k, t[2] + 4 * k});
        s.sigma = 1.0 + k;
        spec.surfaces.push_back(s);
        spec.bodies.push_back({k});
    }
    return Cluster(std::move(spec));
}

std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The text between the opening tag of <DataArray ... Name="name" ...> and </DataArray>.
std::string data_array(const std::string& xml, const std::string& name) {
    const auto at = xml.find("Name=\"" + name + "\"");
    if (at == std::string::npos) return "<missing>";
    const auto begin = xml.find('>', at) + 1;
    return xml.substr(begin, xml.find("</DataArray>", begin) - begin);
}

std::vector<double> numbers(const std::string& text) {
    std::istringstream in(text);
    std::vector<double> out;
    for (double x; in >> x;) out.push_back(x);
    return out;
}

int count_of(const std::string& text, const std::string& what) {
    int n = 0;
    for (auto p = text.find(what); p != std::string::npos; p = text.find(what, p + 1)) ++n;
    return n;
}

class IoTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() /
               ("froth_io_test_" + std::to_string(::getpid()) + "_" +
                ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& rel) const { return (dir_ / rel).string(); }
    fs::path dir_;
};

TEST_F(IoTest, OffRoundTripsCountsCoordinatesAndFacets) {
    const Cluster c = two_tetrahedra();
    write_off(c, path("mesh.off"));
    std::ifstream in(path("mesh.off"));
    std::string magic;
    int nv = 0, nf = 0, ne = -1;
    in >> magic >> nv >> nf >> ne;
    ASSERT_EQ(magic, "OFF");
    ASSERT_EQ(nv, c.n_vertices());
    ASSERT_EQ(nf, c.n_facets());
    EXPECT_EQ(ne, 0);
    for (int v = 0; v < nv; ++v)
        for (int d = 0; d < 3; ++d) {
            double x = NAN;
            in >> x;
            const double want = c.position(v)[d];
            EXPECT_LE(std::abs(x - want), 1e-15 * std::abs(want)) << "vertex " << v << " " << d;
        }
    for (const Surface& s : c.surfaces())
        for (const Tri& t : s.triangles) {
            int k = 0, i = -1, j = -1, l = -1;
            in >> k >> i >> j >> l;
            EXPECT_EQ(k, 3);
            EXPECT_EQ((Tri{i, j, l}), t);
        }
    EXPECT_TRUE(in.good());
    std::string rest;
    in >> rest;
    EXPECT_TRUE(rest.empty()) << "trailing data: " << rest;
}

TEST_F(IoTest, PlyHasHeaderAndPerFaceSurfaceIds) {
    const Cluster c = two_tetrahedra();
    write_ply(c, path("mesh.ply"));
    const std::string text = slurp(path("mesh.ply"));
    ASSERT_EQ(text.rfind("ply\nformat ascii 1.0\n", 0), 0u);
    EXPECT_NE(text.find("element vertex 8\n"), std::string::npos);
    EXPECT_NE(text.find("element face 8\n"), std::string::npos);
    EXPECT_NE(text.find("property int surface\n"), std::string::npos);
    std::istringstream in(text.substr(text.find("end_header\n") + 11));
    for (int v = 0; v < 8 * 3; ++v) {
        double x = NAN;
        in >> x;
        EXPECT_EQ(x, c.position(v / 3)[v % 3]);
    }
    for (int f = 0; f < 8; ++f) {
        int k = 0, i = 0, j = 0, l = 0, s = 0;
        in >> k >> i >> j >> l >> s;
        EXPECT_EQ(k, 3);
        EXPECT_EQ(s, f < 4 ? 1 : 2) << "face " << f;
    }
    EXPECT_FALSE(in.fail());
}

TEST_F(IoTest, VtuHasCountsSurfaceIdsPointsAndFields) {
    Cluster c = two_tetrahedra();
    c.set_time(0.75);
    const std::vector<double> h = {1, 2, 3, 4, 5, 6, 7, 0.1};
    write_vtu(c, path("sub/dir/c.vtu"), {{"h", h}, {"a<b", std::vector<double>(8, -1.5)}});
    const std::string xml = slurp(path("sub/dir/c.vtu"));
    EXPECT_NE(xml.find("type=\"UnstructuredGrid\""), std::string::npos);
    EXPECT_NE(xml.find("NumberOfPoints=\"8\" NumberOfCells=\"8\""), std::string::npos);
    EXPECT_EQ(numbers(data_array(xml, "surface")),
              (std::vector<double>{1, 1, 1, 1, 2, 2, 2, 2}));
    EXPECT_EQ(numbers(data_array(xml, "sigma")),
              (std::vector<double>{1, 1, 1, 1, 2, 2, 2, 2}));
    // Each tetrahedron is one body; its facets have it behind (normal out of it) or in front.
    const std::vector<double> behind = numbers(data_array(xml, "body_behind")),
                              front = numbers(data_array(xml, "body_front"));
    ASSERT_EQ(behind.size(), 8u);
    ASSERT_EQ(front.size(), 8u);
    for (int f = 0; f < 8; ++f) {
        const int body = f / 4, sign = c.bodies()[body].faces[0].sign;
        EXPECT_EQ(sign > 0 ? behind[f] : front[f], body + 1) << "facet " << f;
        EXPECT_EQ(sign > 0 ? front[f] : behind[f], 0) << "facet " << f;
    }
    EXPECT_EQ(numbers(data_array(xml, "types")), std::vector<double>(8, 5));
    EXPECT_EQ(numbers(data_array(xml, "offsets")),
              (std::vector<double>{3, 6, 9, 12, 15, 18, 21, 24}));
    EXPECT_EQ(numbers(data_array(xml, "connectivity")).size(), 24u);
    EXPECT_EQ(numbers(data_array(xml, "h")), h);
    EXPECT_EQ(numbers(data_array(xml, "a&lt;b")), std::vector<double>(8, -1.5));
    EXPECT_EQ(numbers(data_array(xml, "TimeValue")), std::vector<double>{0.75});
    const std::vector<double> pts = numbers(data_array(xml, "Points"));
    ASSERT_EQ(pts.size(), 24u);
    for (int k = 0; k < 24; ++k) EXPECT_EQ(pts[k], c.position(k / 3)[k % 3]);
    for (const auto& entry : fs::directory_iterator(path("sub/dir"))) // no temporary left over
        EXPECT_EQ(entry.path().filename(), "c.vtu");
}

// The temporary is unique (mkstemp), so a user's own "x.off.tmp" survives, a failed write
// leaves nothing, and a written file has the umask's mode, not mkstemp's 0600.
TEST_F(IoTest, WritesUseAUniqueTemporaryAndLeaveNothingBehind) {
    const Cluster c = two_tetrahedra();
    fs::create_directories(dir_);
    std::ofstream(path("x.off.tmp")) << "mine";
    write_off(c, path("x.off"));
    write_off(c, path("x.off")); // over an existing file
    EXPECT_EQ(slurp(path("x.off.tmp")), "mine");
    fs::create_directories(path("d.ply"));
    EXPECT_THROW(write_ply(c, path("d.ply")), IoError); // the rename fails: a directory is there
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(dir_)) names.push_back(entry.path().filename());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"d.ply", "x.off", "x.off.tmp"}));
    const mode_t mask = ::umask(0);
    ::umask(mask);
    EXPECT_EQ(static_cast<mode_t>(fs::status(path("x.off")).permissions()), 0666 & ~mask);
}

TEST_F(IoTest, WrongFieldLengthThrowsNamingTheField) {
    const Cluster c = two_tetrahedra();
    try {
        write_vtu(c, path("c.vtu"), {{"kappa", std::vector<double>(7, 0.0)}});
        FAIL() << "no throw";
    } catch (const InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("'kappa' has 7 values"), std::string::npos)
            << e.what();
    }
    EXPECT_FALSE(fs::exists(path("c.vtu")));
    EXPECT_THROW(write_vtu(c, path("c.vtu"), {{"", std::vector<double>(8)}}), InvalidInput);
    EXPECT_THROW(write_cluster(c, path("c.vtu"), {{"h", {}}}), InvalidInput);
    const std::vector<double> ok(8, 1.0);
    EXPECT_THROW(write_vtu(c, path("c.vtu"), {{"h", ok}, {"h", ok}}), InvalidInput);
}

TEST_F(IoTest, PvdSeriesListsEverySnapshot) {
    const Cluster c = two_tetrahedra();
    PvdSeries series(path("out/run.pvd"));
    EXPECT_EQ(series.count(), 0);
    EXPECT_EQ(series.path(), path("out/run.pvd"));
    EXPECT_EQ(count_of(slurp(path("out/run.pvd")), "<DataSet"), 0);
    const double times[] = {0.0, 0.5, 1.25};
    for (double t : times) series.add(t, c, {{"t", std::vector<double>(8, t)}});
    EXPECT_EQ(series.count(), 3);
    const std::string pvd = slurp(path("out/run.pvd"));
    EXPECT_NE(pvd.find("type=\"Collection\""), std::string::npos);
    EXPECT_EQ(count_of(pvd, "<DataSet"), 3);
    for (int k = 0; k < 3; ++k) {
        char file[32];
        std::snprintf(file, sizeof file, "run_%06d.vtu", k);
        std::ostringstream entry;
        entry << "timestep=\"" << times[k] << "\" group=\"\" part=\"0\" file=\"" << file << "\"";
        EXPECT_NE(pvd.find(entry.str()), std::string::npos) << entry.str() << "\n" << pvd;
        EXPECT_TRUE(fs::is_regular_file(path(std::string("out/") + file))) << file;
        EXPECT_EQ(series.snapshot_path(k), path(std::string("out/") + file));
        const std::string vtu = slurp(path(std::string("out/") + file));
        EXPECT_EQ(numbers(data_array(vtu, "TimeValue")), std::vector<double>{times[k]});
    }
}

TEST_F(IoTest, PvdSeriesRejectsBadInput) {
    const Cluster c = two_tetrahedra();
    EXPECT_THROW(PvdSeries(path("run.vtu")), InvalidInput);
    PvdSeries series(path("run.pvd"));
    EXPECT_THROW(series.add(NAN, c), InvalidInput);
    EXPECT_THROW(series.add(0.0, c, {{"x", {1.0}}}), InvalidInput);
    EXPECT_EQ(series.count(), 0);
    EXPECT_FALSE(fs::exists(path("run_000000.vtu")));
}

TEST_F(IoTest, WriteClusterDispatchesOnExtension) {
    const Cluster c = two_tetrahedra();
    write_cluster(c, path("a/b/m.off"));
    write_cluster(c, path("a/b/m.PLY"));
    write_cluster(c, path("a/b/m.vtu"), {{"h", std::vector<double>(8, 2.0)}});
    write_cluster(c, path("a/b/m.msh"));
    EXPECT_EQ(slurp(path("a/b/m.off")).rfind("OFF\n", 0), 0u);
    EXPECT_EQ(slurp(path("a/b/m.PLY")).rfind("ply\n", 0), 0u);
    EXPECT_NE(slurp(path("a/b/m.vtu")).find("Name=\"h\""), std::string::npos);
    EXPECT_TRUE(fs::is_regular_file(path("a/b/m.msh")));
}

TEST_F(IoTest, UnknownExtensionThrows) {
    const Cluster c = two_tetrahedra();
    try {
        write_cluster(c, path("m.xyz"));
        FAIL() << "no throw";
    } catch (const InvalidInput& e) {
        EXPECT_STREQ(e.what(), "write: unknown file type '.xyz' (use .vtu, .off, .ply or .msh)");
    }
    EXPECT_THROW(write_cluster(c, path("noext")), InvalidInput);
    EXPECT_FALSE(fs::exists(dir_)); // nothing created for a rejected name
}

TEST_F(IoTest, UnwritablePathThrowsIoError) {
    const Cluster c = two_tetrahedra();
    EXPECT_THROW(write_vtu(c, "/proc/froth/x.vtu"), IoError);
    EXPECT_THROW(write_cluster(c, "/proc/froth/x.off"), IoError);
    EXPECT_THROW(write_ply(c, "/proc/froth/x.ply"), IoError);
    EXPECT_THROW(PvdSeries("/proc/froth/run.pvd"), IoError);
    // A regular file where a directory should be.
    fs::create_directories(dir_);
    std::ofstream(path("file")) << "x";
    try {
        write_off(c, path("file/m.off"));
        FAIL() << "no throw";
    } catch (const IoError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("write: cannot create directory", 0), 0u)
            << e.what();
    }
    // A directory where the file should be.
    fs::create_directories(path("d.vtu"));
    EXPECT_THROW(write_vtu(c, path("d.vtu")), IoError);
}

} // namespace
