// froth.fragment: solids -> OCC fragment -> bodies and films (dependencies.md §3, "three_spheres").
#include "builders/fragment.h"

#include "builders/gmsh_session.h"
#include "core/errors.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <numeric>
#include <set>
#include <tuple>
#include <unordered_map>
#include <utility>

namespace froth {
using namespace gmsh_detail;

Vec3 solid_center(const Solid& s) {
    switch (s.kind) {
    case SolidKind::box:
        return s.min + s.size / 2;
    case SolidKind::cylinder:
        return s.base + s.axis / 2;
    default:
        return s.center;
    }
}

namespace {

namespace occ = gmsh::model::occ;
constexpr double kInf = std::numeric_limits<double>::infinity();

std::string label(const FragmentOptions& o, std::size_t k) {
    return o.op + ": solids[" + std::to_string(k + 1) + "] (" + solid_kind_name(o.solids[k].kind) +
           ")";
}

std::string vec(const Vec3& v) {
    std::string s = "{"; // appended, not "{" + ...: GCC 12's -Wrestrict misfires on that
    s += num(v.x()) + ", " + num(v.y()) + ", " + num(v.z()) + "}";
    return s;
}

void check_positive(const std::string& who, const std::string& what, double x) {
    if (!(std::isfinite(x) && x > 0))
        throw InvalidInput(who + ": " + what + " must be positive, got " + num(x));
}

void check_kind_fields(const Solid& s, const std::string& who) {
    switch (s.kind) {
    case SolidKind::ball:
        check_positive(who, "radius r", s.r);
        break;
    case SolidKind::box:
        if (!(s.size.array() > 0).all())
            throw InvalidInput(who + ": size must be positive in x, y and z, got " + vec(s.size));
        break;
    case SolidKind::cylinder:
        check_positive(who, "radius r", s.r);
        if (s.axis.norm() == 0)
            throw InvalidInput(who + ": axis must be a nonzero vector (its length is the height)");
        break;
    case SolidKind::torus:
        check_positive(who, "tube radius r", s.r);
        check_positive(who, "major radius R", s.R);
        if (s.r >= s.R)
            throw InvalidInput(who + ": tube radius r = " + num(s.r) +
                               " must be smaller than the major radius R = " + num(s.R));
        if (s.axis.norm() == 0) throw InvalidInput(who + ": axis must be a nonzero vector");
        break;
    }
}

// -pi/2 <= lo < hi <= pi/2 (a round-off above pi/2 is allowed: lo = -math.pi / 2 in Lua).
void check_latitude(const Solid& s, const std::string& who) {
    constexpr double half = std::numbers::pi / 2, slack = 1e-12;
    const double lo = s.latitude_lo, hi = s.latitude_hi;
    if (!(std::isfinite(lo) && std::isfinite(hi)))
        throw InvalidInput(who + ": latitude must be finite, got {" + num(lo) + ", " + num(hi) +
                           "}");
    if (!(lo >= -half * (1 + slack) && hi <= half * (1 + slack) && lo < hi))
        throw InvalidInput(who + ": latitude {lo, hi} must satisfy -pi/2 <= lo < hi <= pi/2 " +
                           "(radians), got {" + num(lo) + ", " + num(hi) + "}");
}

// OpenCASCADE models to an absolute tolerance of 1e-7: lengths far below it mesh to nothing,
// and far above it (r = 1e300) its boolean operations run for ever, so both are refused here,
// before gmsh sees them.
void check_scale(const Solid& s, const std::string& who) {
    constexpr double lo = 1e-5, hi = 1e5;
    double longest = 0, shortest = kInf;
    auto length = [&](double x) { longest = std::max(longest, x), shortest = std::min(shortest, x); };
    switch (s.kind) {
    case SolidKind::ball: length(s.r); break;
    case SolidKind::box: for (double x : s.size) length(x); break;
    case SolidKind::cylinder: length(s.r), length(s.axis.norm()); break;
    case SolidKind::torus: length(s.r), length(s.R); break;
    }
    longest *= s.scale.maxCoeff(), shortest *= s.scale.minCoeff();
    if (!(shortest >= lo && longest <= hi))
        throw InvalidInput(who + ": its sizes (times scale) span " + num(shortest) + " .. " +
                           num(longest) + "; they must lie in [1e-5, 1e5] (OpenCASCADE works "
                           "to an absolute tolerance of 1e-7: scale the whole cluster instead)");
    for (const Vec3* v : {&s.center, &s.min, &s.base, &s.translate})
        if (v->cwiseAbs().maxCoeff() > hi)
            throw InvalidInput(who + ": coordinates must be at most 1e5 in magnitude, got " +
                               vec(*v));
}

void check_solid(const FragmentOptions& o, std::size_t k) {
    const Solid& s = o.solids[k];
    const std::string who = label(o, k);
    for (const Vec3* v :
         {&s.center, &s.min, &s.size, &s.base, &s.axis, &s.translate, &s.rotate_axis, &s.scale})
        if (!v->allFinite()) throw InvalidInput(who + ": coordinates must be finite");
    if (!(std::isfinite(s.r) && std::isfinite(s.R) && std::isfinite(s.angle) &&
          std::isfinite(s.rotate_angle)))
        throw InvalidInput(who + ": numbers must be finite");
    check_kind_fields(s, who);
    if (!(s.angle > 0 && s.angle <= 2 * std::numbers::pi * (1 + 1e-12)))
        throw InvalidInput(who + ": angle must be in (0, 2 pi], got " + num(s.angle));
    check_latitude(s, who);
    if (s.rotate_angle != 0 && s.rotate_axis.norm() == 0)
        throw InvalidInput(who + ": rotate axis must be a nonzero vector");
    if (!(s.scale.array() > 0).all())
        throw InvalidInput(who + ": scale must be positive, got " + vec(s.scale));
    check_scale(s, who);
    if (s.h) check_positive(who, "h", *s.h);
}

// Body ids given for all solids or none, and numbering the bodies 1..n without gaps.
void check_body_ids(const FragmentOptions& o) {
    const std::size_t n = o.solids.size();
    std::vector<bool> used(n + 1, false);
    for (std::size_t k = 0; k < n; ++k) {
        const std::optional<long long> b = o.solids[k].body;
        if (b.has_value() != o.solids[0].body.has_value())
            throw InvalidInput(label(o, k) + (b ? " has" : " has no") + " body id, solids[1]" +
                               (b ? " has none" : " has one") +
                               ": give body to every solid or to none");
        if (!b) continue;
        if (*b < 1 || *b > static_cast<long long>(n))
            throw InvalidInput(label(o, k) + ": body = " + std::to_string(*b) +
                               " must be in 1.." + std::to_string(n) + " (one body per id)");
        used[*b] = true;
    }
    if (!o.solids[0].body) return;
    for (std::size_t b = 1; b <= n; ++b)
        if (!used[b] && std::find(used.begin() + b, used.end(), true) != used.end())
            throw InvalidInput(o.op + ": body ids must number the bodies 1..n: no solid has body " +
                               std::to_string(b));
}

// Body ids (1-based) of the solids: their own `body`, else body k for solid k.
std::vector<int> body_of_solids(const FragmentOptions& o) {
    std::vector<int> body(o.solids.size());
    for (std::size_t k = 0; k < o.solids.size(); ++k)
        body[k] = static_cast<int>(o.solids[k].body.value_or(static_cast<long long>(k + 1)));
    return body;
}

void check_options(const FragmentOptions& o) {
    if (o.solids.empty()) throw InvalidInput(o.op + ": no solids");
    for (std::size_t k = 0; k < o.solids.size(); ++k)
        check_solid(o, k);
    check_body_ids(o);
    if (o.h) check_positive(o.op, "h", *o.h);
    check_positive(o.op, "sigma", o.sigma);
    for (auto [id, sigma] : o.sigma_of) {
        if (id < 0) throw InvalidInput(o.op + ": sigma: surface ids start at 1");
        check_positive(o.op, "sigma[" + std::to_string(id + 1) + "]", sigma);
    }
}

// Turns OCC's z-aligned torus to the requested axis (about its center).
void align_z_to(int tag, const Vec3& c, const Vec3& axis) {
    const Vec3 a = axis.normalized(), z = Vec3::UnitZ();
    const Vec3 k = z.cross(a);
    if (k.norm() > 1e-14)
        occ::rotate({{3, tag}}, c.x(), c.y(), c.z(), k.x(), k.y(), k.z(),
                    std::atan2(k.norm(), z.dot(a)));
    else if (a.z() < 0)
        occ::rotate({{3, tag}}, c.x(), c.y(), c.z(), 1, 0, 0, std::numbers::pi);
}

int add_solid(const Solid& s) {
    const Vec3 c = solid_center(s);
    int tag = -1;
    switch (s.kind) {
    case SolidKind::ball:
        tag = occ::addSphere(c.x(), c.y(), c.z(), s.r, -1,
                             std::max(s.latitude_lo, -std::numbers::pi / 2),
                             std::min(s.latitude_hi, std::numbers::pi / 2),
                             std::min(s.angle, 2 * std::numbers::pi));
        break;
    case SolidKind::box:
        tag = occ::addBox(s.min.x(), s.min.y(), s.min.z(), s.size.x(), s.size.y(), s.size.z());
        break;
    case SolidKind::cylinder:
        tag = occ::addCylinder(s.base.x(), s.base.y(), s.base.z(), s.axis.x(), s.axis.y(),
                               s.axis.z(), s.r);
        break;
    case SolidKind::torus:
        tag = occ::addTorus(c.x(), c.y(), c.z(), s.R, s.r);
        align_z_to(tag, c, s.axis);
        break;
    }
    if (s.scale != Vec3::Ones())
        occ::dilate({{3, tag}}, c.x(), c.y(), c.z(), s.scale.x(), s.scale.y(), s.scale.z());
    if (s.rotate_angle != 0)
        occ::rotate({{3, tag}}, c.x(), c.y(), c.z(), s.rotate_axis.x(), s.rotate_axis.y(),
                    s.rotate_axis.z(), s.rotate_angle);
    if (s.translate != Vec3::Zero())
        occ::translate({{3, tag}}, s.translate.x(), s.translate.y(), s.translate.z());
    return tag;
}

// Fragments the solids and gives each piece to the first solid containing it: solid k gets
// solid k minus solids 1..k-1. One general fuse instead of a chain of cuts keeps every
// interface conforming. Returns the volume tags of each solid.
std::vector<std::vector<int>> solid_pieces(const FragmentOptions& o,
                                           const std::vector<int>& tags) {
    if (tags.size() == 1) return {{tags[0]}};
    gmsh::vectorpair objects{{3, tags[0]}}, tools, out;
    for (std::size_t k = 1; k < tags.size(); ++k)
        tools.push_back({3, tags[k]});
    std::vector<gmsh::vectorpair> map; // per input (objects, then tools): its pieces
    occ::fragment(objects, tools, out, map);
    if (map.size() != tags.size())
        throw GeometryError(o.op + ": gmsh's fragment lost track of the solids");
    std::set<int> taken;
    std::vector<std::vector<int>> pieces(tags.size());
    for (std::size_t k = 0; k < tags.size(); ++k) {
        for (auto [dim, tag] : map[k])
            if (dim == 3 && taken.insert(tag).second) pieces[k].push_back(tag);
        if (pieces[k].empty())
            throw InvalidInput(label(o, k) + " lies inside the solids before it: " +
                               (o.solids[k].body ? "it adds nothing to its body"
                                                 : "its body would be empty"));
    }
    return pieces;
}

/// A film to be: gmsh surfaces separating regions a < b (1-based body ids, 0 = outside).
struct Film {
    int a = 0, b = 0;
    std::vector<int> entities;
    Vec3 center = Vec3::Zero(); ///< bounding box center: the tie-break of the order
};

struct Surfaces {
    std::map<int, std::pair<int, int>> pair_of; // kept surface entity -> (a, b)
    std::map<int, int> body_of_dropped;         // interface inside one body -> that body
};

Surfaces classify_surfaces(const std::unordered_map<int, int>& body_of_volume) {
    Surfaces r;
    for (int s : entity_tags(2)) {
        const std::vector<int> up = adjacent(2, s, true);
        if (up.empty()) continue; // not on any solid: nothing to do with the cluster
        const int a = body_of_volume.at(up[0]);
        const int b = up.size() > 1 ? body_of_volume.at(up[1]) : 0;
        if (a == b)
            r.body_of_dropped[s] = a; // between two pieces of one body: not a film
        else
            r.pair_of[s] = std::minmax(a, b);
    }
    return r;
}

int find_root(std::map<int, int>& parent, int s) {
    while (parent[s] != s)
        s = parent[s] = parent[parent[s]];
    return s;
}

Vec3 bbox_center(const std::vector<int>& entities) {
    Vec3 lo = Vec3::Constant(kInf), hi = -lo;
    for (int s : entities) {
        double x0, y0, z0, x1, y1, z1;
        gmsh::model::getBoundingBox(2, s, x0, y0, z0, x1, y1, z1);
        lo = lo.cwiseMin(Vec3(x0, y0, z0));
        hi = hi.cwiseMax(Vec3(x1, y1, z1));
    }
    return (lo + hi) / 2;
}

// Merges the kept surfaces of one pair that meet along a curve no third kept surface touches
// (a seam, or where an interface inside a body was dropped). Surfaces of one pair that meet
// nowhere stay separate films (the two caps of the torus bubble).
std::vector<Film> group_films(const Surfaces& surfaces) {
    std::map<int, int> parent;
    for (const auto& entry : surfaces.pair_of)
        parent[entry.first] = entry.first;
    for (int c : entity_tags(1)) {
        std::vector<int> kept;
        for (int s : adjacent(1, c, true))
            if (surfaces.pair_of.count(s)) kept.push_back(s);
        if (kept.size() == 2 && surfaces.pair_of.at(kept[0]) == surfaces.pair_of.at(kept[1]))
            parent[find_root(parent, kept[0])] = find_root(parent, kept[1]);
    }
    std::map<int, Film> by_root;
    for (auto [s, pair] : surfaces.pair_of) {
        Film& f = by_root[find_root(parent, s)];
        std::tie(f.a, f.b) = pair;
        f.entities.push_back(s);
    }
    std::vector<Film> films;
    for (auto& entry : by_root) {
        entry.second.center = bbox_center(entry.second.entities);
        films.push_back(std::move(entry.second));
    }
    std::sort(films.begin(), films.end(), [](const Film& x, const Film& y) {
        return std::make_tuple(x.a, x.b, x.center.z(), x.center.y(), x.center.x()) <
               std::make_tuple(y.a, y.b, y.center.z(), y.center.y(), y.center.x());
    });
    return films;
}

// A cluster must be one connected set of bodies: say which solid is cut off.
void check_connected(const FragmentOptions& o, const std::vector<Film>& films) {
    const std::vector<int> body = body_of_solids(o);
    const int n = *std::max_element(body.begin(), body.end());
    if (n < 2) return;
    std::vector<std::size_t> first_solid(n + 1); // names body k in messages
    for (std::size_t k = o.solids.size(); k-- > 0;)
        first_solid[body[k]] = k;
    std::vector<std::vector<int>> next(n + 1);
    for (const Film& f : films)
        if (f.a > 0) next[f.a].push_back(f.b), next[f.b].push_back(f.a);
    for (int k = 1; k <= n; ++k)
        if (next[k].empty())
            throw InvalidInput(label(o, first_solid[k]) +
                               " touches no other solid: a cluster must be connected");
    std::vector<bool> seen(n + 1, false);
    std::vector<int> stack{1};
    seen[1] = true;
    while (!stack.empty()) {
        const int k = stack.back();
        stack.pop_back();
        for (int m : next[k])
            if (!seen[m]) seen[m] = true, stack.push_back(m);
    }
    for (int k = 2; k <= n; ++k)
        if (!seen[k])
            throw InvalidInput(label(o, first_solid[k]) + " is not connected to solids[1]: a " +
                               "cluster must be connected");
}

/// Target edge lengths: per body (local h or the global one) and so per gmsh entity.
struct Sizing {
    double h = 0;                  ///< global
    std::vector<double> body_h;    ///< 1-based; [0] = the outside, +inf (no constraint)
    std::map<int, double> size[3]; ///< per dimension: entity tag -> target size
    bool local = false;            ///< some solid has its own h
    double largest = 0;
};

double model_extent() {
    double x0, y0, z0, x1, y1, z1;
    gmsh::model::getBoundingBox(-1, -1, x0, y0, z0, x1, y1, z1);
    return std::max({x1 - x0, y1 - y0, z1 - z0});
}

double entity_area(int s) {
    double area = 0;
    occ::getMass(2, s, area);
    return area;
}

// Sizes of every surface from its bodies, then of curves and points from the surfaces they
// bound (the finest wins), so a finer body's films keep their size up to their edges.
void size_entities(Sizing& z, const Surfaces& surfaces) {
    auto& s2 = z.size[2];
    for (auto [s, pair] : surfaces.pair_of)
        s2[s] = std::min(z.body_h[pair.first], z.body_h[pair.second]);
    for (auto [s, body] : surfaces.body_of_dropped)
        s2[s] = z.body_h[body];
    for (int dim = 1; dim >= 0; --dim)
        for (int e : entity_tags(dim)) {
            double h = kInf;
            for (int up : adjacent(dim, e, true))
                if (auto it = z.size[dim + 1].find(up); it != z.size[dim + 1].end())
                    h = std::min(h, it->second);
            if (h < kInf) z.size[dim][e] = h;
        }
}

double total_area(const Surfaces& surfaces) {
    double area = 0;
    for (const auto& entry : surfaces.pair_of)
        area += entity_area(entry.first);
    for (const auto& entry : surfaces.body_of_dropped)
        area += entity_area(entry.first);
    return area;
}

// The global h for about o.default_vertices vertices, by the estimate; at most the extent.
double automatic_h(const FragmentOptions& o, const Surfaces& surfaces) {
    const double n = estimated_vertices(total_area(surfaces), 1.0);
    return std::min(model_extent(), std::sqrt(n / static_cast<double>(o.default_vertices)));
}

Sizing plan_sizes(const FragmentOptions& o, const Surfaces& surfaces, double h) {
    Sizing z;
    const double extent = model_extent();
    z.h = h;
    if (z.h > extent)
        throw InvalidInput(o.op + ": h = " + num(z.h) + " is larger than the cluster (extent " +
                           num(extent) + "); use h <= " + num(extent));
    const std::vector<int> body = body_of_solids(o);
    z.body_h.assign(*std::max_element(body.begin(), body.end()) + 1, kInf);
    for (std::size_t k = 0; k < o.solids.size(); ++k) { // a union: its solids' finest h
        const std::optional<double> hk = o.solids[k].h;
        if (hk && *hk > extent)
            throw InvalidInput(label(o, k) + ": h = " + num(*hk) +
                               " is larger than the cluster (extent " + num(extent) + ")");
        z.local = z.local || hk;
        z.body_h[body[k]] = std::min(z.body_h[body[k]], hk.value_or(z.h));
    }
    size_entities(z, surfaces);
    z.largest = z.h;
    for (auto [s, hs] : z.size[2])
        z.largest = std::max(z.largest, hs);
    return z;
}

// Refuses meshes that would be too large before spending minutes meshing them.
void check_vertex_count(const FragmentOptions& o, const Sizing& z) {
    double n = 0;
    for (auto [s, h] : z.size[2])
        n += estimated_vertices(entity_area(s), h);
    if (n <= static_cast<double>(o.max_vertices)) return;
    std::string about = "over 1e18"; // llround of more (or of inf) is undefined
    if (n < 1e18) {
        about = "about ";
        about += std::to_string(std::llround(n));
    }
    std::string msg = o.op + ": h = " + num(z.h) + (z.local ? " (with the solids' own h)" : "") +
                      " gives " + about + " vertices, more than " +
                      std::to_string(o.max_vertices) + "; use a larger h";
    if (!z.local && std::isfinite(n))
        msg +=
            " (h >= " + num(z.h * std::sqrt(n / static_cast<double>(o.max_vertices)) * 1.01) + ")";
    throw InvalidInput(msg);
}

// Vertices of the films (interfaces inside a body are meshed too but dropped).
std::size_t node_count(const Surfaces& surfaces) {
    std::vector<std::size_t> nodes;
    for (const auto& entry : surfaces.pair_of)
        for (const NodeTri& t : entity_triangles(entry.first))
            nodes.insert(nodes.end(), t.begin(), t.end());
    std::sort(nodes.begin(), nodes.end());
    return static_cast<std::size_t>(std::unique(nodes.begin(), nodes.end()) - nodes.begin());
}

void mesh_with(const Sizing& z, const Surfaces& surfaces) {
    // Interfaces inside a body are not films: hide them so that gmsh does not mesh them
    // (their curves stay visible through the films they bound).
    if (!surfaces.body_of_dropped.empty()) {
        gmsh::vectorpair hidden;
        for (const auto& entry : surfaces.body_of_dropped)
            hidden.push_back({2, entry.first});
        gmsh::model::setVisibility(hidden, 0, /*recursive=*/false);
        gmsh::option::setNumber("Mesh.MeshOnlyVisible", 1);
    }
    if (z.local) {
        // The callback is asked with the entity being meshed; it returns that entity's size,
        // and gmsh takes the minimum with Mesh.MeshSizeMax.
        auto sizes = std::make_shared<Sizing>(z);
        gmsh::model::mesh::setSizeCallback([sizes](int dim, int tag, double, double, double) {
            if (dim < 0 || dim > 2) return sizes->largest;
            auto it = sizes->size[dim].find(tag);
            return it == sizes->size[dim].end() ? sizes->largest : it->second;
        });
        // Otherwise a coarse film bounded only by a fine triple line (a ball's outer cap)
        // takes the line's size everywhere.
        gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 0);
    }
    mesh_surfaces(z.largest);
}

std::vector<FilmPlan> film_plans(const FragmentOptions& o, const std::vector<Film>& films) {
    for (auto [id, sigma] : o.sigma_of)
        if (id >= static_cast<int>(films.size()))
            throw InvalidInput(o.op + ": sigma[" + std::to_string(id + 1) + "] names surface " +
                               std::to_string(id + 1) + ", but the cluster has " +
                               (films.size() == 1 ? std::string("only 1 surface")
                                                  : std::to_string(films.size()) + " surfaces"));
    std::vector<FilmPlan> plans(films.size());
    for (std::size_t f = 0; f < films.size(); ++f) {
        plans[f].entities = films[f].entities;
        auto it = o.sigma_of.find(static_cast<int>(f));
        plans[f].sigma = it == o.sigma_of.end() ? o.sigma : it->second;
    }
    return plans;
}

std::vector<std::vector<int>> body_films(std::size_t n_bodies, const std::vector<Film>& films) {
    std::vector<std::vector<int>> bodies(n_bodies);
    for (std::size_t f = 0; f < films.size(); ++f) {
        if (films[f].a > 0) bodies[films[f].a - 1].push_back(static_cast<int>(f));
        bodies[films[f].b - 1].push_back(static_cast<int>(f));
    }
    return bodies;
}

} // namespace

ClusterSpec build_fragment(const FragmentOptions& o) {
    check_options(o);
    return in_session<GeometryError>(o.op + ": gmsh failed: ", [&] {
        gmsh::model::add(o.op);
        std::vector<int> tags;
        for (const Solid& s : o.solids)
            tags.push_back(add_solid(s));
        const std::vector<std::vector<int>> pieces = solid_pieces(o, tags);
        occ::synchronize();
        const std::vector<int> body = body_of_solids(o);
        std::unordered_map<int, int> body_of_volume;
        for (std::size_t k = 0; k < pieces.size(); ++k)
            for (int v : pieces[k])
                body_of_volume[v] = body[k];
        const Surfaces surfaces = classify_surfaces(body_of_volume);
        const std::vector<Film> films = group_films(surfaces);
        check_connected(o, films);
        std::vector<FilmPlan> plans = film_plans(o, films);
        const double h = o.h ? *o.h : automatic_h(o, surfaces);
        Sizing sizing = plan_sizes(o, surfaces, h);
        check_vertex_count(o, sizing);
        mesh_with(sizing, surfaces);
        if (!o.h) { // the estimate is off by up to 15% (curvature, short curves): correct once
            const double ratio = static_cast<double>(node_count(surfaces)) / o.default_vertices;
            if (std::abs(ratio - 1) > 0.05) {
                gmsh::model::mesh::clear();
                mesh_with(plan_sizes(o, surfaces, std::min(h * std::sqrt(ratio), model_extent())),
                          surfaces);
            }
        }
        const auto bodies = static_cast<std::size_t>(*std::max_element(body.begin(), body.end()));
        return extract(plans, body_films(bodies, films), o.op);
    });
}

} // namespace froth
