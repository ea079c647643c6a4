// Without CGAL there are no Voronoi foams (voronoi.h).
#include "foams/voronoi.h"

#include "core/errors.h"

namespace froth {

std::vector<VoronoiFace> periodic_voronoi(const std::vector<Vec3>&, const Eigen::Matrix3d&) {
    throw InvalidInput("foam: froth was built without CGAL, which computes the Voronoi diagram");
}

bool voronoi_available() { return false; }

} // namespace froth
