#pragma once
// Small clusters built in code for the unit tests: no gmsh, exact combinatorics.

#include "mesh/cluster.h"

#include <cmath>
#include <map>

namespace froth::test {

/// Icosphere of radius R: the icosahedron subdivided `levels` times, projected to the sphere.
/// One surface, one body, outward orientation.
inline ClusterSpec icosphere(int levels, double R = 1.0) {
    const double p = (1.0 + std::sqrt(5.0)) / 2.0;
    ClusterSpec s;
    s.vertices = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0}, {0, -1, p}, {0, 1, p},
                  {0, -1, -p}, {0, 1, -p}, {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
    std::vector<Tri> f = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                          {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                          {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                          {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int l = 0; l < levels; ++l) {
        std::map<std::pair<int, int>, int> mid;
        auto midpoint = [&](int a, int b) {
            auto key = std::minmax(a, b);
            auto it = mid.find(key);
            if (it != mid.end()) return it->second;
            s.vertices.push_back(0.5 * (s.vertices[a] + s.vertices[b]));
            return mid[key] = static_cast<int>(s.vertices.size()) - 1;
        };
        std::vector<Tri> g;
        for (const Tri& t : f) {
            const int a = midpoint(t[0], t[1]), b = midpoint(t[1], t[2]), c = midpoint(t[2], t[0]);
            g.insert(g.end(), {Tri{t[0], a, c}, Tri{t[1], b, a}, Tri{t[2], c, b}, Tri{a, b, c}});
        }
        f = std::move(g);
    }
    for (Vec3& x : s.vertices) x = R * x.normalized();
    s.surfaces.push_back({f, 1.0});
    s.bodies = {{0}};
    return s;
}

/// Two tetrahedra glued along a face, as a three-surface cluster: the shared triangle is
/// surface 3, each tetrahedron's other three faces are surfaces 1 and 2. The edges of the
/// shared triangle are triple-junction edges (a closed triple line of three edges).
inline ClusterSpec twin_tetrahedra() {
    ClusterSpec s;
    s.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.3, 0.3, 1}, {0.3, 0.3, -1}};
    s.surfaces.push_back({{{0, 1, 3}, {1, 2, 3}, {2, 0, 3}}, 1.0});  // upper tetrahedron
    s.surfaces.push_back({{{1, 0, 4}, {2, 1, 4}, {0, 2, 4}}, 1.0});  // lower tetrahedron
    s.surfaces.push_back({{{0, 2, 1}}, 1.0});                       // the shared wall
    s.bodies = {{0, 2}, {1, 2}};
    return s;
}

} // namespace froth::test
