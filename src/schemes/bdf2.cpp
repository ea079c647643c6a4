// The order-2 step's coefficients and predictor (bdf2.h).
#include "schemes/bdf2.h"

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

} // namespace froth
