// Shared steps of the topological transitions (transition_surgery.h).
#include "mesh/transition_surgery.h"

#include "core/errors.h"

#include <Eigen/LU>

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

namespace froth::surgery {

std::vector<int> keep_used_vertices(ClusterSpec& spec, const std::vector<Vec3>& V) {
    std::vector<int> used(V.size(), -1);
    for (const auto& s : spec.surfaces)
        for (const Tri& t : s.triangles)
            for (int v : t) used[v] = 0;
    int count = 0;
    spec.vertices.clear();
    for (std::size_t v = 0; v < V.size(); ++v)
        if (used[v] == 0) used[v] = count++, spec.vertices.push_back(V[v]);
    for (auto& s : spec.surfaces)
        for (Tri& t : s.triangles)
            for (int& v : t) v = used[v];
    return used;
}

void copy_vertex_lists(const Cluster& c, const std::function<int(int)>& map, ClusterSpec& spec) {
    spec.walls = c.walls();
    spec.attachments.clear();
    for (const auto& [v, wall] : c.wall_attachments()) spec.attachments.push_back({map(v), wall});
    spec.fixed.clear();
    for (int v : c.fixed_vertices()) spec.fixed.push_back(map(v));
    spec.curves = c.curves();
    spec.curve_points.clear();
    for (CurvePoint cp : c.curve_points()) {
        cp.vertex = map(cp.vertex);
        spec.curve_points.push_back(cp);
    }
}

Cluster rebuild(ClusterSpec spec, const std::string& what, const std::string& surgery) {
    std::optional<Cluster> r;
    try {
        r.emplace(std::move(spec));
    } catch (const Error& e) {
        throw TopologyError(what + ": the cluster after " + surgery + " is not valid: " + e.what());
    }
    return std::move(*r);
}

void check_one_fan(const std::vector<std::pair<int, int>>& link, int surface,
                   const std::string& what) {
    if (link.empty()) return;
    const std::string name = "surface " + std::to_string(surface + 1);
    std::map<int, int> next, in;
    for (const auto& [x, y] : link) {
        if (!next.emplace(x, y).second || ++in[y] > 1)
            throw TopologyError(what + ": it would fold " + name + " over the point; refine "
                                "the mesh around it first");
    }
    int start = link.front().first; // a path starts where nothing comes in; a cycle anywhere
    for (const auto& [x, y] : link)
        if (!in.count(x)) start = x;
    std::size_t walked = 0;
    for (int v = start; next.count(v) && walked < link.size();) {
        v = next[v];
        ++walked;
        if (v == start) break; // round a closed fan
    }
    if (walked != link.size())
        throw TopologyError(what + ": it would pinch " + name + " at the point (its facets "
                            "there would form more than one fan); refine the mesh around it "
                            "first");
}

bool keeps_its_side(const Vec3& old_area, const std::array<Vec3, 3>& y) {
    const Vec3 area = (y[1] - y[0]).cross(y[2] - y[0]);
    const double scale = std::max({(y[1] - y[0]).squaredNorm(), (y[2] - y[0]).squaredNorm(),
                                   (y[2] - y[1]).squaredNorm()});
    return area.dot(old_area) > 0 && area.norm() > 1e-8 * scale;
}

Offset lattice_offset(const Cluster& c, const Vec3& unwrapped, const Vec3& stored) {
    if (!c.periodic()) return {0, 0, 0};
    const Vec3 k = c.period().inverse() * (unwrapped - stored);
    return {static_cast<int>(std::lround(k.x())), static_cast<int>(std::lround(k.y())),
            static_cast<int>(std::lround(k.z()))};
}

} // namespace froth::surgery
