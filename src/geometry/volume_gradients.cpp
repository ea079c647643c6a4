// d V_b / d X: the constraint gradients of the volume-exact schemes and of minimize (the
// columns G of the bordered systems, numerics.md "Static equilibria").
#include "geometry/geometry.h"

#include <algorithm>
#include <cmath>

namespace froth {
namespace {

/// The vertices on the lid loops of a body.
std::vector<int> rim_vertices(const Body& b) {
    std::vector<int> rim;
    for (const Lid& lid : b.lids)
        for (const auto& e : lid.edges) rim.push_back(e[0]), rim.push_back(e[1]);
    std::sort(rim.begin(), rim.end());
    rim.erase(std::unique(rim.begin(), rim.end()), rim.end());
    return rim;
}

/// d (sum of the body's lid volumes) / d X_v by central differences with a step relative to
/// the lid's size (the lids of flat walls are quadratic in the positions: exact up to round-off).
/// X is the same on entry and on return (only X[v] moves in between).
Vec3 lid_gradient(const Cluster& c, const Body& b, std::vector<Vec3>& X, int v, double step) {
    const Vec3 x = X[v];
    Vec3 g;
    for (int d = 0; d < 3; ++d) {
        double lid[2] = {0, 0};
        for (int s = 0; s < 2; ++s) {
            X[v] = x;
            X[v][d] += s == 0 ? step : -step;
            for (const Lid& l : b.lids) lid[s] += lid_volume(c, l, X);
        }
        g[d] = (lid[0] - lid[1]) / (2 * step);
    }
    X[v] = x;
    return g;
}

/// Adds d V_b / d X of body bi at X to add(v, g) vertex by vertex (a vertex may come more
/// than once). Y is a scratch copy of X for the lids' differences (filled on first use).
template <class Add>
void add_body_gradient(const Cluster& c, const std::vector<Vec3>& X, int bi,
                       std::vector<Vec3>& Y, Add&& add) {
    const Body& b = c.bodies()[bi];
    const std::vector<int> rim = rim_vertices(b);
    const auto on_rim = [&](int v) { return std::binary_search(rim.begin(), rim.end(), v); };
    for (const BodyFace& f : b.faces)
        for (std::size_t j = 0; j < c.surface(f.surface).triangles.size(); ++j) {
            const Tri& t = c.surface(f.surface).triangles[j];
            const Vec3 a2 = f.sign * area_vector2(c.surface(f.surface).corners(X, j)) / 6.0;
            for (int k = 0; k < 3; ++k) {
                const int v = t[k];
                // The cone's gradient X_b x X_c / 6 differs from a2 / 6 by terms that
                // cancel around a closed fan; a rim fan is closed by the lid instead.
                add(v, on_rim(v) ? Vec3(f.sign * X[t[(k + 1) % 3]].cross(X[t[(k + 2) % 3]]) / 6.0)
                                 : a2);
            }
        }
    if (rim.empty()) return;
    double size = 0;
    for (int v : rim) size = std::max(size, (X[v] - X[rim[0]]).norm());
    const double step = 1e-4 * std::max(size, 1e-300);
    if (Y.empty()) Y = X;
    for (int v : rim) add(v, lid_gradient(c, b, Y, v, step));
}

} // namespace

Eigen::MatrixXd body_volume_gradients(const Cluster& c) {
    return body_volume_gradients(c, c.positions());
}

// Dense: a column per body, for clusters of few bodies (3 n_vertices x n_bodies doubles);
// accumulating in place costs a tenth of building triplets and compressing them.
Eigen::MatrixXd body_volume_gradients(const Cluster& c, const std::vector<Vec3>& X) {
    Eigen::MatrixXd G = Eigen::MatrixXd::Zero(3 * c.n_vertices(), c.n_bodies());
    std::vector<Vec3> Y;
    for (int bi = 0; bi < c.n_bodies(); ++bi)
        add_body_gradient(c, X, bi, Y, [&](int v, const Vec3& g) {
            G.col(bi).segment<3>(3 * v) += g;
        });
    return G;
}

// Sparse: a body's column is nonzero only at the vertices of its films, so a foam of n cells
// stores O(n_vertices) numbers instead of O(n_vertices n). Each column is summed in a dense
// scratch vector and copied out at the vertices it touched.
Eigen::SparseMatrix<double> sparse_body_volume_gradients(const Cluster& c,
                                                         const std::vector<Vec3>& X) {
    std::vector<Eigen::Triplet<double>> entries;
    std::vector<Vec3> Y, sum(c.n_vertices(), Vec3::Zero());
    std::vector<char> seen(c.n_vertices(), 0);
    std::vector<int> touched;
    for (int bi = 0; bi < c.n_bodies(); ++bi) {
        add_body_gradient(c, X, bi, Y, [&](int v, const Vec3& g) {
            if (!seen[v]) seen[v] = 1, touched.push_back(v);
            sum[v] += g;
        });
        for (int v : touched) {
            for (int d = 0; d < 3; ++d) entries.emplace_back(3 * v + d, bi, sum[v][d]);
            sum[v].setZero(), seen[v] = 0;
        }
        touched.clear();
    }
    Eigen::SparseMatrix<double> G(3 * c.n_vertices(), c.n_bodies());
    G.setFromTriplets(entries.begin(), entries.end());
    return G;
}

} // namespace froth
