// The mean width of each body and the length of its triple lines (geometry.h, grain_measures):
// what the MacPherson-Srolovitz law of grain growth is written in.
//
// For a body D bounded by films meeting at triple lines, with kappa = kappa_1 + kappa_2 and
// alpha the exterior dihedral angle along a line (pi minus the angle inside D),
//
//     L(D) = (1 / 2 pi) ( int_{dD} kappa dA + sum_lines int alpha ds ),
//
// twice the classical mean breadth (a ball of radius R: 4 R), the normalisation in which
// MacPherson and Srolovitz (Nature 446, 2007) write, for a normal velocity kappa (froth's MCF,
// sigma = mobility = 1) and lines where three films meet at 120 degrees (alpha = pi / 3):
//
//     dV/dt = - int_{dD} kappa dA = -2 pi ( L(D) - (1/6) sum_i e_i ).
//
// On a triangulated boundary L is Steiner's edge sum (1 / 2 pi) sum_e |e| alpha_e over every
// mesh edge, alpha_e the signed angle between the outward normals of the body's two facets at
// e (positive where the boundary is convex): at film edges the discrete curvature, at line
// edges the body's actual angle there. So dV/dt + 2 pi (L - sum e / 6) measures how far the
// flow is from the law: the time and curvature discretisation and the lines' angles.
#include "geometry/geometry.h"

#include <array>
#include <cmath>
#include <map>
#include <set>
#include <utility>

namespace froth {
namespace {

/// One side of a mesh edge as a body's boundary sees it: the outward unit normal of the facet
/// there and the edge vector in that facet's outward order.
struct EdgeSide {
    Vec3 normal;
    Vec3 along;
};

double exterior_angle(const EdgeSide& first, const EdgeSide& second) {
    const Vec3 cross = first.normal.cross(second.normal);
    const double angle = std::atan2(cross.norm(), first.normal.dot(second.normal));
    return cross.dot(first.along) >= 0 ? angle : -angle;
}

} // namespace

std::vector<GrainMeasures> grain_measures(const Cluster& c) {
    const std::vector<Vec3>& X = c.positions();
    std::set<std::pair<int, int>> junction;
    for (const JunctionEdge& e : c.junction_edges()) junction.insert(std::minmax(e.a, e.b));
    const Eigen::Matrix3d to_lattice =
        c.periodic() ? Eigen::Matrix3d(c.period().inverse()) : Eigen::Matrix3d::Zero();
    // An edge where a body sees it: its vertices sorted and, in a periodic cluster, the lattice
    // cell of the first one in the unwrapped body (a cell may meet an edge and its image).
    using EdgeKey = std::array<long, 5>;
    const auto key_of = [&](int u, int w, const Vec3& at_u, const Vec3& at_w) {
        const bool u_first = u < w;
        const Vec3 k = to_lattice * ((u_first ? at_u : at_w) - X[u_first ? u : w]);
        return EdgeKey{std::min(u, w), std::max(u, w), std::lround(k.x()), std::lround(k.y()),
                       std::lround(k.z())};
    };
    const std::vector<double> V = body_volumes(c);
    std::vector<GrainMeasures> out(c.n_bodies());
    for (int b = 0; b < c.n_bodies(); ++b) {
        GrainMeasures& g = out[b];
        g.volume = V[b];
        std::map<EdgeKey, std::vector<EdgeSide>> sides; // the body's facets at each edge
        for (const BodyFace& face : c.bodies()[b].faces) {
            const Surface& s = c.surface(face.surface);
            for (std::size_t f = 0; f < s.triangles.size(); ++f) {
                auto x = s.corners(X, f);
                if (!face.shift.empty())
                    for (Vec3& p : x) p += face.shift[f];
                const Vec3 area = 0.5 * (x[1] - x[0]).cross(x[2] - x[0]);
                g.area += area.norm();
                const Vec3 normal = face.sign * area.normalized();
                for (int k = 0; k < 3; ++k) {
                    const int u = s.triangles[f][k], w = s.triangles[f][(k + 1) % 3];
                    sides[key_of(u, w, x[k], x[(k + 1) % 3])].push_back(
                        {normal, face.sign * (x[(k + 1) % 3] - x[k])});
                }
            }
        }
        double steiner = 0;
        for (const auto& [key, at] : sides) {
            if (at.size() != 2) continue; // an edge on a wall's lid
            const double length = at[0].along.norm();
            steiner += length * exterior_angle(at[0], at[1]);
            if (junction.count({static_cast<int>(key[0]), static_cast<int>(key[1])}))
                g.line_length += length;
        }
        g.mean_width = steiner / (2 * M_PI);
    }
    return out;
}

} // namespace froth
