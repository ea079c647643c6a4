#pragma once
/// The kinetic coefficients beta_i of (1.19)/(1.20): the mobility of each surface, entering the
/// schemes through <beta(nu^m) kappa_gamma, chi>^h in (3.7a)/(3.10a) and
/// <beta(nu^m) grad_s kappa_gamma, grad_s chi> in (3.8a)/(3.11a). Constant (1 by default), the
/// surface's own energy density (beta = gamma, which the exact solution (5.4)/(5.5) needs), or a
/// user function of the unit normal.

#include "anisotropy/anisotropy.h"

#include <functional>
#include <string>

namespace froth {

class Mobility {
  public:
    enum class Kind { Constant, EnergyDensity, Function };
    using Fn = std::function<double(const Eigen::Vector3d&)>;

    /// beta = 1.
    Mobility() = default;
    /// \throw InvalidInput unless value is finite and positive.
    static Mobility constant(double value);
    /// beta(nu) = sigma gamma(nu): the surface's energy density.
    static Mobility energy_density();
    /// beta(nu) = fn(nu) for unit nu; `name` says where fn came from (for messages).
    static Mobility function(Fn fn, std::string name);

    Kind kind() const { return kind_; }
    /// True for the constant 1, which leaves the isotropic systems unchanged.
    bool is_unit() const { return kind_ == Kind::Constant && value_ == 1.0; }
    double constant_value() const { return value_; }
    /// "1", "0.5", "gamma" or the function's name.
    std::string describe() const;

    /// beta at the unit normal nu of a surface whose density is sigma gamma (gamma null:
    /// isotropic). \throw InvalidInput naming `where` when the value is not finite and positive
    /// or a user function fails (its message prefixed by `where`).
    double operator()(const Eigen::Vector3d& nu, double sigma, const Anisotropy* gamma,
                      const std::string& where) const;

  private:
    Kind kind_ = Kind::Constant;
    double value_ = 1.0;
    Fn fn_;
    std::string name_;
};

} // namespace froth
