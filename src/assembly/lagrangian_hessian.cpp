// The Hessian of the Lagrangian of minimize's Newton steps (lagrangian_hessian.h).
#include "assembly/lagrangian_hessian.h"

#include <Eigen/Dense>

namespace froth {
namespace {

Eigen::Matrix3d cross_matrix(const Vec3& a) {
    Eigen::Matrix3d m;
    m << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
    return m;
}

using Triplets = std::vector<Eigen::Triplet<double>>;

void add_block(Triplets& t, int a, int b, const Eigen::Matrix3d& B) {
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            t.emplace_back(3 * a + i, 3 * b + j, B(i, j));
}

/// sigma times the area's Hessian of one facet (the header's formula), added block by block.
void add_area_hessian(Triplets& t, const Tri& tri, const std::array<Vec3, 3>& x, double sigma) {
    const Vec3 n = (x[1] - x[0]).cross(x[2] - x[0]);
    const double length = n.norm();
    if (!(length > 0)) return; // a degenerate facet: minimize rejects such states
    const Vec3 nu = n / length;
    const Eigen::Matrix3d tangent = Eigen::Matrix3d::Identity() - nu * nu.transpose();
    std::array<Eigen::Matrix3d, 3> E;
    for (int i = 0; i < 3; ++i)
        E[i] = cross_matrix(x[(i + 2) % 3] - x[(i + 1) % 3]);
    const Eigen::Matrix3d N = cross_matrix(nu);
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) {
            Eigen::Matrix3d H = -E[i] * tangent * E[j] / length;
            if (j == (i + 2) % 3) H += N;
            if (j == (i + 1) % 3) H -= N;
            add_block(t, tri[i], tri[j], 0.5 * sigma * H);
        }
}

/// -p s d^2 V of one facet of a body (s its side): blocks s [e_j]_x / 6 at (i, j).
void add_volume_hessian(Triplets& t, const Tri& tri, const std::array<Vec3, 3>& x, double factor) {
    for (int j = 0; j < 3; ++j) {
        const Eigen::Matrix3d E = factor / 6.0 * cross_matrix(x[(j + 2) % 3] - x[(j + 1) % 3]);
        for (int i = 0; i < 3; ++i)
            add_block(t, tri[i], tri[j], E);
    }
}

} // namespace

SparseMatrix lagrangian_hessian(const Cluster& c, const std::vector<double>& pressures) {
    const std::vector<Vec3>& X = c.positions();
    Triplets t;
    for (const Surface& s : c.surfaces())
        for (std::size_t f = 0; f < s.triangles.size(); ++f)
            add_area_hessian(t, s.triangles[f], s.corners(X, f), s.sigma);
    SparseMatrix H(3 * c.n_vertices(), 3 * c.n_vertices());
    H.setFromTriplets(t.begin(), t.end());
    t.clear();
    const int constraints = std::min<int>(c.n_volume_constraints(), pressures.size());
    for (int b = 0; b < constraints; ++b)
        for (const BodyFace& face : c.bodies()[b].faces) {
            const Surface& s = c.surface(face.surface);
            for (std::size_t f = 0; f < s.triangles.size(); ++f)
                add_volume_hessian(t, s.triangles[f], s.corners(X, f), -pressures[b] * face.sign);
        }
    SparseMatrix V(H.rows(), H.cols());
    V.setFromTriplets(t.begin(), t.end());
    const SparseMatrix Vt = V.transpose();
    return H + 0.5 * (V + Vt);
}

} // namespace froth
