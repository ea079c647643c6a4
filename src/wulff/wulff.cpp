#include "wulff/wulff.h"

#include "core/errors.h"
#include "core/format.h"
#include "wulff/convex_hull.h"
#include "wulff/polytope.h"
#include "wulff/sphere_sampling.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace froth {
namespace {

constexpr int kMinDirections = 20;
constexpr int kMaxDirections = 200000;
/// Hull triangles of the Frank points whose fourth point is within this times max |d_k| of
/// their plane are one facet (one vertex of W_h). It catches round-off twins (points coplanar
/// in exact arithmetic, e.g. by symmetry, give vertices of W_h a few ulps apart that fold faces)
/// and nothing resolvable: measured over the presets with eps 1e-2..1e-5 and up to 164k
/// directions, 1e-15 still leaves twins and 1e-12 starts to fold faces of l1(1e-5).
constexpr double kCoplanarTolerance = 1e-14;

void check_subdivisions(const char* who, int k) {
    if (k < 0 || k > kMaxSubdivisions)
        throw InvalidInput(std::string(who) + ": subdivisions must be an integer in 0.." +
                           std::to_string(kMaxSubdivisions) + " (got " + std::to_string(k) + ")");
}

void check_scale(const char* who, double scale) {
    if (!std::isfinite(scale) || !(scale > 0.0))
        throw InvalidInput(std::string(who) + ": scale must be a finite number > 0 (got " +
                           fmt(scale) + ")");
}

void check_options(const WulffOptions& o) {
    if (o.directions) {
        if (*o.directions < kMinDirections || *o.directions > kMaxDirections)
            throw InvalidInput("wulff_shape: directions must be an integer in " +
                               std::to_string(kMinDirections) + ".." +
                               std::to_string(kMaxDirections) + " (got " +
                               std::to_string(*o.directions) + ")");
    } else {
        check_subdivisions("wulff_shape", o.subdivisions);
    }
    check_scale("wulff_shape", o.scale);
}

/// The unit plane directions p_k: the sphere sampling, then the facet directions that are not
/// already there (a near twin, closer than 1e-6, would only add an ill-conditioned vertex).
std::vector<Vec3> plane_directions(const Anisotropy& gamma, const WulffOptions& o) {
    std::vector<Vec3> p =
        o.directions ? fibonacci_sphere(*o.directions) : icosphere(o.subdivisions).vertices;
    if (!o.facet_directions) return p;
    const std::size_t n_sphere = p.size();
    for (const Vec3& f : facet_directions(gamma)) {
        const auto twin = std::find_if(p.begin(), p.begin() + n_sphere,
                                       [&](const Vec3& q) { return (q - f).norm() < 1e-6; });
        if (twin == p.begin() + n_sphere) p.push_back(f);
    }
    return p;
}

ClusterSpec one_body(TriangleSurface s) {
    ClusterSpec spec;
    spec.vertices = std::move(s.vertices);
    spec.surfaces.push_back({std::move(s.triangles), 1.0, {}});
    spec.bodies = {{0}};
    return spec;
}

/// A facet plane nu . q = h of a triangle, oriented so that h >= 0 (0 is inside the polytope).
struct FacetPlane {
    Vec3 nu;
    double h;
    double area;
};

std::vector<FacetPlane> facet_planes(const std::vector<Vec3>& X, const std::vector<Tri>& tris) {
    std::vector<FacetPlane> planes;
    planes.reserve(tris.size());
    for (const Tri& t : tris) {
        const Vec3 n = (X[t[1]] - X[t[0]]).cross(X[t[2]] - X[t[0]]);
        const double twice_area = n.norm();
        if (!(twice_area > 0.0)) continue;
        FacetPlane f{n / twice_area, 0.0, 0.5 * twice_area};
        f.h = f.nu.dot(X[t[0]] + X[t[1]] + X[t[2]]) / 3.0;
        if (f.h < 0.0) f.nu = -f.nu, f.h = -f.h;
        planes.push_back(f);
    }
    return planes;
}

/// Fibonacci points turned by a fixed rotation with generic angles: no icosphere vertex, no
/// facet direction and no unturned Fibonacci point is among them.
std::vector<Vec3> probe_directions(int n) {
    const Eigen::Matrix3d R =
        (Eigen::AngleAxisd(0.3, Vec3::UnitZ()) * Eigen::AngleAxisd(0.7, Vec3::UnitY()) *
         Eigen::AngleAxisd(1.1, Vec3::UnitX()))
            .toRotationMatrix();
    std::vector<Vec3> p = fibonacci_sphere(n);
    for (Vec3& x : p)
        x = R * x;
    return p;
}

void check_triangles(const std::vector<Vec3>& X, const std::vector<Tri>& tris) {
    if (tris.empty()) throw InvalidInput("cahn_hoffmann_check: no triangles");
    for (std::size_t i = 0; i < tris.size(); ++i)
        for (int v : tris[i])
            if (v < 0 || v >= static_cast<int>(X.size()))
                throw InvalidInput("cahn_hoffmann_check: triangle " + std::to_string(i + 1) +
                                   " names vertex " + std::to_string(v + 1) + ", but there are " +
                                   std::to_string(X.size()) + " vertices");
}

} // namespace

ClusterSpec wulff_shape(const Anisotropy& gamma, const WulffOptions& options) {
    check_options(options);
    // The half-space q . p_k <= gamma(p_k) is q . d_k <= 1 with d_k = p_k / gamma(p_k), a point
    // on the boundary of the Frank diagram: W_h is the polar of conv{d_k}.
    std::vector<Vec3> d = plane_directions(gamma, options);
    for (Vec3& p : d)
        p /= gamma.gamma(p);
    TriangleSurface s = polar_polytope(d, kCoplanarTolerance, "wulff_shape");
    for (Vec3& x : s.vertices)
        x *= options.scale;
    return one_body(std::move(s));
}

ClusterSpec frank_diagram(const Anisotropy& gamma, int subdivisions) {
    check_subdivisions("frank_diagram", subdivisions);
    TriangleSurface s = icosphere(subdivisions);
    for (Vec3& p : s.vertices)
        p /= gamma.gamma(p);
    return one_body(std::move(s));
}

CahnHoffmannCheck cahn_hoffmann_check(const Anisotropy& gamma, const std::vector<Vec3>& X,
                                      const std::vector<Tri>& triangles, double scale,
                                      int samples) {
    check_scale("cahn_hoffmann_check", scale);
    if (samples < 1 || samples > kMaxDirections)
        throw InvalidInput("cahn_hoffmann_check: samples must be an integer in 1.." +
                           std::to_string(kMaxDirections) + " (got " + std::to_string(samples) +
                           ")");
    check_triangles(X, triangles);
    const std::vector<FacetPlane> planes = facet_planes(X, triangles);
    CahnHoffmannCheck r;
    double energy = 0.0, volume = 0.0;
    for (const FacetPlane& f : planes) {
        const double g = gamma.gamma(f.nu);
        r.max_support_error = std::max(r.max_support_error, std::abs(f.h - scale * g) / scale);
        energy += g * f.area;
        volume += f.h * f.area / 3.0;
    }
    // E(r W) = 3 r^2 |W| = 3 |r W| / r for the energy sum_t gamma(nu_t) |t|.
    r.energy_defect = std::abs(energy - 3.0 * volume / scale) / (3.0 * volume / scale);
    r.samples = samples;
    for (const Vec3& p : probe_directions(samples)) {
        const Vec3 x = scale * gamma.gamma_prime(p);
        double inside = std::numeric_limits<double>::infinity();
        for (const FacetPlane& f : planes)
            inside = std::min(inside, f.h - f.nu.dot(x));
        r.max_distance = std::max(r.max_distance, std::abs(inside) / scale);
        r.max_outside = std::max(r.max_outside, -inside / scale);
    }
    return r;
}

bool wulff_shape_available() {
    return convex_hull_available();
}

} // namespace froth
