#include "anisotropy/mobility.h"

#include "core/errors.h"
#include "core/format.h"

#include <cmath>

namespace froth {

namespace {
// beta scales the SD system's kappa block against its position block: far outside this range
// the factorisation meets entries 1e200 apart and reports a singular matrix, which would not
// say why. Within it, tau absorbs any time unit.
constexpr double kMinBeta = 1e-100, kMaxBeta = 1e100;
bool in_range(double b) { return std::isfinite(b) && b >= kMinBeta && b <= kMaxBeta; }
} // namespace

Mobility Mobility::constant(double value) {
    if (!(std::isfinite(value) && value > 0))
        throw InvalidInput("set_mobility: beta must be a finite number > 0 (got " + fmt(value) +
                           ")");
    if (!in_range(value))
        throw InvalidInput("set_mobility: beta must be between 1e-100 and 1e100 (got " +
                           fmt(value) + "); scale tau instead");
    Mobility m;
    m.value_ = value;
    return m;
}

Mobility Mobility::energy_density() {
    Mobility m;
    m.kind_ = Kind::EnergyDensity;
    return m;
}

Mobility Mobility::function(Fn fn, std::string name) {
    if (!fn) throw InvalidInput("mobility: no function given");
    Mobility m;
    m.kind_ = Kind::Function;
    m.fn_ = std::move(fn);
    m.name_ = std::move(name);
    return m;
}

std::string Mobility::describe() const {
    switch (kind_) {
    case Kind::Constant: return fmt(value_);
    case Kind::EnergyDensity: return "gamma";
    case Kind::Function: return name_;
    }
    return {};
}

double Mobility::operator()(const Eigen::Vector3d& nu, double sigma, const Anisotropy* gamma,
                            const std::string& where) const {
    double b = value_;
    if (kind_ == Kind::EnergyDensity) b = sigma * (gamma ? gamma->gamma(nu) : nu.norm());
    if (kind_ == Kind::Function) {
        try {
            b = fn_(nu);
        } catch (const InvalidInput& e) { // name the surface too
            throw InvalidInput(where + ": " + e.what());
        }
    }
    if (!(std::isfinite(b) && b > 0))
        throw InvalidInput(where + ": the mobility " + describe() + " is " + fmt(b) +
                           " at the normal (" + fmt(nu[0]) + ", " + fmt(nu[1]) + ", " +
                           fmt(nu[2]) + "); it must be finite and positive");
    if (!in_range(b))
        throw InvalidInput(where + ": the mobility " + describe() + " is " + fmt(b) +
                           " at the normal (" + fmt(nu[0]) + ", " + fmt(nu[1]) + ", " +
                           fmt(nu[2]) + "); it must be between 1e-100 and 1e100");
    return b;
}

} // namespace froth
