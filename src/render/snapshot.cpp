// The z-buffer rasterizer of snapshot.h and its PNG encoding.
#include "render/snapshot.h"

#include "core/errors.h"
#include "geometry/geometry.h"
#include "io/text_file.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <vector>

namespace froth {
namespace {

constexpr int kSamples = 3; // supersampling per axis
constexpr unsigned char kBackground = 250;

using Rgb = std::array<float, 3>;

struct Camera {
    Vec3 center, right, up, dir;
    double scale; // supersampled pixels per unit length
    int W, H;
    Vec3 project(const Vec3& x) const { // (column, row, depth): rows grow downwards
        const Vec3 d = x - center;
        return {0.5 * W + scale * d.dot(right), 0.5 * H - scale * d.dot(up), d.dot(dir)};
    }
};

Camera make_camera(const Cluster& c, const Vec3& view, int W, int H) {
    Camera cam;
    cam.W = W, cam.H = H;
    cam.dir = view.normalized();
    const Vec3 z = std::abs(cam.dir.z()) > 0.99 ? Vec3::UnitY() : Vec3::UnitZ();
    cam.right = cam.dir.cross(z).normalized();
    cam.up = cam.right.cross(cam.dir);
    Vec3 lo = c.position(0), hi = lo;
    for (const Vec3& x : c.positions())
        lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    cam.center = 0.5 * (lo + hi);
    double radius = 0;
    for (const Vec3& x : c.positions())
        radius = std::max(radius, (x - cam.center).norm());
    cam.scale = 0.92 * std::min(W, H) / (2 * std::max(radius, 1e-300));
    return cam;
}

/// Blue (negative) - white - red (positive), t in [-1, 1].
Rgb diverging(double t) {
    t = std::clamp(t, -1.0, 1.0);
    const Rgb white{0.97f, 0.97f, 0.97f}, blue{0.23f, 0.30f, 0.75f}, red{0.71f, 0.02f, 0.15f};
    const Rgb& end = t < 0 ? blue : red;
    const float s = static_cast<float>(std::abs(t));
    return {white[0] + s * (end[0] - white[0]), white[1] + s * (end[1] - white[1]),
            white[2] + s * (end[2] - white[2])};
}

/// Per-vertex colours for color = "mean_curvature" (grey otherwise: unused).
std::vector<Rgb> vertex_colors(const Cluster& c, const std::string& mode) {
    std::vector<Rgb> colors(c.n_vertices(), Rgb{0.8f, 0.8f, 0.8f});
    if (mode != "mean_curvature") return colors;
    const std::vector<double> H = vertex_mean_curvature(c);
    std::vector<double> finite;
    for (double h : H)
        if (std::isfinite(h)) finite.push_back(h);
    if (finite.empty()) return colors;
    // The 2nd and 98th percentiles: a few junction vertices must not wash the scale out.
    std::sort(finite.begin(), finite.end());
    const double lo = finite[finite.size() * 2 / 100], hi = finite[finite.size() * 98 / 100];
    for (int v = 0; v < c.n_vertices(); ++v) {
        const double h = std::isfinite(H[v]) ? H[v] : 0;
        if (lo < 0 && hi > 0) { // both signs: diverging about 0
            colors[v] = diverging(h / std::max(-lo, hi));
        } else { // one sign (a bubble): the range from pale to full, in the sign's colour
            const double t = hi > lo ? (h - lo) / (hi - lo) : 1;
            colors[v] = diverging((hi > 0 ? 1 : -1) * (0.15 + 0.85 * std::clamp(t, 0.0, 1.0)));
        }
    }
    return colors;
}

struct Buffers {
    std::vector<float> depth;
    std::vector<Rgb> color;
    std::vector<int> surface;
};

/// Draws one facet with per-corner colours, a flat shade and depth test.
void draw_triangle(const std::array<Vec3, 3>& p, const std::array<Rgb, 3>& col, float shade,
                   int surface, Buffers& b, int W, int H) {
    const double area = (p[1].x() - p[0].x()) * (p[2].y() - p[0].y()) -
                        (p[2].x() - p[0].x()) * (p[1].y() - p[0].y());
    if (!(std::abs(area) > 1e-12)) return;
    const int x0 =
        std::max(0, static_cast<int>(std::floor(std::min({p[0].x(), p[1].x(), p[2].x()}))));
    const int x1 =
        std::min(W - 1, static_cast<int>(std::ceil(std::max({p[0].x(), p[1].x(), p[2].x()}))));
    const int y0 =
        std::max(0, static_cast<int>(std::floor(std::min({p[0].y(), p[1].y(), p[2].y()}))));
    const int y1 =
        std::min(H - 1, static_cast<int>(std::ceil(std::max({p[0].y(), p[1].y(), p[2].y()}))));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const double px = x + 0.5, py = y + 0.5;
            double w[3];
            for (int k = 0; k < 3; ++k) {
                const Vec3 &a = p[(k + 1) % 3], &bb = p[(k + 2) % 3];
                w[k] = ((bb.x() - a.x()) * (py - a.y()) - (px - a.x()) * (bb.y() - a.y())) / area;
            }
            if (w[0] < 0 || w[1] < 0 || w[2] < 0) continue;
            const float z = static_cast<float>(w[0] * p[0].z() + w[1] * p[1].z() + w[2] * p[2].z());
            const std::size_t i = static_cast<std::size_t>(y) * W + x;
            if (z >= b.depth[i]) continue;
            b.depth[i] = z;
            b.surface[i] = surface;
            for (int ch = 0; ch < 3; ++ch)
                b.color[i][ch] = shade * static_cast<float>(w[0] * col[0][ch] + w[1] * col[1][ch] +
                                                            w[2] * col[2][ch]);
        }
}

void check_options(const SnapshotOptions& o) {
    if (o.width < 16 || o.width > 8192 || o.height < 16 || o.height > 8192)
        throw InvalidInput("snapshot: size must be {w, h} with 16 <= w, h <= 8192, got {" +
                           std::to_string(o.width) + ", " + std::to_string(o.height) + "}");
    if (!(o.view.allFinite() && o.view.norm() > 0))
        throw InvalidInput("snapshot: view must be a finite non-zero direction {x, y, z}");
    if (o.color != "surface" && o.color != "mean_curvature")
        throw InvalidInput("snapshot: color must be \"surface\" or \"mean_curvature\", got '" +
                           o.color + "'");
}

} // namespace

std::array<unsigned char, 3> surface_color(int i) {
    static const unsigned char palette[][3] = {
        {78, 121, 167}, {242, 142, 43},  {225, 87, 89},   {118, 183, 178}, {89, 161, 79},
        {237, 201, 72}, {176, 122, 161}, {255, 157, 167}, {156, 117, 95},  {186, 176, 172}};
    const auto& p = palette[i % 10];
    return {p[0], p[1], p[2]};
}

std::string render_rgb(const Cluster& c, const SnapshotOptions& o, SnapshotStats* stats) {
    check_options(o);
    const int W = o.width * kSamples, H = o.height * kSamples;
    const Camera cam = make_camera(c, o.view, W, H);
    const Vec3 light = (-cam.dir + 0.5 * cam.up - 0.3 * cam.right).normalized();
    Buffers b{std::vector<float>(std::size_t(W) * H, std::numeric_limits<float>::infinity()),
              std::vector<Rgb>(std::size_t(W) * H, Rgb{1, 1, 1}),
              std::vector<int>(std::size_t(W) * H, -1)};
    const std::vector<Rgb> by_vertex = vertex_colors(c, o.color);
    for (int s = 0; s < c.n_surfaces(); ++s) {
        const auto sc = surface_color(s);
        const Rgb flat{sc[0] / 255.f, sc[1] / 255.f, sc[2] / 255.f};
        for (std::size_t f = 0; f < c.surface(s).triangles.size(); ++f) {
            const Tri& t = c.surface(s).triangles[f];
            const auto x = c.surface(s).corners(c.positions(), f); // whole across a periodic box
            const Vec3 n = (x[1] - x[0]).cross(x[2] - x[0]).normalized();
            const float shade = static_cast<float>(0.3 + 0.7 * std::abs(n.dot(light)));
            std::array<Rgb, 3> col;
            for (int k = 0; k < 3; ++k)
                col[k] = o.color == "surface" ? flat : by_vertex[t[k]];
            draw_triangle({cam.project(x[0]), cam.project(x[1]), cam.project(x[2])}, col, shade, s,
                          b, W, H);
        }
    }
    std::string rgb(std::size_t(o.width) * o.height * 3, static_cast<char>(kBackground));
    std::size_t covered = 0;
    std::set<int> seen;
    for (int y = 0; y < o.height; ++y)
        for (int x = 0; x < o.width; ++x) {
            float sum[3] = {0, 0, 0};
            int hits = 0;
            for (int sy = 0; sy < kSamples; ++sy)
                for (int sx = 0; sx < kSamples; ++sx) {
                    const std::size_t i = std::size_t(y * kSamples + sy) * W + x * kSamples + sx;
                    const bool hit = b.surface[i] >= 0;
                    hits += hit;
                    if (hit) seen.insert(b.surface[i]);
                    for (int ch = 0; ch < 3; ++ch)
                        sum[ch] += hit ? 255.f * b.color[i][ch] : kBackground;
                }
            covered += 2 * hits >= kSamples * kSamples;
            for (int ch = 0; ch < 3; ++ch)
                rgb[(std::size_t(y) * o.width + x) * 3 + ch] = static_cast<char>(
                    std::lround(std::clamp(sum[ch] / (kSamples * kSamples), 0.f, 255.f)));
        }
    if (stats) {
        stats->coverage = static_cast<double>(covered) / (double(o.width) * o.height);
        stats->surfaces = o.color == "surface" ? static_cast<int>(seen.size()) : 0;
    }
    return rgb;
}

SnapshotStats write_snapshot(const Cluster& c, const std::string& path, const SnapshotOptions& o) {
    SnapshotStats stats;
    const std::string rgb = render_rgb(c, o, &stats);
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = static_cast<png_uint_32>(o.width);
    image.height = static_cast<png_uint_32>(o.height);
    image.format = PNG_FORMAT_RGB;
    png_alloc_size_t size = 0;
    if (!png_image_write_to_memory(&image, nullptr, &size, 0, rgb.data(), 0, nullptr))
        throw IoError("snapshot: libpng cannot encode the image: " + std::string(image.message));
    std::string png(size, '\0');
    if (!png_image_write_to_memory(&image, png.data(), &size, 0, rgb.data(), 0, nullptr))
        throw IoError("snapshot: libpng cannot encode the image: " + std::string(image.message));
    png.resize(size);
    io::write_text_file(path, png, "snapshot");
    return stats;
}

} // namespace froth
