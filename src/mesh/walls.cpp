#include "mesh/walls.h"

#include "core/errors.h"
#include "core/format.h"

#include <algorithm>
#include <cmath>
#include <iterator>

namespace froth {
namespace {

Vec3 unit_vector(const Vec3& v, const std::string& who, const char* what) {
    const double n = v.norm();
    if (!(std::isfinite(n) && n > 0))
        throw InvalidInput(who + ": " + what + " must be a finite non-zero vector, got " +
                           point_text(v));
    return v / n;
}

void require_finite(double value, const std::string& who, const char* what) {
    if (!std::isfinite(value))
        throw InvalidInput(who + ": " + what + " must be finite, got " + fmt(value));
}

class PlaneWall final : public Wall {
  public:
    PlaneWall(const Vec3& n, double d) : n_(n), d_(d) {}
    double value(const Vec3& x) const override { return n_.dot(x) - d_; }
    Vec3 gradient(const Vec3&) const override { return n_; }
    std::string describe() const override {
        return "plane " + point_text(n_) + " . x = " + fmt(d_);
    }
    WallParameters parameters() const override { return {"plane", {n_[0], n_[1], n_[2], d_}, {}}; }
    bool is_flat() const override { return true; }

  private:
    Vec3 n_;
    double d_;
};

class SlabWall final : public Wall {
  public:
    SlabWall(const Vec3& n, double lo, double hi) : n_(n), lo_(lo), hi_(hi) {}
    double value(const Vec3& x) const override {
        return 0.5 * (hi_ - lo_) - std::abs(n_.dot(x) - 0.5 * (lo_ + hi_));
    }
    Vec3 gradient(const Vec3& x) const override {
        return n_.dot(x) > 0.5 * (lo_ + hi_) ? Vec3(-n_) : n_;
    }
    std::string describe() const override {
        return "slab " + fmt(lo_) + " <= " + point_text(n_) + " . x <= " + fmt(hi_);
    }
    WallParameters parameters() const override {
        return {"slab", {n_[0], n_[1], n_[2], lo_, hi_}, {}};
    }
    bool is_flat() const override { return true; }

  private:
    Vec3 n_;
    double lo_, hi_;
};

class SphereWall final : public Wall {
  public:
    SphereWall(const Vec3& c, double r) : c_(c), r_(r) {}
    double value(const Vec3& x) const override { return (x - c_).norm() - r_; }
    Vec3 gradient(const Vec3& x) const override { return (x - c_).normalized(); }
    std::string describe() const override {
        return "sphere |x - " + point_text(c_) + "| = " + fmt(r_);
    }
    WallParameters parameters() const override { return {"sphere", {c_[0], c_[1], c_[2], r_}, {}}; }

    /// The radial projection of the triangle onto the sphere, c . S + R^3 Omega: with x = c + R n
    /// on the sphere, x . n = c . n + R. S is the flat triangle's vector area (the arcs differ
    /// from its sides by O(h^3)), Omega its signed solid angle seen from c (Van Oosterom and
    /// Strackee), positive when the triangle faces away from c.
    double fan_flux(const Vec3& apex, const Vec3& a, const Vec3& b) const override {
        const Vec3 u1 = apex - c_, u2 = b - c_, u3 = a - c_;
        const double l1 = u1.norm(), l2 = u2.norm(), l3 = u3.norm();
        const double omega = 2 * std::atan2(u1.dot(u2.cross(u3)),
                                            l1 * l2 * l3 + u1.dot(u2) * l3 + u1.dot(u3) * l2 +
                                                u2.dot(u3) * l1);
        const Vec3 S = 0.5 * (b - apex).cross(a - apex);
        return c_.dot(S) + r_ * r_ * r_ * omega;
    }

  private:
    Vec3 c_;
    double r_;
};

class CylinderWall final : public Wall {
  public:
    CylinderWall(const Vec3& p, const Vec3& a, double r) : p_(p), a_(a), r_(r) {}
    double value(const Vec3& x) const override { return radial(x).norm() - r_; }
    Vec3 gradient(const Vec3& x) const override { return radial(x).normalized(); }
    std::string describe() const override {
        return "cylinder of radius " + fmt(r_) + " about " + point_text(p_) + " + s " +
               point_text(a_);
    }
    WallParameters parameters() const override {
        return {"cylinder", {p_[0], p_[1], p_[2], a_[0], a_[1], a_[2], r_}, {}};
    }

    /// The patch of the cylinder that the triangle spans when the cylinder is unrolled (the
    /// triangle straight in (theta, s)), p . S + R A: with x = p + s a + R n on the cylinder,
    /// x . n = p . n + R. S is the flat triangle's vector area (as for the sphere, the patch's
    /// differs by O(h^3)), A the patch's signed area, R times the triangle's signed area in
    /// (theta, s), positive when the triangle faces away from the axis. A fan of such patches
    /// is the lid on the wall itself, so the lid's volume follows the rim as the films do (a
    /// flat fan under the curved wall let the volume-exact step push the films by the change
    /// of the bulge it leaves out, raising the energy by ~1e-5 a step, tests/regression).
    double fan_flux(const Vec3& apex, const Vec3& a, const Vec3& b) const override {
        const Vec3 e1 = a_.unitOrthogonal(), e2 = a_.cross(e1); // (e1, e2, a) right-handed
        const auto theta = [&](const Vec3& x) {
            const Vec3 d = x - p_;
            return std::atan2(d.dot(e2), d.dot(e1));
        };
        const double t0 = theta(apex);
        const double ta = std::remainder(theta(a) - t0, 2 * M_PI);
        const double tb = std::remainder(theta(b) - t0, 2 * M_PI);
        const double s0 = apex.dot(a_), sa = a.dot(a_) - s0, sb = b.dot(a_) - s0;
        const double A = 0.5 * r_ * (tb * sa - ta * sb);
        const Vec3 S = 0.5 * (b - apex).cross(a - apex);
        return p_.dot(S) + r_ * A;
    }

  private:
    Vec3 radial(const Vec3& x) const {
        const Vec3 d = x - p_;
        return d - d.dot(a_) * a_;
    }
    Vec3 p_, a_;
    double r_;
};

class FunctionWall final : public Wall {
  public:
    FunctionWall(std::function<double(const Vec3&)> F, std::function<Vec3(const Vec3&)> g,
                 std::string name, double step)
        : F_(std::move(F)), g_(std::move(g)), name_(std::move(name)), step_(step) {}
    double value(const Vec3& x) const override {
        const double f = F_(x);
        if (!std::isfinite(f))
            throw GeometryError("wall '" + name_ + "': F is " + fmt(f) + " at " + point_text(x));
        return f;
    }
    Vec3 gradient(const Vec3& x) const override {
        Vec3 g;
        if (g_) {
            g = g_(x);
        } else {
            for (int d = 0; d < 3; ++d) {
                Vec3 e = Vec3::Zero();
                e[d] = step_;
                g[d] = (value(x + e) - value(x - e)) / (2 * step_);
            }
        }
        if (!g.allFinite())
            throw GeometryError("wall '" + name_ + "': grad F is " + point_text(g) + " at " +
                                point_text(x));
        return g;
    }
    std::string describe() const override { return "wall '" + name_ + "'"; }
    WallParameters parameters() const override { return {"function", {step_}, name_}; }

  private:
    std::function<double(const Vec3&)> F_;
    std::function<Vec3(const Vec3&)> g_;
    std::string name_;
    double step_;
};

} // namespace

double Wall::fan_flux(const Vec3& apex, const Vec3& a, const Vec3& b) const {
    return 0.5 * apex.dot(b.cross(a));
}

double Wall::distance(const Vec3& x) const {
    const double f = value(x);
    if (f == 0) return 0;
    return std::abs(f) / gradient(x).norm();
}

Vec3 Wall::normal(const Vec3& x) const {
    const Vec3 g = gradient(x);
    const double n = g.norm();
    if (!(n > 0))
        throw GeometryError(describe() + ": grad F vanishes at " + point_text(x) +
                            "; the wall has no tangent plane there");
    return g / n;
}

Vec3 Wall::project(const Vec3& x0) const {
    Vec3 x = x0;
    for (int it = 0; it < 50; ++it) {
        const double f = value(x);
        const Vec3 g = gradient(x);
        const double g2 = g.squaredNorm();
        if (!(g2 > 0)) break;
        const Vec3 dx = f / g2 * g;
        x -= dx;
        if (dx.norm() <= 1e-14 * (1 + x.norm())) return x;
    }
    if (distance(x) <= 1e-12 * (1 + x.norm())) return x;
    throw GeometryError(describe() + ": cannot project " + point_text(x0) +
                        " onto the wall (Newton's method did not converge)");
}

WallPtr make_plane(const Vec3& normal, double offset) {
    require_finite(offset, "plane", "offset");
    return std::make_shared<PlaneWall>(unit_vector(normal, "plane", "normal"), offset);
}

WallPtr make_slab(const Vec3& normal, double lo, double hi) {
    require_finite(lo, "slab", "lower offset");
    require_finite(hi, "slab", "upper offset");
    if (!(lo < hi))
        throw InvalidInput("slab: the lower offset " + fmt(lo) + " must be below the upper " +
                           fmt(hi));
    return std::make_shared<SlabWall>(unit_vector(normal, "slab", "normal"), lo, hi);
}

WallPtr make_sphere_wall(const Vec3& center, double radius) {
    if (!center.allFinite()) throw InvalidInput("sphere_wall: center must be finite");
    if (!(std::isfinite(radius) && radius > 0))
        throw InvalidInput("sphere_wall: radius must be positive, got " + fmt(radius));
    return std::make_shared<SphereWall>(center, radius);
}

WallPtr make_cylinder_wall(const Vec3& point, const Vec3& axis, double radius) {
    if (!point.allFinite()) throw InvalidInput("cylinder_wall: point must be finite");
    if (!(std::isfinite(radius) && radius > 0))
        throw InvalidInput("cylinder_wall: radius must be positive, got " + fmt(radius));
    return std::make_shared<CylinderWall>(point, unit_vector(axis, "cylinder_wall", "axis"),
                                          radius);
}

WallPtr make_function_wall(std::function<double(const Vec3&)> F,
                           std::function<Vec3(const Vec3&)> gradient, std::string name,
                           double fd_step) {
    if (!F) throw InvalidInput("wall: F is required");
    if (!(std::isfinite(fd_step) && fd_step > 0))
        throw InvalidInput("wall: the finite-difference step must be positive, got " +
                           fmt(fd_step));
    return std::make_shared<FunctionWall>(std::move(F), std::move(gradient), std::move(name),
                                          fd_step);
}

namespace {

/// The unit vector v as saved: checked, not normalised again (that could change its last bit).
Vec3 saved_unit_vector(const Vec3& v, const std::string& kind) {
    if (!(std::abs(v.norm() - 1) <= 1e-12))
        throw InvalidInput("wall: a saved " + kind + "'s normal or axis " + point_text(v) +
                           " is not a unit vector");
    return v;
}

} // namespace

WallPtr wall_from_parameters(const WallParameters& p) {
    static const std::pair<const char*, std::size_t> counts[] = {
        {"plane", 4}, {"slab", 5}, {"sphere", 4}, {"cylinder", 7}};
    const auto known = std::find_if(std::begin(counts), std::end(counts),
                                    [&](const auto& k) { return p.kind == k.first; });
    if (known == std::end(counts))
        throw InvalidInput("wall: '" + p.kind + "' is not a preset wall kind (plane, slab, " +
                           "sphere, cylinder)");
    if (p.values.size() != known->second)
        throw InvalidInput("wall: a " + p.kind + " takes " + std::to_string(known->second) +
                           " numbers, got " + std::to_string(p.values.size()));
    for (double v : p.values) require_finite(v, "wall", "every number of a saved wall");
    const auto& v = p.values;
    const Vec3 a(v[0], v[1], v[2]);
    if (p.kind == "plane") return std::make_shared<PlaneWall>(saved_unit_vector(a, p.kind), v[3]);
    if (p.kind == "slab") {
        if (!(v[3] < v[4])) throw InvalidInput("wall: a saved slab has lo >= hi");
        return std::make_shared<SlabWall>(saved_unit_vector(a, p.kind), v[3], v[4]);
    }
    const double r = v.back();
    if (!(r > 0)) throw InvalidInput("wall: a saved " + p.kind + " has radius " + fmt(r));
    if (p.kind == "sphere") return std::make_shared<SphereWall>(a, r);
    return std::make_shared<CylinderWall>(a, saved_unit_vector(Vec3(v[3], v[4], v[5]), p.kind), r);
}

std::string point_text(const Vec3& x) {
    std::string text = "("; // appended, not "(" + ...: GCC 12 warns falsely (-Wrestrict) there
    text += fmt(x.x());
    text += ", ";
    text += fmt(x.y());
    text += ", ";
    text += fmt(x.z());
    return text + ")";
}

} // namespace froth
