#pragma once
/// The value types every module shares: a point or vector of R^3 and a triangle's vertex ids.

#include <Eigen/Core>

#include <array>
#include <string>
#include <vector>

namespace froth {

using Vec3 = Eigen::Vector3d;
using Tri = std::array<int, 3>; ///< vertex ids, 0-based, in the facet's orientation

/// A named array of numbers: the schemes' history as a state file keeps it (io/state_file.h).
struct NamedValues {
    std::string name;
    std::vector<double> values;
};

/// The values of the array called `name` in `arrays`, or null if there is none.
inline const std::vector<double>* find_named(const std::vector<NamedValues>& arrays,
                                             const char* name) {
    for (const NamedValues& a : arrays)
        if (a.name == name) return &a.values;
    return nullptr;
}

} // namespace froth
