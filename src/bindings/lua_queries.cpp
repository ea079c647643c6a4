// froth.Cluster queries and edits (issue 14, item 4): c:vertices{where}, c:facets{where},
// c:edges{where} list elements with their attributes, filtered by a Lua predicate, as Evolver's
// `list vertex where ...`; c:set_vertex moves one vertex; c:fix, c:unfix and c:fixed hold
// vertices in place (Evolver's `fix vertex where ...`); c:grain_measures gives each body's
// mean width and triple-line length. Ids are 1-based here.
#include "bindings/lua_queries.h"

#include "bindings/lua_cluster.h"
#include "bindings/luax.h"
#include "core/errors.h"
#include "geometry/geometry.h"

#include <algorithm>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace froth::lua {
namespace {

ClusterHandle& self(lua_State* L) {
    return check_cluster(L, 1);
}

void push_vec(lua_State* L, const Vec3& x) {
    push_numbers(L, std::vector<double>{x[0], x[1], x[2]});
}

void set_bool(lua_State* L, const char* key, bool value) {
    lua_pushboolean(L, value);
    lua_setfield(L, -2, key);
}

/// The bodies (0-based) each surface bounds.
std::vector<std::vector<int>> bodies_of_surfaces(const Cluster& c) {
    std::vector<std::vector<int>> r(c.n_surfaces());
    for (int b = 0; b < c.n_bodies(); ++b)
        for (const BodyFace& f : c.bodies()[b].faces)
            r[f.surface].push_back(b);
    return r;
}

/// Reads {where = f} (optional) and returns the stack index of f, or 0.
int read_where(lua_State* L, const char* op) {
    Options o(L, 2, op, true);
    const int t = o.push("where");
    if (t != LUA_TNIL && t != LUA_TFUNCTION)
        o.error("where", "must be a function (record) -> boolean");
    o.finish();
    return t == LUA_TFUNCTION ? lua_gettop(L) : 0;
}

/// With the record on top of the stack: appends it to the result table at `out` if where(record)
/// is true (or there is no where), else drops it. Errors in where propagate with their message.
void keep_if(lua_State* L, int where, int out, int& n) {
    if (where) {
        lua_pushvalue(L, where);
        lua_pushvalue(L, -2);
        lua_call(L, 1, 1);
        const bool keep = lua_toboolean(L, -1);
        lua_pop(L, 1);
        if (!keep) {
            lua_pop(L, 1);
            return;
        }
    }
    lua_rawseti(L, out, ++n);
}

int l_vertices(lua_State* L) {
    ClusterHandle& h = self(L);
    const Cluster& c = h.cluster;
    const int where = read_where(L, "vertices");
    const std::vector<std::vector<int>> body_of = bodies_of_surfaces(c);
    std::vector<char> on_line(c.n_vertices(), 0), quadruple(c.n_vertices(), 0);
    for (const JunctionEdge& e : c.junction_edges())
        on_line[e.a] = on_line[e.b] = 1;
    for (int q : c.quadruple_points())
        quadruple[q] = 1;
    lua_newtable(L);
    const int out = lua_gettop(L);
    int n = 0;
    for (int v = 0; v < c.n_vertices(); ++v) {
        lua_createtable(L, 0, 8);
        set_integer(L, "id", v + 1);
        push_vec(L, c.position(v));
        lua_setfield(L, -2, "x");
        std::vector<int> surfaces, bodies;
        for (int k = c.pair_begin(v); k < c.pair_begin(v + 1); ++k) {
            surfaces.push_back(c.pair_surface(k));
            for (int b : body_of[c.pair_surface(k)])
                bodies.push_back(b);
        }
        std::sort(bodies.begin(), bodies.end());
        bodies.erase(std::unique(bodies.begin(), bodies.end()), bodies.end());
        set_integers(L, "surfaces", surfaces, 1);
        set_integers(L, "bodies", bodies, 1);
        set_integers(L, "walls", c.vertex_walls(v), 1);
        set_bool(L, "triple_line", on_line[v]);
        set_bool(L, "quadruple_point", quadruple[v]);
        set_bool(L, "fixed", c.is_fixed(v));
        if (const CurvePoint* cp = c.curve_point(v)) {
            set_integer(L, "curve", cp->curve + 1);
            set_number(L, "p", cp->p);
        }
        keep_if(L, where, out, n);
    }
    return 1;
}

int l_facets(lua_State* L) {
    ClusterHandle& h = self(L);
    const Cluster& c = h.cluster;
    const int where = read_where(L, "facets");
    const std::vector<std::vector<int>> body_of = bodies_of_surfaces(c);
    lua_newtable(L);
    const int out = lua_gettop(L);
    int n = 0, id = 0;
    for (int s = 0; s < c.n_surfaces(); ++s)
        for (const Tri& t : c.surface(s).triangles) {
            const Vec3 cross =
                (c.position(t[1]) - c.position(t[0])).cross(c.position(t[2]) - c.position(t[0]));
            lua_createtable(L, 0, 6);
            set_integer(L, "id", ++id);
            set_integer(L, "surface", s + 1);
            set_integers(L, "vertices", t, 1);
            set_number(L, "area", 0.5 * cross.norm());
            push_vec(L, cross.normalized());
            lua_setfield(L, -2, "normal");
            set_integers(L, "bodies", body_of[s], 1);
            keep_if(L, where, out, n);
        }
    return 1;
}

int l_edges(lua_State* L) {
    ClusterHandle& h = self(L);
    const Cluster& c = h.cluster;
    const int where = read_where(L, "edges");
    struct Incidence {
        std::vector<int> surfaces; // in increasing order: surfaces are visited in order
        int facets = 0;
    };
    std::map<std::pair<int, int>, Incidence> edges; // sorted by vertex pair: a stable order
    for (int s = 0; s < c.n_surfaces(); ++s)
        for (const Tri& t : c.surface(s).triangles)
            for (int k = 0; k < 3; ++k) {
                Incidence& e = edges[std::minmax(t[k], t[(k + 1) % 3])];
                if (e.surfaces.empty() || e.surfaces.back() != s) e.surfaces.push_back(s);
                ++e.facets;
            }
    lua_newtable(L);
    const int out = lua_gettop(L);
    int n = 0, id = 0;
    for (const auto& [edge, incidence] : edges) {
        const std::vector<int>& surfaces = incidence.surfaces;
        lua_createtable(L, 0, 6);
        set_integer(L, "id", ++id);
        set_integers(L, "vertices", std::vector<int>{edge.first, edge.second}, 1);
        set_number(L, "length", (c.position(edge.second) - c.position(edge.first) +
                                 c.edge_shift(edge.first, edge.second)).norm());
        set_integers(L, "surfaces", surfaces, 1);
        set_bool(L, "triple_line", surfaces.size() == 3);
        set_bool(L, "boundary", incidence.facets == 1); // a free boundary edge: a wall or a wire
        set_bool(L, "wire", c.is_wire_edge(edge.first, edge.second));
        keep_if(L, where, out, n);
    }
    return 1;
}

/// c:set_vertex(v, {x, y, z}): moves vertex v; refused (nothing changes) if a facet at v would
/// lose its area or the point is not finite.
int l_set_vertex(lua_State* L) {
    ClusterHandle& h = self(L);
    ChangeGuard change(L, h, "set_vertex");
    Cluster& c = h.cluster;
    const int v = check_id(L, 2, c.n_vertices(), "vertex", "vertices");
    const Vec3 x = read_xyz(L, 3, "set_vertex: expected a point {x, y, z}");
    return guarded(L, [&] {
        if (!x.allFinite() || x.cwiseAbs().maxCoeff() > kMaxCoordinate)
            throw InvalidInput("set_vertex: vertex " + std::to_string(v + 1) +
                               ": the point must be finite and at most 1e100 in magnitude");
        std::vector<Vec3> X = c.positions();
        X[v] = x;
        if (auto [s, f] = find_degenerate_facet(c, X); s >= 0)
            throw GeometryError("set_vertex: moving vertex " + std::to_string(v + 1) +
                                " there gives facet " + std::to_string(f + 1) + " of surface " +
                                std::to_string(s + 1) + " zero area; nothing changed");
        c.set_positions(std::move(X));
        return 0;
    });
}

/// The id at the top of the stack (an integer, or a record's `id`), 0-based; pops it.
int pop_vertex_id(lua_State* L, const char* op, int entry) {
    if (lua_type(L, -1) == LUA_TTABLE) {
        lua_getfield(L, -1, "id");
        lua_remove(L, -2);
    }
    int is_integer = 0;
    const lua_Integer id = lua_tointegerx(L, -1, &is_integer);
    if (!is_integer || id < 1 || id > std::numeric_limits<int>::max())
        luaL_error(L,
                   "%s: entry %d is not a vertex id (a positive integer, or a record of "
                   "c:vertices{...}), got %s",
                   op, entry, luaL_tolstring(L, -1, nullptr));
    lua_pop(L, 1);
    return static_cast<int>(id) - 1;
}

/// c:fix(vertices) / c:unfix(vertices): returns the number of fixed vertices afterwards.
int set_fixed(lua_State* L, bool fixed) {
    ClusterHandle& h = self(L);
    const char* op = fixed ? "fix" : "unfix";
    ChangeGuard change(L, h, op);
    const std::vector<int> ids = read_vertex_ids(L, 2, op);
    return guarded(L, [&] {
        h.cluster.set_fixed(ids, fixed);
        h.stepper.reset(); // the schemes' unknowns changed
        lua_pushinteger(L, static_cast<lua_Integer>(h.cluster.fixed_vertices().size()));
        return 1;
    });
}

int l_fix(lua_State* L) {
    return set_fixed(L, true);
}
int l_unfix(lua_State* L) {
    return set_fixed(L, false);
}

int l_fixed(lua_State* L) {
    const Cluster& c = self(L).cluster;
    lua_newtable(L);
    const std::vector<int> ids = c.fixed_vertices();
    for (std::size_t k = 0; k < ids.size(); ++k) {
        lua_pushinteger(L, ids[k] + 1);
        lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
    }
    return 1;
}

/// c:grain_measures() -> {{body, volume, area, mean_width, line_length}, ...}
int l_grain_measures(lua_State* L) {
    const Cluster& c = self(L).cluster;
    return guarded(L, [&] {
        const std::vector<GrainMeasures> g = grain_measures(c);
        lua_createtable(L, static_cast<int>(g.size()), 0);
        for (std::size_t b = 0; b < g.size(); ++b) {
            lua_createtable(L, 0, 5);
            set_integer(L, "body", static_cast<lua_Integer>(b + 1));
            set_number(L, "volume", g[b].volume);
            set_number(L, "area", g[b].area);
            set_number(L, "mean_width", g[b].mean_width);
            set_number(L, "line_length", g[b].line_length);
            lua_rawseti(L, -2, static_cast<lua_Integer>(b + 1));
        }
        return 1;
    });
}

/// c:film_angles() -> {{vertex, surfaces = {a, b, c}, angles = {.., .., ..}, young_error,
/// force_imbalance}, ...}: the report's film angles vertex by vertex (geometry.h
/// triple_line_vertex_angles); angles[i] faces surfaces[i].
int l_film_angles(lua_State* L) {
    const Cluster& c = self(L).cluster;
    return guarded(L, [&] {
        const std::vector<LineVertexAngles> all = triple_line_vertex_angles(c);
        lua_createtable(L, static_cast<int>(all.size()), 0);
        for (std::size_t k = 0; k < all.size(); ++k) {
            const LineVertexAngles& a = all[k];
            lua_createtable(L, 0, 5);
            set_integer(L, "vertex", a.vertex + 1);
            set_integers(L, "surfaces", a.surfaces, 1);
            push_numbers(L, a.angles);
            lua_setfield(L, -2, "angles");
            set_number(L, "young_error", a.young_error);
            set_number(L, "force_imbalance", a.force_imbalance);
            lua_rawseti(L, -2, static_cast<lua_Integer>(k + 1));
        }
        return 1;
    });
}

const luaL_Reg methods[] = {
    {"vertices", l_vertices},     {"facets", l_facets}, {"edges", l_edges},
    {"set_vertex", l_set_vertex}, {"fix", l_fix},       {"unfix", l_unfix},
    {"fixed", l_fixed},           {"grain_measures", l_grain_measures},
    {"film_angles", l_film_angles},
    {nullptr, nullptr},
};

} // namespace

std::vector<int> read_vertex_ids(lua_State* L, int idx, const char* op) {
    idx = lua_absindex(L, idx);
    std::vector<int> ids;
    if (lua_type(L, idx) == LUA_TNUMBER) {
        lua_pushvalue(L, idx);
        ids.push_back(pop_vertex_id(L, op, 1));
        return ids;
    }
    if (lua_type(L, idx) != LUA_TTABLE)
        luaL_error(L,
                   "%s: expected a vertex id, an array of ids or of vertex records "
                   "(c:vertices{...}), got %s",
                   op, luaL_typename(L, idx));
    const lua_Integer n = luaL_len(L, idx);
    for (lua_Integer k = 1; k <= n; ++k) {
        lua_rawgeti(L, idx, k);
        ids.push_back(pop_vertex_id(L, op, static_cast<int>(k)));
    }
    return ids;
}

void add_query_methods(lua_State* L) {
    luaL_setfuncs(L, methods, 0);
}

} // namespace froth::lua
