#include "wulff/sphere_sampling.h"

#include <Eigen/Eigenvalues>

#include <cmath>
#include <map>
#include <numbers>
#include <utility>

namespace froth {
namespace {

TriangleSurface icosahedron() {
    const double t = std::numbers::phi;
    TriangleSurface m;
    m.vertices = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                  {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
    for (Vec3& v : m.vertices)
        v.normalize();
    m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                   {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                   {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                   {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    return m;
}

/// Splits every triangle into four at its edge midpoints (projected to the sphere); a midpoint
/// is made once per edge so the sphere stays closed.
TriangleSurface subdivide(const TriangleSurface& in) {
    TriangleSurface out{in.vertices, {}};
    std::map<std::pair<int, int>, int> midpoint;
    auto mid = [&](int a, int b) {
        const auto key = std::minmax(a, b);
        auto [it, fresh] = midpoint.try_emplace(key, static_cast<int>(out.vertices.size()));
        if (fresh) out.vertices.push_back((in.vertices[a] + in.vertices[b]).normalized());
        return it->second;
    };
    out.triangles.reserve(4 * in.triangles.size());
    for (const Tri& t : in.triangles) {
        const int ab = mid(t[0], t[1]), bc = mid(t[1], t[2]), ca = mid(t[2], t[0]);
        out.triangles.push_back({t[0], ab, ca});
        out.triangles.push_back({t[1], bc, ab});
        out.triangles.push_back({t[2], ca, bc});
        out.triangles.push_back({ab, bc, ca});
    }
    return out;
}

/// The unit eigenvectors of the needle-like terms (see facet_directions), one per +- pair.
std::vector<Vec3> needle_axes(const Anisotropy& gamma) {
    std::vector<Vec3> axes;
    for (int l = 0; l < gamma.n_terms(); ++l) {
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(gamma.G(l));
        const Vec3 lambda = es.eigenvalues(); // ascending
        if (lambda[2] < 25.0 * lambda[1]) continue;
        const Vec3 a = es.eigenvectors().col(2);
        bool repeated = false;
        for (const Vec3& b : axes)
            repeated = repeated || std::abs(a.dot(b)) > 1.0 - 1e-12;
        if (!repeated) axes.push_back(a);
    }
    return axes;
}

/// Appends +-p (p normalised) unless p is (nearly) zero or already present.
void add_pair(std::vector<Vec3>& out, const Vec3& p) {
    const double n = p.norm();
    if (!(n > 1e-9)) return;
    const Vec3 u = p / n;
    for (const Vec3& q : out)
        if ((q - u).norm() < 1e-9 || (q + u).norm() < 1e-9) return;
    out.push_back(u);
    out.push_back(-u);
}

} // namespace

TriangleSurface icosphere(int subdivisions) {
    TriangleSurface m = icosahedron();
    for (int k = 0; k < subdivisions; ++k)
        m = subdivide(m);
    return m;
}

std::vector<Vec3> facet_directions(const Anisotropy& gamma) {
    const std::vector<Vec3> a = needle_axes(gamma);
    const int n = static_cast<int>(a.size());
    std::vector<Vec3> out;
    for (const Vec3& ai : a)
        add_pair(out, ai);
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            add_pair(out, a[i].cross(a[j]));
    for (int i = 0; i < n; ++i)
        for (int j = i + 1; j < n; ++j)
            for (int k = j + 1; k < n; ++k) {
                Eigen::Matrix3d M;
                M.row(0) = a[i], M.row(1) = a[j], M.row(2) = a[k];
                if (std::abs(M.determinant()) < 1e-6) continue;
                const Eigen::Matrix3d Minv = M.inverse();
                for (int s = 0; s < 4; ++s) // the other four sign patterns are the negatives
                    add_pair(out, Minv * Vec3(1.0, s & 1 ? -1.0 : 1.0, s & 2 ? -1.0 : 1.0));
            }
    return out;
}

} // namespace froth
