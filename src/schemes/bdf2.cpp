// The order-2 step's coefficients and predictor (bdf2.h).
#include "schemes/bdf2.h"

#include "geometry/geometry.h"

#include <algorithm>
#include <cmath>

namespace froth {

Bdf2Step make_bdf2_step(const Cluster& c, std::vector<Vec3> predicted,
                        const std::vector<Vec3>& previous, double tau, double previous_tau) {
    const double w = tau / previous_tau;
    Bdf2Step s{tau, (1 + 2 * w) / (1 + w), w * w / (1 + w), c, {}, {}};
    const auto& X = c.positions();
    s.shift.resize(X.size()), s.memory.resize(X.size());
    for (std::size_t v = 0; v < X.size(); ++v) {
        s.shift[v] = predicted[v] - X[v];
        s.memory[v] = (s.b / s.a) * (X[v] - previous[v]);
    }
    s.predictor.set_positions(std::move(predicted));
    return s;
}

double shape_difference(const Cluster& c, const std::vector<Vec3>& a, const std::vector<Vec3>& b) {
    const PairGeometry g = pair_geometry(c);
    const auto& X = c.positions();
    Vec3 lo = X[0], hi = X[0];
    for (const Vec3& x : X) lo = lo.cwiseMin(x), hi = hi.cwiseMax(x);
    double worst = 0;
    for (int v = 0; v < c.n_vertices(); ++v) {
        const Vec3 d = a[v] - b[v];
        Vec3 q[3];
        int rank = 0;
        double normal2 = 0;
        for (int k = c.pair_begin(v); k < c.pair_begin(v + 1) && rank < 3; ++k) {
            Vec3 u = g.omega[k];
            for (int j = 0; j < rank; ++j) u -= q[j].dot(u) * q[j];
            if (u.norm() <= 1e-3 * g.omega[k].norm()) continue; // (nearly) parallel normals
            q[rank] = u.normalized();
            normal2 += std::pow(q[rank].dot(d), 2);
            ++rank;
        }
        worst = std::max(worst, std::sqrt(normal2));
    }
    return worst / (hi - lo).norm();
}

} // namespace froth
