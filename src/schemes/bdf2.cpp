// The order-2 step's coefficients and predictor (bdf2.h).
#include "schemes/bdf2.h"

#include "geometry/geometry.h"

namespace froth {
namespace {

/// D projected onto the span of the vertex's pair normals and wall normals: the directions in
/// which the vertex moves the surface (free film: its normal; triple line: the plane normal to
/// the line; contact line: the plane of the film normal and the wall normal).
std::vector<Vec3> shape_motion(const Cluster& c, const std::vector<Vec3>& D) {
    const PairGeometry g = pair_geometry(c);
    std::vector<Vec3> out(D.size());
    for (int v = 0; v < c.n_vertices(); ++v) {
        Vec3 q[3];
        int rank = 0;
        const auto add = [&](Vec3 u) {
            for (int k = 0; k < rank; ++k) u -= q[k].dot(u) * q[k];
            if (rank < 3 && u.norm() > 1e-3) q[rank++] = u.normalized();
        };
        for (int k = c.pair_begin(v); k < c.pair_begin(v + 1); ++k)
            add(g.omega[k].normalized());
        for (int w : c.vertex_walls(v)) add(c.walls()[w]->normal(c.position(v)).normalized());
        Vec3 p = Vec3::Zero();
        for (int k = 0; k < rank; ++k) p += q[k].dot(D[v]) * q[k];
        out[v] = p;
    }
    return out;
}

} // namespace

Bdf2Step make_bdf2_step(const Cluster& c, const std::vector<Vec3>& previous, double tau,
                        double previous_tau) {
    const double w = tau / previous_tau;
    Bdf2Step s{tau, (1 + 2 * w) / (1 + w), w * w / (1 + w), c, {}, {}};
    const auto& X = c.positions();
    s.shift.resize(X.size()), s.memory.resize(X.size());
    std::vector<Vec3> predicted(X.size()), Dv(X.size());
    for (std::size_t v = 0; v < X.size(); ++v)
        Dv[v] = X[v] - previous[v];
    const std::vector<Vec3> Dn = shape_motion(c, Dv);
    for (std::size_t v = 0; v < X.size(); ++v) {
        const Vec3 D = Dv[v];
        s.shift[v] = w * Dn[v];
        s.memory[v] = (s.b / s.a) * D;
        predicted[v] = X[v] + s.shift[v];
    }
    s.predictor.set_positions(std::move(predicted));
    return s;
}

} // namespace froth
