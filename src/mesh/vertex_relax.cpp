// Mesh upkeep (transitions.h, relax_flat_corners): a film vertex that has come to lie on the
// segment between two of its neighbours makes a flat cap, a facet with a corner near 180
// degrees. Inside a film an edge flip mends it; where the cap's long side is a triple line
// (a one-edge line that the flow stretched past the film vertex beside it) nothing can be
// flipped, and collapsing the vertex may turn its other facets over. Moving the vertex in its
// tangent plane towards the mean of its neighbours (Evolver's `V` for that vertex alone) opens
// the cap and keeps the film's shape to second order. relax_short_edge_ends moves the film
// vertices of short edges the same way (one beside a line vertex, joined to the line's next
// vertex too, cannot collapse onto it).
#include "mesh/transitions.h"

#include "mesh/transition_surgery.h"

#include <algorithm>
#include <cmath>
#include <set>
#include <vector>

namespace froth {
namespace {

double corner_angle(const std::array<Vec3, 3>& x, int k) {
    const Vec3 u = x[(k + 1) % 3] - x[k], w = x[(k + 2) % 3] - x[k];
    return std::atan2(u.cross(w).norm(), u.dot(w)) * 180.0 / M_PI;
}

/// The flat corners: the film vertex at the largest corner of each facet with a corner below
/// `angle` degrees and one above 90 (a cap, not a needle).
std::vector<int> flat_corners(const Cluster& c, const std::vector<int>& rank, double angle) {
    std::set<int> out;
    for (const Surface& s : c.surfaces())
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const auto x = s.corners(c.positions(), f);
            std::array<double, 3> a{corner_angle(x, 0), corner_angle(x, 1), corner_angle(x, 2)};
            const int top = static_cast<int>(std::max_element(a.begin(), a.end()) - a.begin());
            const int apex = s.triangles[f][top];
            if (*std::min_element(a.begin(), a.end()) < angle && a[top] > 90 && rank[apex] == 0)
                out.insert(apex);
        }
    return {out.begin(), out.end()};
}

/// The film vertices at the ends of edges shorter than min_length.
std::vector<int> short_edge_ends(const Cluster& c, const std::vector<int>& rank, double min_length) {
    std::set<int> out;
    for (const Surface& s : c.surfaces())
        for (std::size_t f = 0; f < s.triangles.size(); ++f) {
            const auto x = s.corners(c.positions(), f);
            for (int k = 0; k < 3; ++k)
                if ((x[(k + 1) % 3] - x[k]).norm() < min_length)
                    for (int v : {s.triangles[f][k], s.triangles[f][(k + 1) % 3]})
                        if (rank[v] == 0) out.insert(v);
        }
    return {out.begin(), out.end()};
}

/// Each of `vertices` (film vertices) in turn moves in its tangent plane to the mean of its
/// neighbours unless a facet at it would turn over or flatten; no two moved vertices are
/// neighbours.
VertexRelaxResult relax_vertices(const Cluster& c, const std::vector<int>& vertices) {
    VertexRelaxResult r;
    if (vertices.empty()) return r;
    // each film vertex's facets: (surface, facet, corner)
    std::vector<std::vector<std::array<int, 3>>> at(c.n_vertices());
    for (int si = 0; si < c.n_surfaces(); ++si) {
        const auto& tris = c.surface(si).triangles;
        for (int f = 0; f < static_cast<int>(tris.size()); ++f)
            for (int k = 0; k < 3; ++k) at[tris[f][k]].push_back({si, f, k});
    }
    std::vector<Vec3> X = c.positions();
    std::vector<char> touched(c.n_vertices(), 0); // moved, or next to a moved vertex
    for (int v : vertices) {
        if (touched[v]) continue;
        // the neighbours' mean and the vertex normal, in v's own frame (facet corners)
        Vec3 mean = Vec3::Zero(), normal = Vec3::Zero();
        for (const auto& [si, f, k] : at[v]) {
            const auto x = c.surface(si).corners(c.positions(), f);
            mean += 0.5 * (x[(k + 1) % 3] + x[(k + 2) % 3] - 2 * x[k]);
            normal += (x[(k + 1) % 3] - x[k]).cross(x[(k + 2) % 3] - x[k]);
        }
        mean /= static_cast<double>(at[v].size());
        if (!(normal.norm() > 0)) continue;
        normal.normalize();
        // the whole way, or where a facet would turn over, half or a quarter of it
        const Vec3 full = mean - mean.dot(normal) * normal;
        Vec3 d = full;
        bool keeps = false;
        for (double part : {1.0, 0.5, 0.25}) {
            d = part * full;
            keeps = true;
            for (const auto& [si, f, k] : at[v]) {
                const auto x = c.surface(si).corners(c.positions(), f);
                std::array<Vec3, 3> y = x;
                y[k] += d;
                keeps = keeps && surgery::keeps_its_side((x[1] - x[0]).cross(x[2] - x[0]), y);
            }
            if (keeps) break;
        }
        if (!keeps) continue;
        X[v] += d;
        ++r.moved;
        for (const auto& [si, f, k] : at[v])
            for (int w : c.surface(si).triangles[f]) touched[w] = 1;
    }
    if (r.moved == 0) return r;
    r.cluster.emplace(c);
    r.cluster->set_positions(std::move(X));
    return r;
}

} // namespace

VertexRelaxResult relax_flat_corners(const Cluster& c, double angle) {
    return relax_vertices(c, flat_corners(c, surgery::vertex_ranks(c), angle));
}

VertexRelaxResult relax_short_edge_ends(const Cluster& c, double min_length) {
    return relax_vertices(c, short_edge_ends(c, surgery::vertex_ranks(c), min_length));
}

} // namespace froth
