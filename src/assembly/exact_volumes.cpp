// The weights and volume right-hand side of the volume-exact surface diffusion step
// (exact_volumes.h has the equations).
#include "assembly/exact_volumes.h"

#include <Eigen/Dense>

namespace froth {
namespace {

/// chi_bk: the sign (+1 outward, -1 inward, 0 absent, or in a periodic cell on both sides) of
/// pair k's surface in body b.
std::vector<std::vector<int>> body_surface_signs(const Cluster& c) {
    std::vector<std::vector<int>> sign(c.n_bodies(), std::vector<int>(c.n_surfaces(), 0));
    for (int b = 0; b < c.n_bodies(); ++b)
        for (const BodyFace& f : c.bodies()[b].faces) sign[b][f.surface] += f.sign; // 0: both sides
    return sign;
}

} // namespace

std::vector<Vec3> simpson_pair_weights(const Cluster& c, const std::vector<Vec3>& dX) {
    const auto& X = c.positions();
    std::vector<Vec3> w(c.n_pairs(), Vec3::Zero());
    for (int i = 0; i < c.n_surfaces(); ++i)
        for (std::size_t f = 0; f < c.surface(i).triangles.size(); ++f) {
            const Tri& t = c.surface(i).triangles[f];
            const auto x = c.surface(i).corners(X, f);
            const Vec3 e1 = x[1] - x[0], e2 = x[2] - x[0];
            const Vec3 d1 = dX[t[1]] - dX[t[0]], d2 = dX[t[2]] - dX[t[0]];
            const Vec3 mean = e1.cross(e2) + (e1.cross(d2) + d1.cross(e2)) / 2 + d1.cross(d2) / 3;
            for (int v : t) w[c.pair_index(v, i)] += mean / 6;
        }
    return w;
}

PairGeometry with_pair_weights(PairGeometry g, const std::vector<Vec3>& w) {
    for (std::size_t k = 0; k < w.size(); ++k) g.omega[k] = w[k] / g.mass[k];
    return g;
}

Eigen::VectorXd volume_rhs(const Cluster& c, const PairGeometry& g, const Eigen::VectorXd& swept) {
    const int nb = c.n_bodies();
    Eigen::VectorXd r = Eigen::VectorXd::Zero(c.n_pairs());
    if (nb == 0) return r;
    const auto sign = body_surface_signs(c);
    Eigen::MatrixXd S = Eigen::MatrixXd::Zero(nb, nb);
    for (int k = 0; k < c.n_pairs(); ++k)
        for (int a = 0; a < nb; ++a)
            for (int b = 0; b < nb; ++b)
                S(a, b) += sign[a][c.pair_surface(k)] * sign[b][c.pair_surface(k)] * g.mass[k];
    const Eigen::VectorXd coef = S.ldlt().solve(swept);
    for (int k = 0; k < c.n_pairs(); ++k)
        for (int b = 0; b < nb; ++b) r[k] += coef[b] * sign[b][c.pair_surface(k)] * g.mass[k];
    return r;
}

namespace {

Eigen::Matrix3d cross_matrix(const Vec3& u) {
    Eigen::Matrix3d m;
    m << 0, -u[2], u[1], u[2], 0, -u[0], -u[1], u[0], 0;
    return m;
}

} // namespace

void assemble_weight_derivative(const Cluster& c, const PositionBasis& P,
                                const std::vector<Vec3>& dX, const Eigen::VectorXd& kappa,
                                int size, SparseBuilder& M) {
    M.begin(size, size);
    const auto& X = c.positions();
    for (int i = 0; i < c.n_surfaces(); ++i)
        for (std::size_t f = 0; f < c.surface(i).triangles.size(); ++f) {
            const Tri& t = c.surface(i).triangles[f];
            const auto x = c.surface(i).corners(X, f);
            const Vec3 u1 = (x[1] - x[0]) / 2 + (dX[t[1]] - dX[t[0]]) / 3;
            const Vec3 u2 = (x[2] - x[0]) / 2 + (dX[t[2]] - dX[t[0]]) / 3;
            const Eigen::Matrix3d D[3] = {cross_matrix(u2 - u1), -cross_matrix(u2), cross_matrix(u1)};
            for (int a = 0; a < 3; ++a) {
                const double k = kappa[c.pair_index(t[a], i)] / 6;
                for (int b = 0; b < 3; ++b) P.add_block(M, t[a], t[b], k * D[b]);
            }
        }
    M.finish();
}

Eigen::VectorXd pair_sweep(const Cluster& c, const std::vector<Vec3>& w, const std::vector<Vec3>& dX) {
    const auto sign = body_surface_signs(c);
    Eigen::VectorXd swept = Eigen::VectorXd::Zero(c.n_bodies());
    for (int v = 0; v < c.n_vertices(); ++v)
        for (int k = c.pair_begin(v); k < c.pair_begin(v + 1); ++k)
            for (int b = 0; b < c.n_bodies(); ++b)
                swept[b] += sign[b][c.pair_surface(k)] * w[k].dot(dX[v]);
    return swept;
}

Eigen::VectorXd pair_kappa(const KappaBasis& Z, const Eigen::VectorXd& z, int offset) {
    Eigen::VectorXd kappa = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(Z.start.size()) - 1);
    for (int k = 0; k + 1 < static_cast<int>(Z.start.size()); ++k)
        for (int x = Z.start[k]; x < Z.start[k + 1]; ++x) kappa[k] += Z.val[x] * z[offset + Z.col[x]];
    return kappa;
}

void add_kappa_rhs(const KappaBasis& Z, const Eigen::VectorXd& r, int offset, Eigen::VectorXd& rhs) {
    for (int k = 0; k + 1 < static_cast<int>(Z.start.size()); ++k)
        for (int x = Z.start[k]; x < Z.start[k + 1]; ++x) rhs[offset + Z.col[x]] += Z.val[x] * r[k];
}

} // namespace froth
