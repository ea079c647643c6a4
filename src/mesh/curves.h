#pragma once
/// Wire curves: a parametric curve x(p) that fixed vertices of a wire lie on (Surface
/// Evolver's `boundary N parameters 1` with fixed vertices). The vertices stay where they are;
/// what the curve adds is refinement: refine (cluster.h) puts the midpoint of a wire edge
/// between two vertices on one curve onto the curve, so a refined ring stays a circle instead
/// of keeping the chords of its first polygon.

#include "core/types.h"

#include <functional>
#include <memory>
#include <string>

namespace froth {

class Curve {
  public:
    /// x may throw (the bindings' Lua errors); `name` says where it came from.
    Curve(std::function<Vec3(double)> x, std::string name);
    /// x(p). \throw GeometryError naming the curve if it is not finite.
    Vec3 point(double p) const;
    const std::string& name() const { return name_; }
    /// The parameter of the point of the curve nearest to x, by Newton's method on
    /// |x(p) - x|^2 from p0 (finite-difference derivatives): the local minimiser, so p0 decides
    /// which way round a closed curve it goes.
    double nearest(const Vec3& x, double p0) const;

  private:
    std::function<Vec3(double)> x_;
    std::string name_;
};

using CurvePtr = std::shared_ptr<const Curve>;

/// A vertex on a curve at parameter p (ids 0-based into the cluster's vertices and curves).
struct CurvePoint {
    int vertex;
    int curve;
    double p;
};

/// The parameter of the midpoint of the curve between points a and b: of the average of
/// their parameters and the nearest points to the chord's midpoint seen from either end, the
/// one closest to that midpoint (so an edge across the seam of a closed curve, from 5 pi / 3
/// to 0, gets 11 pi / 6 and not 5 pi / 6).
double curve_midpoint(const Curve& curve, const CurvePoint& a, const CurvePoint& b, const Vec3& xa,
                      const Vec3& xb);

} // namespace froth
