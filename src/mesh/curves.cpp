#include "mesh/curves.h"

#include "core/errors.h"
#include "core/format.h"

#include <cmath>

namespace froth {

Curve::Curve(std::function<Vec3(double)> x, std::string name)
    : x_(std::move(x)), name_(std::move(name)) {
    if (!x_) throw InvalidInput("curve '" + name_ + "': x is required");
}

Vec3 Curve::point(double p) const {
    const Vec3 x = x_(p);
    if (!x.allFinite())
        throw GeometryError("curve '" + name_ + "': x(" + fmt(p) + ") is not finite");
    return x;
}

double Curve::nearest(const Vec3& x, double p0) const {
    double p = p0;
    for (int it = 0; it < 40; ++it) {
        const double h = 1e-5 * (1 + std::abs(p));
        const Vec3 c = point(p), cp = point(p + h), cm = point(p - h);
        const Vec3 d1 = (cp - cm) / (2 * h), d2 = (cp - 2 * c + cm) / (h * h);
        const double g = (c - x).dot(d1), H = d1.squaredNorm() + (c - x).dot(d2);
        if (!(d1.squaredNorm() > 0)) break;
        // Newton where the distance is convex along the curve, else a gradient step.
        const double dp = -g / (H > 0 ? H : d1.squaredNorm());
        p += dp;
        if (std::abs(dp) <= 1e-13 * (1 + std::abs(p))) break;
    }
    return p;
}

double curve_midpoint(const Curve& curve, const CurvePoint& a, const CurvePoint& b, const Vec3& xa,
                      const Vec3& xb) {
    const Vec3 m = 0.5 * (xa + xb);
    const double candidates[] = {0.5 * (a.p + b.p), curve.nearest(m, a.p), curve.nearest(m, b.p)};
    double best = candidates[0], best_distance = INFINITY;
    for (double p : candidates) {
        const double d = (curve.point(p) - m).norm();
        if (d < best_distance) best = p, best_distance = d;
    }
    return best;
}

} // namespace froth
