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
    } catch (const std::string&) { // gmsh's errors (AbortOnError = 2); never throw from a
    } catch (const std::exception&) { // destructor: nothing sensible is left to do
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
