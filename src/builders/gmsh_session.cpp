// The gmsh session guard and the mesh extraction shared by the gmsh builders.
#include "builders/gmsh_session.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace froth::gmsh_detail {

std::string num(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

Session::Session() : lock_(mutex()) {
    gmsh::initialize(0, nullptr, /*readConfigFiles=*/false); // no user gmshrc: reproducible
    gmsh::option::setNumber("General.Terminal", 0);
}

Session::~Session() {
    try {
        gmsh::finalize();
    } catch (...) { // nothing sensible to do; never throw from a destructor
    }
}

std::mutex& Session::mutex() {
    static std::mutex m;
    return m;
}

std::vector<NodeTri> entity_triangles(int tag) {
    std::vector<std::size_t> elements, nodes;
    gmsh::model::mesh::getElementsByType(2, elements, nodes, tag); // type 2: 3-node triangle
    std::vector<NodeTri> tris(nodes.size() / 3);
    for (std::size_t i = 0; i < tris.size(); ++i)
        tris[i] = {nodes[3 * i], nodes[3 * i + 1], nodes[3 * i + 2]};
    return tris;
}

// Flips whole parts (gmsh entities) so that the merged surface is consistently oriented: where
// triangles of two parts share an edge they must traverse it in opposite directions. Triangles
// within one entity are already consistent. gmsh's oriented getBoundary signs cannot be used
// for this (wrong in 4.8), so it works from the mesh alone. Parts that share no edge keep
// their own orientation.
void orient_parts(std::vector<std::vector<NodeTri>>& parts, const std::string& what) {
    if (parts.size() < 2) return;
    struct Half {
        std::size_t lo, hi;
        int part, dir;
    };
    std::vector<Half> h;
    for (int p = 0; p < static_cast<int>(parts.size()); ++p)
        for (const NodeTri& t : parts[p])
            for (int k = 0; k < 3; ++k) {
                const std::size_t a = t[k], b = t[(k + 1) % 3];
                h.push_back({std::min(a, b), std::max(a, b), p, a < b ? 1 : -1});
            }
    std::sort(h.begin(), h.end(), [](const Half& x, const Half& y) {
        return std::tie(x.lo, x.hi) < std::tie(y.lo, y.hi);
    });
    // links[p]: (q, r) meaning sign[q] must be r * sign[p]
    std::vector<std::vector<std::pair<int, int>>> links(parts.size());
    for (std::size_t i = 0, j; i < h.size(); i = j) {
        for (j = i + 1; j < h.size() && h[j].lo == h[i].lo && h[j].hi == h[i].hi; ++j) {
        }
        if (j - i != 2 || h[i].part == h[i + 1].part) continue; // only manifold seams link
        const int r = -h[i].dir * h[i + 1].dir;
        links[h[i].part].emplace_back(h[i + 1].part, r);
        links[h[i + 1].part].emplace_back(h[i].part, r);
    }
    std::vector<int> sign(parts.size(), 0);
    for (std::size_t root = 0; root < parts.size(); ++root) {
        if (sign[root] != 0) continue;
        sign[root] = 1;
        std::vector<int> stack{static_cast<int>(root)};
        while (!stack.empty()) {
            const int p = stack.back();
            stack.pop_back();
            for (auto [q, r] : links[p]) {
                if (sign[q] == 0)
                    sign[q] = r * sign[p], stack.push_back(q);
                else if (sign[q] != r * sign[p])
                    throw TopologyError(what + " cannot be oriented consistently");
            }
        }
    }
    for (std::size_t p = 0; p < parts.size(); ++p)
        if (sign[p] < 0)
            for (NodeTri& t : parts[p])
                std::swap(t[1], t[2]);
}

ClusterSpec extract(const std::vector<FilmPlan>& films, std::vector<std::vector<int>> bodies,
                    const std::string& op) {
    std::vector<std::vector<NodeTri>> tris(films.size());
    std::vector<std::size_t> used;
    for (std::size_t f = 0; f < films.size(); ++f) {
        std::vector<std::vector<NodeTri>> parts;
        for (int e : films[f].entities)
            parts.push_back(entity_triangles(e));
        orient_parts(parts, op + ": surface " + std::to_string(f + 1));
        for (auto& part : parts)
            tris[f].insert(tris[f].end(), part.begin(), part.end());
        for (const NodeTri& t : tris[f])
            used.insert(used.end(), t.begin(), t.end());
    }
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());

    std::vector<std::size_t> tags;
    std::vector<double> xyz, param;
    gmsh::model::mesh::getNodes(tags, xyz, param, -1, -1, false, false); // every node
    std::unordered_map<std::size_t, std::size_t> row;
    for (std::size_t i = 0; i < tags.size(); ++i)
        row.emplace(tags[i], i);

    ClusterSpec spec;
    for (std::size_t tag : used) {
        auto it = row.find(tag);
        if (it == row.end())
            throw IoError(op + ": triangle node " + std::to_string(tag) + " has no coordinates");
        spec.vertices.emplace_back(xyz[3 * it->second], xyz[3 * it->second + 1],
                                   xyz[3 * it->second + 2]);
    }
    auto id = [&](std::size_t tag) {
        return static_cast<int>(std::lower_bound(used.begin(), used.end(), tag) - used.begin());
    };
    for (std::size_t f = 0; f < films.size(); ++f) {
        ClusterSpec::Surface s;
        s.sigma = films[f].sigma;
        for (const NodeTri& t : tris[f])
            s.triangles.push_back({id(t[0]), id(t[1]), id(t[2])});
        spec.surfaces.push_back(std::move(s));
    }
    spec.bodies = std::move(bodies);
    return spec;
}

std::vector<int> adjacent(int dim, int tag, bool up) {
    std::vector<int> upward, downward;
    gmsh::model::getAdjacencies(dim, tag, upward, downward);
    std::vector<int>& r = up ? upward : downward;
    std::sort(r.begin(), r.end());
    return r;
}

std::vector<int> entity_tags(int dim) {
    gmsh::vectorpair dim_tags;
    gmsh::model::getEntities(dim_tags, dim);
    std::vector<int> r;
    for (auto [d, t] : dim_tags)
        r.push_back(t);
    std::sort(r.begin(), r.end());
    return r;
}

void mesh_surfaces(double h) {
    gmsh::option::setNumber("Mesh.MeshSizeMax", h);
    gmsh::option::setNumber("Mesh.Algorithm", 6); // Frontal-Delaunay: well-shaped and fast
    gmsh::model::mesh::generate(2);               // surfaces only; no tetrahedra needed
}

double estimated_vertices(double area, double h) {
    return 1.2 * area / (h * h);
}

void check_h(const std::string& op, double h, double lo, double hi, double area) {
    if (!(std::isfinite(h) && h > 0))
        throw InvalidInput(op + ": h must be positive, got " + num(h));
    if (h < lo)
        throw InvalidInput(op + ": h = " + num(h) + " is too small (about " +
                           std::to_string(std::llround(estimated_vertices(area, h))) +
                           " vertices); use h >= " + num(lo));
    if (h > hi) throw InvalidInput(op + ": h must be at most " + num(hi) + ", got " + num(h));
}

} // namespace froth::gmsh_detail
