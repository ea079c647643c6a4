#pragma once
/// Headless pictures of a cluster (c:snapshot, evolve{snapshots}): a shaded PNG, no display
/// and no OpenGL needed. The facets are drawn by froth's own z-buffer rasterizer (orthographic
/// view, two-sided Lambert shading with an ambient term, 3x3 supersampling for smooth edges)
/// and encoded by libpng. Chosen over VTK's offscreen rendering, whose Debian build needs an
/// X or EGL context and ~400 MB of packages, and over Cairo, a 2D painter that would still
/// need the depth sorting done here and cannot resolve intersecting facets: a z-buffer is
/// exact for any overlap and is ~150 lines; libpng is already a dependency of libgmsh-dev.

#include "mesh/cluster.h"

#include <string>

namespace froth {

struct SnapshotOptions {
    int width = 800, height = 600;
    /// The direction the camera looks along (from the eye into the scene); the picture is
    /// an orthographic view that fits the cluster's bounding sphere.
    Vec3 view = Vec3(-1.0, -0.8, -0.6);
    /// "surface": one colour per surface (a fixed palette); "mean_curvature": the vertex mean
    /// curvature on a blue-white-red scale symmetric about 0.
    std::string color = "surface";
};

/// What the picture shows (also what the tests check).
struct SnapshotStats {
    double coverage = 0; ///< fraction of pixels that show the cluster
    int surfaces = 0;    ///< surfaces visible in the picture (color "surface"; else 0)
};

/// Renders c into an RGB image of width x height, row-major, 3 bytes per pixel.
/// \throw InvalidInput for a size outside 16..8192, a zero view direction or an unknown colour.
std::string render_rgb(const Cluster& c, const SnapshotOptions& options, SnapshotStats* stats);

/// render_rgb written as a PNG to path atomically (io/text_file.h).
/// \throw InvalidInput as render_rgb, IoError ("snapshot: cannot open ...").
SnapshotStats write_snapshot(const Cluster& c, const std::string& path,
                             const SnapshotOptions& options = {});

/// The surface palette's colour of surface i (RGB 0..255), for tests and legends.
std::array<unsigned char, 3> surface_color(int i);

} // namespace froth
