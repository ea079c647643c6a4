#include "builders/gmsh_builder.h"

#include "core/errors.h"

#include <gmsh.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <new>
#include <numbers>
#include <sstream>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace froth {
namespace {

using NodeTri = std::array<std::size_t, 3>; // a triangle as gmsh node tags

/// One froth surface to be: the gmsh surface entities merged into it.
struct FilmPlan {
    std::vector<int> entities;
    double sigma = 1.0;
};

std::string num(double x) {
    std::ostringstream s;
    s << x;
    return s.str();
}

// gmsh is a process-wide singleton and not thread-safe, so one session at a time. The guard
// also finalizes when an exception leaves a build half done, so the next build starts clean.
class Session {
  public:
    Session() : lock_(mutex()) {
        gmsh::initialize(0, nullptr, /*readConfigFiles=*/false); // no user gmshrc: reproducible
        gmsh::option::setNumber("General.Terminal", 0);
    }
    ~Session() {
        try {
            gmsh::finalize();
        } catch (...) { // nothing sensible to do; never throw from a destructor
        }
    }
    Session(const Session&) = delete;
    Session& operator=(const Session&) = delete;

  private:
    static std::mutex& mutex() {
        static std::mutex m;
        return m;
    }
    std::lock_guard<std::mutex> lock_;
};

// gmsh::initialize sets General.AbortOnError = 2, so in 4.8 every gmsh error is thrown as a
// plain std::string (not a std::exception). Runs body in a gmsh session and turns whatever
// gmsh throws into the froth exception E, with prefix naming the operation.
template <class E, class F> auto in_session(const std::string& prefix, F&& body) {
    try {
        Session session;
        return body();
    } catch (const Error&) {
        throw;
    } catch (const std::bad_alloc&) {
        throw;
    } catch (const std::string& s) {
        throw E(prefix + s);
    } catch (const std::exception& e) {
        throw E(prefix + e.what());
    } catch (...) { // safe: no Lua code runs inside a gmsh session
        throw E(prefix + "unknown gmsh error");
    }
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

// The ClusterSpec of the current gmsh model: one surface per film, vertices compacted to the
// nodes that the triangles use, numbered 0.. in increasing gmsh node tag.
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

// h bounds scale with the size of the object; the minimum keeps the mesh below ~1e6 vertices.
void check_h(const std::string& op, double h, double lo, double hi, double area) {
    if (!(std::isfinite(h) && h > 0))
        throw InvalidInput(op + ": h must be positive, got " + num(h));
    if (h < lo)
        throw InvalidInput(
            op + ": h = " + num(h) + " is too small (about " +
            std::to_string(std::llround(1.2 * area / (h * h))) + // dependencies.md §3
            " vertices); use h >= " + num(lo));
    if (h > hi) throw InvalidInput(op + ": h must be at most " + num(hi) + ", got " + num(h));
}

// Groups the surface entities of the double bubble by their adjacent volumes: a seam can split
// one film into several entities, and the key (lower, upper or both) is what defines a film.
std::vector<FilmPlan> double_bubble_films(int lower, int upper, const DoubleBubbleOptions& o) {
    std::vector<FilmPlan> films(3);
    for (int i = 0; i < 3; ++i)
        films[i].sigma = o.sigma[i];
    for (int s : entity_tags(2)) {
        const std::vector<int> up = adjacent(2, s, true);
        if (up == std::vector<int>{lower})
            films[0].entities.push_back(s);
        else if (up == std::vector<int>{upper})
            films[1].entities.push_back(s);
        else if (up == std::vector<int>{std::min(lower, upper), std::max(lower, upper)})
            films[2].entities.push_back(s);
    }
    for (int i = 0; i < 3; ++i)
        if (films[i].entities.empty())
            throw GeometryError("double_bubble: gmsh produced no surface " + std::to_string(i + 1));
    return films;
}

} // namespace

ClusterSpec build_double_bubble(const DoubleBubbleOptions& o) {
    const std::string op = "double_bubble";
    check_h(op, o.h, 0.005, 0.5, 5 * std::numbers::pi);
    if (!(std::isfinite(o.split) && std::abs(o.split) <= 0.9))
        throw InvalidInput(op + ": split must be in [-0.9, 0.9], got " + num(o.split));
    for (int i = 0; i < 3; ++i)
        if (!(std::isfinite(o.sigma[i]) && o.sigma[i] > 0))
            throw InvalidInput(op + ": sigma[" + std::to_string(i + 1) +
                               "] must be positive, got " + num(o.sigma[i]));
    return in_session<GeometryError>(op + ": gmsh failed: ", [&] {
        namespace occ = gmsh::model::occ;
        gmsh::model::add(op);
        const int ball = occ::addSphere(0, 0, 0, 1);
        const int box = occ::addBox(-2, -2, -2, 4, 4, 2 + o.split); // the half-space z < split
        gmsh::vectorpair pieces, outside;
        std::vector<gmsh::vectorpair> map;
        occ::fragment({{3, ball}}, {{3, box}}, pieces, map);
        int lower = -1, upper = -1;
        for (auto [dim, tag] : pieces) {
            if (dim != 3) continue;
            double x0, y0, z0, x1, y1, z1;
            occ::getBoundingBox(3, tag, x0, y0, z0, x1, y1, z1);
            if (x1 - x0 > 3)
                outside.push_back({3, tag}); // the rest of the 4-wide box
            else
                (z0 + z1 < 2 * o.split ? lower : upper) = tag;
        }
        if (lower < 0 || upper < 0) throw GeometryError(op + ": the fragment lacks a bubble");
        occ::remove(outside, /*recursive=*/true); // keeps the cap it shares with the lower bubble
        occ::synchronize();
        mesh_surfaces(o.h);
        return extract(double_bubble_films(lower, upper, o), {{0, 2}, {1, 2}}, op);
    });
}

ClusterSpec build_sphere(const SphereOptions& o) {
    const std::string op = "sphere";
    if (!(std::isfinite(o.R) && o.R > 0))
        throw InvalidInput(op + ": R must be positive, got " + num(o.R));
    if (!o.center.allFinite()) throw InvalidInput(op + ": center must be finite");
    check_h(op, o.h, 0.005 * o.R, o.R, 4 * std::numbers::pi * o.R * o.R);
    return in_session<GeometryError>(op + ": gmsh failed: ", [&] {
        // Mesh the unit sphere at the origin and map it: OCC's Frontal-Delaunay fails on some
        // offset spheres (R = 2 at (1,-2,3)) and gmsh silently falls back to MeshAdapt, 10x
        // slower. The unit sphere meshes at every h tried, and scaling keeps the shape.
        gmsh::model::add(op);
        gmsh::model::occ::addSphere(0, 0, 0, 1);
        gmsh::model::occ::synchronize();
        mesh_surfaces(o.h / o.R);
        FilmPlan film;
        film.entities = entity_tags(2); // the sphere face (its seam does not split it)
        ClusterSpec spec = extract({film}, {{0}}, op);
        for (Vec3& x : spec.vertices)
            x = o.center + o.R * x;
        return spec;
    });
}

namespace {

// Physical groups of dimension dim in order of tag, each as its entity tags; if there are
// none, each entity of that dimension alone.
std::vector<std::vector<int>> groups_or_entities(int dim, bool& physical) {
    gmsh::vectorpair groups;
    gmsh::model::getPhysicalGroups(groups, dim);
    std::sort(groups.begin(), groups.end());
    std::vector<std::vector<int>> r;
    for (auto [d, tag] : groups) {
        std::vector<int> entities;
        gmsh::model::getEntitiesForPhysicalGroup(d, tag, entities);
        r.push_back(entities);
    }
    physical = !groups.empty();
    if (!physical)
        for (int e : entity_tags(dim))
            r.push_back({e});
    return r;
}

std::vector<FilmPlan> msh_films(const std::string& where) {
    bool physical = false;
    std::vector<FilmPlan> films;
    for (const std::vector<int>& group : groups_or_entities(2, physical)) {
        std::size_t n = 0;
        for (int e : group)
            n += entity_triangles(e).size();
        if (n == 0 && physical)
            throw IoError(where + "physical surface " + std::to_string(films.size() + 1) +
                          " has no triangles");
        if (n > 0) films.push_back({group, 1.0});
    }
    return films;
}

std::vector<std::vector<int>> msh_bodies(const std::vector<FilmPlan>& films,
                                         const std::string& where) {
    std::unordered_map<int, int> film_of; // surface entity -> froth surface
    for (std::size_t f = 0; f < films.size(); ++f)
        for (int e : films[f].entities)
            film_of.emplace(e, static_cast<int>(f));
    bool physical = false;
    std::vector<std::vector<int>> bodies;
    for (const std::vector<int>& volumes : groups_or_entities(3, physical)) {
        std::vector<int> body;
        for (int v : volumes)
            for (int s : adjacent(3, v, false))
                if (auto it = film_of.find(s); it != film_of.end()) body.push_back(it->second);
        std::sort(body.begin(), body.end());
        body.erase(std::unique(body.begin(), body.end()), body.end());
        if (body.empty() && physical) // a named body we cannot build: say so rather than drop it
            throw IoError(where + "physical volume " + std::to_string(bodies.size() + 1) +
                          " has no triangulated boundary surfaces");
        if (!body.empty()) bodies.push_back(std::move(body));
    }
    return bodies;
}

} // namespace

ClusterSpec read_msh(const std::string& path) {
    // gmsh::open on a missing file only logs and returns, so check first.
    if (std::FILE* f = std::fopen(path.c_str(), "rb"))
        std::fclose(f);
    else
        throw IoError("read: cannot open '" + path + "': " + std::strerror(errno));
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec))
        throw IoError("read: cannot open '" + path + "': Is a directory");
    const std::string where = "read: '" + path + "': ";
    return in_session<IoError>("read: '" + path + "' is not a readable mesh: ", [&] {
        gmsh::open(path);
        std::vector<FilmPlan> films = msh_films(where);
        if (films.empty()) throw IoError("read: '" + path + "' has no triangles");
        return extract(films, msh_bodies(films, where), "read: '" + path + "'");
    });
}

} // namespace froth
