#pragma once
/// Clusters from solids combined by gmsh OpenCASCADE booleans (froth.fragment): every solid
/// region becomes a body and every film between two bodies (or a body and the outside) one
/// surface. gmsh stays private to the .cpp.

#include "mesh/cluster.h"

#include <cstddef>
#include <map>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

namespace froth {

enum class SolidKind { ball, box, cylinder, torus };

/// "ball", "box", "cylinder", "torus".
inline const char* solid_kind_name(SolidKind kind) {
    switch (kind) {
    case SolidKind::ball: return "ball";
    case SolidKind::box: return "box";
    case SolidKind::cylinder: return "cylinder";
    case SolidKind::torus: return "torus";
    }
    return "?";
}

/// One input solid. Only the fields of its kind are used. Transformations apply in the order
/// scale, rotate (both about the solid's center), translate.
struct Solid {
    SolidKind kind = SolidKind::ball;
    Vec3 center = Vec3::Zero(); ///< ball, torus
    double r = 1.0;             ///< ball radius, cylinder radius, torus minor (tube) radius
    double R = 2.0;             ///< torus major radius (center to tube center), R > r
    Vec3 min = Vec3::Zero();    ///< box corner
    Vec3 size = Vec3::Ones();   ///< box extents, each > 0
    Vec3 base = Vec3::Zero();   ///< cylinder: center of its first disk
    Vec3 axis = Vec3::UnitZ();  ///< cylinder: axis vector (its length is the height);
                                ///< torus: the direction of its axis of symmetry
    double angle = 2 * std::numbers::pi; ///< ball only: azimuthal opening in (0, 2 pi], the
                                         ///< wedge from azimuth 0 (+x) counterclockwise about
                                         ///< the z axis through the center (before rotate)
    double latitude_lo = -std::numbers::pi / 2; ///< ball only: the latitude band [lo, hi]
    double latitude_hi = std::numbers::pi / 2;  ///< (radians, -pi/2 <= lo < hi <= pi/2) about
                                                ///< the z axis through the center; a band
                                                ///< other than the whole ball is closed by
                                                ///< flat disks (lo = 0: the upper half ball)
    Vec3 translate = Vec3::Zero();
    Vec3 rotate_axis = Vec3::UnitZ();
    double rotate_angle = 0;   ///< radians, right-handed about rotate_axis
    Vec3 scale = Vec3::Ones(); ///< factors along x, y, z, each > 0
    std::optional<double> h;   ///< target edge length on its body's films; none: global h
    std::optional<long long> body; ///< 1-based id of the body its volume goes to (solids
                                   ///< with one id form one body); for all solids or none
};

/// The solid's center: ball/torus center, box center, midpoint of the cylinder's axis.
Vec3 solid_center(const Solid& s);

struct FragmentOptions {
    std::vector<Solid> solids;
    std::optional<double> h;           ///< global target edge length; none: about default_vertices
    double sigma = 1.0;                ///< tension of every surface not in sigma_of
    std::map<int, double> sigma_of;    ///< 0-based surface id -> tension
    std::size_t max_vertices = 400000; ///< refuse meshes estimated larger than this
    std::size_t default_vertices = 5000;
    std::string op = "fragment"; ///< message prefix
};

/// Builds the solids in gmsh, fragments them and meshes the films.
///  - Solid k gets its volume minus that of the solids before it (a later solid never takes
///    volume from an earlier one) and gives it to body k, or to body `body` when the solids
///    carry body ids (then the solids of one id form one body: a union). Overlapping solids
///    thus give one body each, and the order of the solids says who owns an overlap.
///  - Surfaces: one per connected film separating the same pair of regions (body ids, 0 = the
///    outside, including enclosed cavities), ordered by that pair (lower id first), ties by the
///    film's bounding box center compared z, then y, then x. gmsh surfaces split by seams or by
///    the interfaces between the parts of one body are merged and oriented consistently.
///  - A body's surfaces are the films with its id.
/// \throw InvalidInput for bad solids or options (naming "solids[k] (kind)", 1-based), body
/// ids given for some solids only or not numbering the bodies 1..n, a solid that lies inside
/// earlier ones, a disconnected cluster, an h too small (estimated vertices above
/// max_vertices) or larger than the cluster; GeometryError if gmsh fails; TopologyError if a
/// film cannot be oriented.
ClusterSpec build_fragment(const FragmentOptions& options);

} // namespace froth
