// Snapshots (render/snapshot.h) by pixel statistics, not golden images: the covered fraction
// of a sphere's picture against the disc it must fill, the background where nothing is, one
// colour per visible surface, shading that varies over a curved surface, the PNG read back.
#include "expect_error.h"
#include "render/snapshot.h"
#include "test_meshes.h"

#include <gtest/gtest.h>
#include <png.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <string>
#include <vector>

namespace froth {
namespace {

using test::icosphere;
using test::twin_tetrahedra;

// The camera fits the bounding sphere into 0.92 of the shorter side: a sphere's disc has
// radius 0.46 min(w, h).
double disc_fraction(int w, int h) {
    const double r = 0.46 * std::min(w, h);
    return M_PI * r * r / (double(w) * h);
}

TEST(Snapshot, ASphereFillsItsDiscOnTheBackground) {
    const Cluster c(icosphere(3));
    SnapshotOptions o;
    o.width = 320, o.height = 240;
    SnapshotStats s;
    const std::string rgb = render_rgb(c, o, &s);
    ASSERT_EQ(rgb.size(), 320u * 240u * 3u);
    // The inscribed polyhedron covers slightly less than the disc.
    EXPECT_NEAR(s.coverage, disc_fraction(320, 240), 0.015);
    EXPECT_LT(s.coverage, disc_fraction(320, 240));
    EXPECT_EQ(s.surfaces, 1);
    const auto px = [&](int x, int y, int ch) {
        return static_cast<unsigned char>(rgb[(std::size_t(y) * 320 + x) * 3 + ch]);
    };
    for (int ch = 0; ch < 3; ++ch) {
        EXPECT_EQ(px(0, 0, ch), 250) << "a corner is background";
        EXPECT_EQ(px(319, 239, ch), 250);
    }
    // The centre shows the surface's colour, shaded: its hue (blue above red) and not grey.
    EXPECT_GT(px(160, 120, 2), px(160, 120, 0));
    // Lambert shading: the centre (facing the light) and the rim differ in brightness.
    std::set<int> blues;
    for (int x = 60; x < 260; x += 10)
        blues.insert(px(x, 120, 2));
    EXPECT_GT(blues.size(), 5u);
}

TEST(Snapshot, EverySurfaceOfTwinTetrahedraHasItsColour) {
    const Cluster c(twin_tetrahedra());
    SnapshotOptions o;
    o.width = o.height = 200;
    o.view = Vec3(-1, -1, -0.2);
    SnapshotStats s;
    render_rgb(c, o, &s);
    EXPECT_GE(s.surfaces, 2); // the two caps from the side; the inner wall is hidden
    EXPECT_GT(s.coverage, 0.1);
    EXPECT_NE(surface_color(0), surface_color(1));
}

TEST(Snapshot, WritesAPngThatReadsBack) {
    const Cluster c(icosphere(2));
    const std::string path = ::testing::TempDir() + "froth_snapshot_test.png";
    SnapshotOptions o;
    o.width = 64, o.height = 48;
    o.color = "mean_curvature";
    write_snapshot(c, path, o);
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    ASSERT_TRUE(png_image_begin_read_from_file(&image, path.c_str())) << image.message;
    EXPECT_EQ(image.width, 64u);
    EXPECT_EQ(image.height, 48u);
    image.format = PNG_FORMAT_RGB;
    std::vector<unsigned char> rgb(PNG_IMAGE_SIZE(image));
    ASSERT_TRUE(png_image_finish_read(&image, nullptr, rgb.data(), 0, nullptr));
    int background = 0;
    for (std::size_t i = 0; i < rgb.size(); i += 3)
        background += rgb[i] == 250 && rgb[i + 1] == 250 && rgb[i + 2] == 250;
    EXPECT_NEAR(1.0 - background / (64.0 * 48.0), disc_fraction(64, 48), 0.05);
    std::remove(path.c_str());
}

TEST(Snapshot, BadOptionsAreRefused) {
    const Cluster c(icosphere(1));
    SnapshotOptions o;
    o.width = 8;
    test::expect_invalid([&] { render_rgb(c, o, nullptr); }, {"snapshot: size", "{8, 600}"});
    o = SnapshotOptions{};
    o.view = Vec3::Zero();
    test::expect_invalid([&] { render_rgb(c, o, nullptr); }, {"view must be a finite non-zero"});
    o = SnapshotOptions{};
    o.color = "area";
    test::expect_invalid([&] { render_rgb(c, o, nullptr); }, {"color must be", "'area'"});
}

} // namespace
} // namespace froth
