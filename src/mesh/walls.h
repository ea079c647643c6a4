#pragma once
/// External boundaries dD = {F = 0} (seed §3, before (3.10)): the walls that parts of the
/// surface boundaries are attached to. The seed asks |grad F| = 1 on the wall; froth only needs
/// grad F != 0 there and normalises (the tangent plane and the first-order distance
/// F / |grad F| do not depend on the scaling), so a user's F need not be a distance.

#include "core/types.h"

#include <Eigen/Core>
#include <Eigen/Geometry> // cross products

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace froth {

/// What a wall is made of, for saving and restoring it exactly (io/state_file.h): a preset's
/// kind and the numbers it holds (already normalised: restoring does not normalise again, so
/// the restored wall is bit for bit the saved one), or kind "function" with the wall's name and
/// finite-difference step (a user function cannot be saved; it is given again by name).
struct WallParameters {
    std::string kind; ///< "plane", "slab", "sphere", "cylinder" or "function"
    std::vector<double> values;
    std::string name; ///< kind "function" only
};

class Wall {
  public:
    virtual ~Wall() = default;
    /// F(x); zero on the wall.
    virtual double value(const Vec3& x) const = 0;
    /// grad F(x).
    virtual Vec3 gradient(const Vec3& x) const = 0;
    /// A short description, e.g. "plane 0 0 1 . x = 0".
    virtual std::string describe() const = 0;
    /// The kind and numbers that wall_from_parameters restores this wall from.
    virtual WallParameters parameters() const = 0;
    /// True when the wall is a union of planes: then a fan from a point on the wall closes a
    /// body's lid exactly (volumes) and the linearised constraint keeps vertices on it exactly.
    virtual bool is_flat() const { return false; }
    /// The flux integral of x . nu over the patch of the wall that the triangle (apex, b, a)
    /// spans, nu oriented like the triangle: 3 times the volume it adds to a body whose lid it is
    /// (seed (1.25); numerics.md §1). The default is the flat triangle's own flux, exact on
    /// planes; curved walls may do better.
    virtual double fan_flux(const Vec3& apex, const Vec3& a, const Vec3& b) const;

    /// The first-order distance |F| / |grad F| (exact for the presets).
    double distance(const Vec3& x) const;
    /// The unit normal grad F / |grad F| at x. \throw GeometryError if grad F vanishes.
    Vec3 normal(const Vec3& x) const;
    /// x moved onto the wall along grad F by Newton steps (for lid centers and the optional
    /// projection of evolve); \throw GeometryError if that does not converge.
    Vec3 project(const Vec3& x) const;
};

using WallPtr = std::shared_ptr<const Wall>;

/// The plane normal . x = offset (normal normalised).
/// \throw InvalidInput for a zero or non-finite normal or a non-finite offset.
WallPtr make_plane(const Vec3& normal, double offset);
/// The two planes normal . x = lo and normal . x = hi, lo < hi, as one wall:
/// F = (hi - lo) / 2 - |normal . x - (lo + hi) / 2|, F >= 0 inside the slab.
WallPtr make_slab(const Vec3& normal, double lo, double hi);
/// The sphere |x - center| = radius, F = |x - center| - radius.
WallPtr make_sphere_wall(const Vec3& center, double radius);
/// The cylinder at distance radius from the line point + s axis.
WallPtr make_cylinder_wall(const Vec3& point, const Vec3& axis, double radius);
/// A wall from user functions. Without a gradient function the gradient is taken by central
/// differences with step `fd_step`. Both functions may throw (the bindings' Lua errors).
WallPtr make_function_wall(std::function<double(const Vec3&)> F,
                           std::function<Vec3(const Vec3&)> gradient, std::string name,
                           double fd_step = 1e-6);

/// The preset wall of saved parameters (plane: n, d; slab: n, lo, hi; sphere: c, r; cylinder:
/// p, a, r), with the numbers as they are. \throw InvalidInput for kind "function" (the
/// caller supplies those), an unknown kind, a wrong count, non-finite values, a normal or axis
/// that is not of unit length within 1e-12, lo >= hi or a radius that is not positive.
WallPtr wall_from_parameters(const WallParameters& p);
/// "(x, y, z)" with %.6g numbers, for wall descriptions and error messages.
std::string point_text(const Vec3& x);

} // namespace froth
