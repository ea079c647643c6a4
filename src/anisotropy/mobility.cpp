#include "anisotropy/mobility.h"

#include "core/errors.h"
#include "core/format.h"

#include <cmath>

namespace froth {

Mobility Mobility::constant(double value) {
    if (!(std::isfinite(value) && value > 0))
        throw InvalidInput("set_mobility: beta must be a finite number > 0 (got " + fmt(value) +
                           ")");
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
    return b;
}

} // namespace froth
