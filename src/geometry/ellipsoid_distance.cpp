#include "core/errors.h"
#include "geometry/geometry.h"

#include <algorithm>
#include <cmath>

namespace froth {

double distance_to_ellipsoid(const Vec3& x, const Vec3& a) {
    if (!(a.minCoeff() > 0) || !a.allFinite())
        throw InvalidInput("ellipsoid distance: the semi-axes must be positive and finite");
    // f(t) = sum (a_i x_i / (a_i^2 + t))^2 - 1 is convex and decreasing where every
    // a_i^2 + t > 0 (for x_i != 0). At t = max_i (a_i |x_i| - a_i^2) one term is 1, so f >= 0:
    // Newton from there rises monotonically to the root (the tangent of a convex function lies
    // below it). Components with x_i = 0 drop out: the measure is meant for points near the
    // surface, not for points on a symmetry plane deep inside.
    const Vec3 ax = a.cwiseProduct(x);
    const Vec3 a2 = a.cwiseProduct(a);
    if (ax.cwiseAbs().maxCoeff() == 0) return a.minCoeff(); // x is the center
    double t = -1e300;
    for (int d = 0; d < 3; ++d)
        if (x[d] != 0) t = std::max(t, a[d] * std::abs(x[d]) - a2[d]);
    for (int it = 0; it < 200; ++it) {
        double f = -1, df = 0;
        for (int d = 0; d < 3; ++d) {
            if (x[d] == 0) continue;
            const double q = ax[d] / (a2[d] + t);
            f += q * q;
            df -= 2 * q * q / (a2[d] + t);
        }
        if (!(f > 0) || df == 0) break; // at the root, up to round-off
        const double step = -f / df;
        t += step;
        if (step <= 1e-16 * (std::abs(t) + a2.maxCoeff())) break;
    }
    Vec3 y = Vec3::Zero();
    for (int d = 0; d < 3; ++d)
        if (x[d] != 0) y[d] = a2[d] * x[d] / (a2[d] + t);
    return (x - y).norm();
}

} // namespace froth
