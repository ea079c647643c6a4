// A vanishing body joins a neighbour (transitions.h, absorb_body): the films between the two
// go, the body's other films become the neighbour's, and where such a film meets one of the
// neighbour's along a line of the films that went, the two join into one film.
//
// No vertex moves, so nothing can turn over and the energy falls by exactly the tension of the
// films that went (equal tensions); the neighbour's volume grows by exactly the body's. The
// lines of the films that went stop being triple lines (two films meet there now, one after the
// join), their quadruple points become points of the neighbour's lines. This is the pop of a
// cell whose faces could not shrink away first (a grain flattened at the mesh's scale, with
// more than four neighbours): the cell's place goes to one neighbour instead of to a point.
#include "mesh/transitions.h"

#include "core/errors.h"
#include "core/format.h"
#include "mesh/transition_surgery.h"

#include <algorithm>
#include <map>
#include <numeric>
#include <set>
#include <utility>

namespace froth {
namespace {

std::string body_name(int b) { return "absorb_body: body " + std::to_string(b + 1); }

/// Union-find over surface ids.
struct Groups {
    std::vector<int> parent;
    explicit Groups(int n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
    int find(int s) { return parent[s] == s ? s : parent[s] = find(parent[s]); }
    void join(int a, int b) { // the lower id stays the root
        a = find(a), b = find(b);
        parent[std::max(a, b)] = std::min(a, b);
    }
};

/// Body k's sign on surface s (+1: the normal points out of k), 0 if s is not k's.
int sign_of(const Cluster& c, int k, int s) {
    for (const BodyFace& f : c.bodies()[k].faces)
        if (f.surface == s) return f.sign;
    return 0;
}

/// The bodies body b shares films with, the largest shared area first.
std::vector<int> neighbours_by_area(const Cluster& c, int b,
                                    const std::vector<std::array<int, 2>>& cells,
                                    const std::vector<double>& areas) {
    std::map<int, double> shared;
    for (const BodyFace& f : c.bodies()[b].faces) {
        const auto& k = cells[f.surface];
        const int other = k[0] == b ? k[1] : k[0];
        if (other >= 0) shared[other] += areas[f.surface];
    }
    std::vector<int> out;
    for (const auto& [k, area] : shared) out.push_back(k);
    std::stable_sort(out.begin(), out.end(), [&](int x, int y) { return shared[x] > shared[y]; });
    return out;
}

/// The area of each surface.
std::vector<double> surface_areas_here(const Cluster& c) {
    std::vector<double> areas(c.n_surfaces(), 0.0);
    for (int s = 0; s < c.n_surfaces(); ++s)
        for (std::size_t f = 0; f < c.surface(s).triangles.size(); ++f)
            areas[s] += surgery::facet_area(c, s, f).norm() / 2;
    return areas;
}

/// The films of b that go (those with n) and the groups of films that join: across each line
/// of a film that goes, the two films left.
struct Plan {
    std::vector<char> gone;
    Groups groups;
    double gone_area = 0;
};

Plan plan(const Cluster& c, int b, int n, const std::vector<std::array<int, 2>>& cells,
          const std::vector<double>& areas) {
    Plan p{std::vector<char>(c.n_surfaces(), 0), Groups(c.n_surfaces())};
    for (const BodyFace& f : c.bodies()[b].faces)
        if (cells[f.surface][0] == n || cells[f.surface][1] == n)
            p.gone[f.surface] = 1, p.gone_area += areas[f.surface];
    for (const TripleLine& tl : c.triple_lines()) {
        std::vector<int> kept;
        for (int s : tl.surfaces)
            if (!p.gone[s]) kept.push_back(s);
        if (kept.size() == 2) p.groups.join(kept[0], kept[1]);
    }
    return p;
}

/// spec's surfaces after the plan: each group as one surface (its lowest id's, in the order
/// of those ids), the members' facets turned where their sign seen from b + n differs from
/// the representative's. surface_id: each old surface's new id (-1: gone).
void join_surfaces(const Cluster& c, int b, int n, Plan& p, ClusterSpec& spec,
                   std::vector<int>& surface_id, std::vector<int>& kept_surfaces) {
    const auto sign_from_merged = [&](int s) {
        const int from_b = sign_of(c, b, s);
        return from_b != 0 ? from_b : sign_of(c, n, s);
    };
    std::vector<ClusterSpec::Surface> surfaces;
    surface_id.assign(c.n_surfaces(), -1);
    for (int s = 0; s < c.n_surfaces(); ++s) { // the representatives first, in order
        if (p.gone[s] || p.groups.find(s) != s) continue;
        surface_id[s] = static_cast<int>(surfaces.size());
        kept_surfaces.push_back(s);
        surfaces.push_back(spec.surfaces[s]);
    }
    for (int s = 0; s < c.n_surfaces(); ++s) {
        const int rep = p.groups.find(s);
        if (p.gone[s] || rep == s) continue;
        surface_id[s] = surface_id[rep];
        ClusterSpec::Surface& to = surfaces[surface_id[rep]];
        const ClusterSpec::Surface& from = spec.surfaces[s];
        const bool flip = sign_from_merged(s) != sign_from_merged(rep);
        for (std::size_t f = 0; f < from.triangles.size(); ++f) {
            Tri t = from.triangles[f];
            if (flip) std::swap(t[1], t[2]);
            to.triangles.push_back(t);
            if (!spec.period) continue;
            auto k = from.offsets.empty() ? std::array<Offset, 3>{} : from.offsets[f];
            if (flip) std::swap(k[1], k[2]);
            to.offsets.push_back(k);
        }
    }
    spec.surfaces = std::move(surfaces);
}

/// spec's bodies: c's but b, n with b's films too, through surface_id.
void list_bodies(const Cluster& c, int b, int n, const std::vector<int>& surface_id,
                 ClusterSpec& spec) {
    spec.bodies.clear();
    spec.volconst.clear();
    std::vector<char> listed(spec.surfaces.size(), 0);
    for (int k = 0; k < c.n_bodies(); ++k) {
        if (k == b) continue;
        std::vector<int> ids;
        const auto add = [&](int s) {
            const int id = surface_id[s];
            if (id >= 0 && !std::exchange(listed[id], 1)) ids.push_back(id);
        };
        std::fill(listed.begin(), listed.end(), 0);
        for (const BodyFace& f : c.bodies()[k].faces) add(f.surface);
        if (k == n)
            for (const BodyFace& f : c.bodies()[b].faces) add(f.surface);
        std::sort(ids.begin(), ids.end());
        spec.bodies.push_back(std::move(ids));
        spec.volconst.push_back(c.bodies()[k].volconst);
    }
}

void describe(const Cluster& c, int b, int n, int n_neighbours, const Plan& p, const Cluster& r,
              TransitionRecord& record) {
    record.kind = "absorb body";
    record.body = b;
    record.neighbours = n_neighbours;
    record.cells = {b, n};
    record.removed_vertices = c.n_vertices() - r.n_vertices();
    record.removed_facets = c.n_facets() - r.n_facets();
    for (int s = 0; s < c.n_surfaces(); ++s) // a point of the films that went
        if (p.gone[s]) {
            record.point = c.position(c.surface(s).triangles.front()[0]);
            break;
        }
    record.where = "body " + std::to_string(b + 1) + " (volume " +
                   fmt(body_volume(c, c.bodies()[b], c.positions())) + ", " +
                   std::to_string(n_neighbours) + " neighbouring cells) joined body " +
                   std::to_string(n + 1) + " at " + point_text(record.point) +
                   ": their films of area " + fmt(p.gone_area) + " went";
}

/// absorb_body into body n, a neighbour of b.
Cluster absorb_into(const Cluster& c, int b, int n, const std::vector<std::array<int, 2>>& cells,
                    const std::vector<double>& areas, int n_neighbours,
                    TransitionRecord* record) {
    Plan p = plan(c, b, n, cells, areas);
    ClusterSpec spec = cluster_spec(c);
    std::vector<int> surface_id, kept_surfaces;
    join_surfaces(c, b, n, p, spec, surface_id, kept_surfaces);
    list_bodies(c, b, n, surface_id, spec);
    const std::vector<int> used = surgery::keep_used_vertices(spec, c.positions());
    // a fixed vertex or one on a wall or wire goes only with the user's say
    const auto gone_with = [&](int v) {
        if (used[v] >= 0) return;
        throw TopologyError(body_name(b) + ": vertex " + std::to_string(v + 1) + ", fixed or on "
                            "a wall or wire, lies inside the films that would go with it");
    };
    for (int v : c.fixed_vertices()) gone_with(v);
    for (const auto& attached : c.wall_attachments()) gone_with(attached[0]);
    for (const CurvePoint& cp : c.curve_points()) gone_with(cp.vertex);
    surgery::copy_vertex_lists(c, [&](int old) { return used[old]; }, spec);
    Cluster r = surgery::rebuild(std::move(spec), body_name(b), "absorbing it");
    surgery::carry_over_without_body(c, b, kept_surfaces, r);
    if (record) describe(c, b, n, n_neighbours, p, r, *record);
    return r;
}

} // namespace

Cluster absorb_body(const Cluster& c, int b, int into, TransitionRecord* record) {
    if (b < 0 || b >= c.n_bodies())
        throw InvalidInput("absorb_body: body " + std::to_string(b + 1) + " does not exist (the "
                           "cluster has " + std::to_string(c.n_bodies()) + ")");
    if (into >= c.n_bodies() || into == b)
        throw InvalidInput(body_name(b) + ": body " + std::to_string(into + 1) + " cannot "
                           "absorb it (not another body of the cluster)");
    if (!c.bodies()[b].lids.empty())
        throw TopologyError(body_name(b) + " meets walls or wires; only a cell bounded by "
                            "films alone can be absorbed");
    const int n_neighbours = static_cast<int>(neighbour_cells(c, b).size()); // throws if wrapping
    const auto cells = surface_cells(c);
    const std::vector<double> areas = surface_areas_here(c);
    const std::vector<int> candidates = neighbours_by_area(c, b, cells, areas);
    if (into >= 0) {
        if (std::find(candidates.begin(), candidates.end(), into) == candidates.end())
            throw TopologyError(body_name(b) + " does not meet body " + std::to_string(into + 1));
        return absorb_into(c, b, into, cells, areas, n_neighbours, record);
    }
    if (candidates.empty()) throw TopologyError(body_name(b) + " does not meet another body");
    // the largest contact first; another where joining that one would wrap a cell around a
    // periodic box (it meets b twice, once through the box) or make no valid cluster
    std::string first_error;
    for (int n : candidates) {
        try {
            return absorb_into(c, b, n, cells, areas, n_neighbours, record);
        } catch (const TopologyError& e) {
            if (first_error.empty()) first_error = e.what();
        }
    }
    throw TopologyError(first_error);
}

} // namespace froth
