// froth.Cluster methods: check arguments, call the engine, push results. Ids are 1-based here
// and 0-based in the engine; the conversion happens only in this file.
#include "bindings/lua_cluster.h"

#include "bindings/lua_anisotropy.h"
#include "bindings/luax.h"
#include "bindings/lua_queries.h"
#include "bindings/lua_snapshot.h"
#include "bindings/lua_state.h"
#include "bindings/lua_statics.h"
#include "bindings/lua_walls.h"
#include "core/format.h"
#include "io/write.h"
#include "run/evolve.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <unistd.h>

namespace froth::lua {

ClusterHandle& check_cluster(lua_State* L, int idx) {
    return check<ClusterHandle>(L, idx, kClusterType);
}

ChangeGuard::ChangeGuard(lua_State* L, ClusterHandle& h, const char* op) : h_(h) {
    if (h.changing)
        luaL_error(L, "%s: the cluster is busy: c:%s is running, and its callbacks (on_step, "
                      "mobility and wall functions) may read the cluster but not change it",
                   op, h.changing);
    if (h.querying > 0)
        luaL_error(L, "%s: the cluster is busy: a query is running a wall function, which may "
                      "read the cluster but not change it", op);
    h.changing = op;
}

Mobility read_mobility(lua_State* L, int idx) {
    if (lua_type(L, idx) == LUA_TNUMBER) {
        const double b = lua_tonumber(L, idx);
        Mobility m;
        guarded(L, [&] {
            m = Mobility::constant(b); // "mobility: ..." becomes "set_mobility: ..."
            return 0;
        });
        return m;
    }
    if (lua_type(L, idx) == LUA_TSTRING && std::string(lua_tostring(L, idx)) == "gamma")
        return Mobility::energy_density();
    if (lua_isfunction(L, idx)) {
        auto f = std::make_shared<LuaFunction>(L, idx, "mobility", "beta");
        return Mobility::function(
            [f](const Eigen::Vector3d& nu) { return f->call(nu[0], nu[1], nu[2], 1)[0]; },
            "function");
    }
    luaL_error(L, "set_mobility: beta must be a positive number, \"gamma\" or a function "
                  "(nx, ny, nz) -> beta, got %s", luaL_typename(L, idx));
    return {};
}

namespace {

ClusterHandle& self(lua_State* L) { return check_cluster(L, 1); }

int check_surface(lua_State* L, int idx, const Cluster& c) {
    return check_id(L, idx, c.n_surfaces(), "surface", "surfaces");
}

int l_info(lua_State* L) {
    const Cluster& c = self(L).cluster;
    lua_createtable(L, 0, 6);
    set_integer(L, "vertices", c.n_vertices());
    set_integer(L, "facets", c.n_facets());
    set_integer(L, "surfaces", c.n_surfaces());
    set_integer(L, "triple_lines", static_cast<long long>(c.triple_lines().size()));
    set_integer(L, "quadruple_points", static_cast<long long>(c.quadruple_points().size()));
    set_integer(L, "bodies", c.n_bodies());
    set_integer(L, "walls", static_cast<long long>(c.walls().size()));
    return 1;
}

int l_energy(lua_State* L) {
    lua_pushnumber(L, energy(self(L).cluster));
    return 1;
}

int l_area(lua_State* L) {
    const Cluster& c = self(L).cluster;
    const std::vector<double> areas = surface_areas(c);
    if (lua_isnoneornil(L, 2)) {
        double total = 0;
        for (double a : areas) total += a;
        lua_pushnumber(L, total);
    } else {
        lua_pushnumber(L, areas[check_surface(L, 2, c)]);
    }
    return 1;
}

int l_volumes(lua_State* L) {
    ClusterHandle& h = self(L);
    const Cluster& c = h.cluster;
    QueryGuard query(h);
    return guarded(L, [&] { // lids evaluate the walls, and a user's wall function may fail
        push_numbers(L, body_volumes(c));
        return 1;
    });
}

int l_sigma(lua_State* L) {
    const Cluster& c = self(L).cluster;
    lua_pushnumber(L, c.surface(check_surface(L, 2, c)).sigma);
    return 1;
}

int l_set_sigma(lua_State* L) {
    ClusterHandle& h = self(L);
    Cluster& c = h.cluster;
    ChangeGuard change(L, h, "set_sigma");
    const int s = check_surface(L, 2, c);
    const double value = luaL_checknumber(L, 3);
    return guarded(L, [&] {
        c.set_sigma(s, value);
        return 0;
    });
}

/// The surfaces an argument names: an id, or "all".
std::vector<int> check_surfaces(lua_State* L, int idx, const Cluster& c, const char* op) {
    if (lua_type(L, idx) == LUA_TSTRING && std::string(lua_tostring(L, idx)) == "all") {
        std::vector<int> all(c.n_surfaces());
        for (int i = 0; i < c.n_surfaces(); ++i) all[i] = i;
        return all;
    }
    if (!lua_isinteger(L, idx))
        luaL_error(L, "%s: expected a surface id or \"all\", got %s", op, luaL_typename(L, idx));
    return {check_surface(L, idx, c)};
}

/// c:set_anisotropy(surface or "all", gamma or nil): nil restores the isotropic sigma |nu|.
int l_set_anisotropy(lua_State* L) {
    ClusterHandle& h = self(L);
    Cluster& c = h.cluster;
    ChangeGuard change(L, h, "set_anisotropy");
    const std::vector<int> ids = check_surfaces(L, 2, c, "set_anisotropy");
    std::shared_ptr<const Anisotropy> gamma;
    if (!lua_isnoneornil(L, 3)) gamma = check_anisotropy(L, 3, "set_anisotropy");
    for (int i : ids) c.set_anisotropy(i, gamma);
    return 0;
}

int l_anisotropy(lua_State* L) {
    const Cluster& c = self(L).cluster;
    const auto& gamma = c.surface(check_surface(L, 2, c)).gamma;
    if (gamma) push_anisotropy(L, gamma);
    else lua_pushnil(L);
    return 1;
}

/// c:set_mobility(surface or "all", beta).
int l_set_mobility(lua_State* L) {
    ClusterHandle& h = self(L);
    Cluster& c = h.cluster;
    ChangeGuard change(L, h, "set_mobility");
    const std::vector<int> ids = check_surfaces(L, 2, c, "set_mobility");
    const Mobility beta = read_mobility(L, 3);
    for (int i : ids) c.set_mobility(i, beta);
    return 0;
}

/// c:mobility(surface): a number, "gamma" or "function".
int l_mobility(lua_State* L) {
    const Cluster& c = self(L).cluster;
    const Mobility& beta = c.surface(check_surface(L, 2, c)).beta;
    if (beta.kind() == Mobility::Kind::Constant) lua_pushnumber(L, beta.constant_value());
    else lua_pushstring(L, beta.describe().c_str());
    return 1;
}

/// c:ellipsoid_distance{a, b, c}: max over vertices of the distance to the ellipsoid with these
/// semi-axes (the Table 1 error of the seed), and the mean as a second result.
int l_ellipsoid_distance(lua_State* L) {
    const Cluster& c = self(L).cluster;
    luaL_checktype(L, 2, LUA_TTABLE);
    Vec3 axes;
    for (int d = 0; d < 3; ++d) {
        if (lua_rawgeti(L, 2, d + 1) != LUA_TNUMBER)
            luaL_error(L, "ellipsoid_distance: expected the semi-axes {a, b, c}");
        axes[d] = lua_tonumber(L, -1);
        lua_pop(L, 1);
    }
    return guarded(L, [&] {
        double max = 0, sum = 0;
        for (const Vec3& x : c.positions()) {
            const double d = distance_to_ellipsoid(x, axes);
            max = std::max(max, d), sum += d;
        }
        lua_pushnumber(L, max);
        lua_pushnumber(L, sum / c.n_vertices());
        return 2;
    });
}

int l_time(lua_State* L) {
    lua_pushnumber(L, self(L).cluster.time());
    return 1;
}

int l_vertex(lua_State* L) {
    const Cluster& c = self(L).cluster;
    const Vec3& x = c.position(check_id(L, 2, c.n_vertices(), "vertex", "vertices"));
    push_numbers(L, std::vector<double>{x[0], x[1], x[2]});
    return 1;
}

// c:period() -> {a, b, c} (the period vectors) or nil for a cluster that is not periodic
int l_period(lua_State* L) {
    const Cluster& c = self(L).cluster;
    if (!c.periodic()) {
        lua_pushnil(L);
        return 1;
    }
    lua_createtable(L, 3, 0);
    for (int k = 0; k < 3; ++k) {
        const Vec3 a = c.period().col(k);
        push_numbers(L, std::vector<double>{a[0], a[1], a[2]});
        lua_rawseti(L, -2, k + 1);
    }
    return 1;
}

int l_triple_lines(lua_State* L) {
    const Cluster& c = self(L).cluster;
    lua_createtable(L, static_cast<int>(c.triple_lines().size()), 0);
    int k = 0;
    for (const TripleLine& line : c.triple_lines()) {
        lua_createtable(L, 0, 3);
        push_integers(L, line.vertices, 1);
        lua_setfield(L, -2, "vertices");
        push_integers(L, line.surfaces, 1);
        lua_setfield(L, -2, "surfaces");
        lua_pushboolean(L, line.closed);
        lua_setfield(L, -2, "closed");
        lua_rawseti(L, -2, ++k);
    }
    return 1;
}

int l_quadruple_points(lua_State* L) {
    push_integers(L, self(L).cluster.quadruple_points(), 1);
    return 1;
}

int l_bodies(lua_State* L) {
    const Cluster& c = self(L).cluster;
    lua_createtable(L, c.n_bodies(), 0);
    for (int b = 0; b < c.n_bodies(); ++b) {
        std::vector<int> signed_ids;
        for (const BodyFace& f : c.bodies()[b].faces) signed_ids.push_back(f.sign * (f.surface + 1));
        push_integers(L, signed_ids);
        lua_rawseti(L, -2, b + 1);
    }
    return 1;
}

int l_walls(lua_State* L) {
    const Cluster& c = self(L).cluster;
    lua_createtable(L, static_cast<int>(c.walls().size()), 0);
    for (std::size_t w = 0; w < c.walls().size(); ++w) {
        push_wall(L, c.walls()[w]);
        lua_rawseti(L, -2, static_cast<lua_Integer>(w + 1));
    }
    return 1;
}

int l_report(lua_State* L) {
    ClusterHandle& h = self(L);
    const Cluster& c = h.cluster;
    QueryGuard query(h);
    return guarded(L, [&] {
        push_report(L, make_report(c));
        return 1;
    });
}

/// fixed_point = {tol, max_iterations, max_halvings} (r > 1 only); defaults when absent.
FixedPointOptions read_fixed_point(lua_State* L, Options& o, const char* what) {
    FixedPointOptions f;
    const int t = o.push("fixed_point");
    const int idx = lua_gettop(L);
    if (t == LUA_TTABLE) {
        Options fo(L, idx, what);
        f.tol = fo.number("tol", f.tol);
        f.max_iterations = static_cast<int>(fo.integer("max_iterations", f.max_iterations));
        f.max_halvings = static_cast<int>(fo.integer("max_halvings", f.max_halvings));
        fo.finish();
    } else if (t != LUA_TNIL) {
        o.error("fixed_point", "must be a table {tol, max_iterations, max_halvings}");
    }
    lua_settop(L, idx - 1);
    return f;
}

/// sd_solver = "auto" | "lu" | "blocks" (SaddleSolver).
SaddleSolver read_sd_solver(Options& o) {
    const std::string name = o.string("sd_solver", "auto");
    if (name != "auto" && name != "lu" && name != "blocks")
        o.error("sd_solver", "must be \"auto\", \"lu\" or \"blocks\"");
    return parse_saddle_solver(name);
}

/// line_relaxation = t_r (TimeStepper::set_line_relaxation).
double read_line_relaxation(Options& o) {
    const double t = o.number("line_relaxation", 0.0);
    if (!(std::isfinite(t) && t >= 0)) o.error("line_relaxation", "must be a finite time >= 0");
    return t;
}

int l_step(lua_State* L) {
    ClusterHandle& h = self(L);
    ChangeGuard change(L, h, "step");
    Options o(L, 2, "step");
    const std::string flow = o.string("flow");
    const double tau = o.number("tau");
    const bool project = o.boolean("project", false);
    const bool exact = o.boolean("exact_volumes", true);
    const long long order = o.integer("order", 1);
    if (order != 1 && order != 2) o.error("order", "must be 1 or 2");
    const double line_relaxation = read_line_relaxation(o);
    const SaddleSolver sd_solver = read_sd_solver(o);
    const FixedPointOptions fp = read_fixed_point(L, o, "step: fixed_point");
    o.finish();
    return guarded(L, [&] {
        h.stepper.set_fixed_point(fp);
        h.stepper.set_exact_volumes(exact);
        h.stepper.set_order(static_cast<int>(order));
        h.stepper.set_line_relaxation(line_relaxation);
        h.stepper.set_sd_solver(sd_solver);
        const StepReport r = h.stepper.step(h.cluster, parse_flow(flow), tau, project);
        push_step_report(L, r);
        return 1;
    });
}

/// watch = false switches the topology watch off; a table sets its thresholds.
WatchOptions read_watch_options(lua_State* L, Options& o) {
    WatchOptions w;
    const int t = o.push("watch");
    const int idx = lua_gettop(L);
    if (t == LUA_TBOOLEAN) {
        w.enabled = lua_toboolean(L, idx);
    } else if (t == LUA_TTABLE) {
        Options wo(L, idx, "evolve: watch");
        w.min_volume_fraction = wo.number("min_volume_fraction", w.min_volume_fraction);
        w.min_edge_fraction = wo.number("min_edge_fraction", w.min_edge_fraction);
        w.min_facet_angle = wo.number("min_facet_angle", w.min_facet_angle);
        w.min_line_fraction = wo.number("min_line_fraction", w.min_line_fraction);
        w.self_intersection_every =
            static_cast<int>(wo.integer("self_intersection_every", w.self_intersection_every));
        wo.finish();
    } else if (t != LUA_TNIL) {
        o.error("watch", "must be false or a table of thresholds");
    }
    lua_settop(L, idx - 1);
    return w;
}

EvolveOptions read_evolve_options(lua_State* L, Options& o) {
    EvolveOptions e;
    e.flow = parse_flow(o.string("flow")); // throws InvalidInput, caught by the caller's guard
    e.adaptive = o.push("tau") == LUA_TSTRING;
    lua_pop(L, 1);
    if (e.adaptive) {
        if (o.string("tau") != "auto") o.error("tau", "must be a number or \"auto\"");
        e.tau = o.number("tau_start", 1e-6); // the first step
        e.tol = o.number("tol", e.tol);
        e.tau_max = o.number("tau_max", 0.0);
        if (o.has("tau_max") && !(std::isfinite(e.tau_max) && e.tau_max > 0))
            o.error("tau_max", "must be positive and finite");
        if (o.has("tau_growth")) o.error("tau_growth", "has no meaning with tau = \"auto\"");
    } else {
        e.tau = o.number("tau");
        e.tau_start = o.number("tau_start", 0.0);
        e.tau_growth = o.number("tau_growth", e.tau_growth);
        if (o.has("tol") || o.has("tau_max"))
            o.error(o.has("tol") ? "tol" : "tau_max", "needs tau = \"auto\"");
    }
    if (o.has("T") && o.has("steps")) o.error("T", "and option 'steps' exclude each other");
    if (!o.has("T") && !o.has("steps")) o.error("T", "or option 'steps' is required");
    if (o.has("T")) {
        e.duration = o.number("T");
        if (!(std::isfinite(e.duration) && e.duration > 0)) o.error("T", "must be positive and finite");
    }
    e.steps = static_cast<int>(o.integer("steps", -1));
    if (o.has("steps") && e.steps < 0) o.error("steps", "must be >= 0");
    e.every = static_cast<int>(o.integer("every", 0));
    e.output = o.string("output", "");
    e.history = o.string("history", "");
    e.checkpoint = o.string("checkpoint", ""); // a stem, like history; ".froth" is added
    if (!e.checkpoint.empty() &&
        !(e.checkpoint.size() > 6 && e.checkpoint.compare(e.checkpoint.size() - 6, 6, ".froth") == 0))
        e.checkpoint += ".froth";
    e.snapshots = o.string("snapshots", "");
    o.push("snapshot");
    e.snapshot = read_snapshot_options(L, lua_gettop(L), "evolve: snapshot");
    lua_pop(L, 1);
    e.project_onto_walls = o.boolean("project", false);
    e.exact_volumes = o.boolean("exact_volumes", true);
    const long long order = o.integer("order", 1);
    if (order != 1 && order != 2) o.error("order", "must be 1 or 2");
    e.order = static_cast<int>(order);
    e.line_relaxation = read_line_relaxation(o);
    e.sd_solver = read_sd_solver(o);
    const bool progress = o.boolean("progress", isatty(STDOUT_FILENO));
    e.progress = progress && isatty(STDOUT_FILENO) ? stdout : nullptr;
    if (o.push("on_step") != LUA_TNIL && !lua_isfunction(L, -1))
        o.error("on_step", "must be a function");
    lua_pop(L, 1);
    e.watch = read_watch_options(L, o);
    e.transitions = o.boolean("transitions", true);
    e.fixed_point = read_fixed_point(L, o, "evolve: fixed_point");
    return e;
}


int l_evolve(lua_State* L) {
    ClusterHandle& h = self(L);
    ChangeGuard change(L, h, "evolve");
    Options o(L, 2, "evolve");
    EvolveOptions e;
    guarded(L, [&] { // parse_flow throws InvalidInput: it must become a Lua error
        e = read_evolve_options(L, o);
        return 0;
    });
    o.finish();
    lua_getfield(L, 2, "on_step");
    const int callback = lua_gettop(L);
    if (lua_isfunction(L, callback))
        e.on_step = [L, callback](const StepReport& r) {
            lua_pushvalue(L, callback);
            push_step_report(L, r);
            lua_call(L, 1, 1); // errors propagate as Lua errors; the cluster keeps the last step
            const bool go_on = !(lua_isboolean(L, -1) && !lua_toboolean(L, -1));
            lua_pop(L, 1);
            return go_on;
        };
    return guarded(L, [&] {
        const EvolveResult r = evolve(h.cluster, h.stepper, e, &h.transitions);
        // Ctrl-C is acknowledged where the user pressed it (Evolver does the same); scripts
        // read stop_reason = "interrupted".
        if (r.stop_reason == "interrupted")
            std::fprintf(stderr, "evolve: interrupted (Ctrl-C) at step %d, t = %s; the cluster "
                                 "keeps the state of that step\n", r.steps, fmt(r.last.t).c_str());
        push_report(L, r.last);
        set_integer(L, "steps", r.steps);
        set_number(L, "wall_s", r.wall_seconds);
        set_number(L, "solve_s", r.solve_seconds);
        set_integer(L, "factorizations", r.factorizations);
        set_number(L, "max_energy_increase", r.max_energy_increase);
        set_integer(L, "rejected_steps", r.rejected_steps);
        set_integer(L, "collapsed_edges", r.collapsed_edges);
        set_integer(L, "split_edges", r.split_edges);
        set_integer(L, "flipped_edges", r.flipped_edges);
        set_integer(L, "relaxed_vertices", r.relaxed_vertices);
        set_integer(L, "deferred", r.deferred);
        lua_pushstring(L, r.stop_reason.c_str());
        lua_setfield(L, -2, "stop_reason");
        if (r.event) {
            lua_createtable(L, 0, 3);
            lua_pushstring(L, r.event->kind.c_str());
            lua_setfield(L, -2, "kind");
            lua_pushstring(L, r.event->message.c_str());
            lua_setfield(L, -2, "message");
            set_number(L, "t", r.event->t);
            lua_setfield(L, -2, "event");
        }
        push_transition_events(L, r.events);
        lua_setfield(L, -2, "events");
        return 1;
    });
}

int l_write(lua_State* L) {
    const Cluster& c = self(L).cluster;
    const std::string path = luaL_checkstring(L, 2);
    return guarded(L, [&] {
        write_cluster(c, path, {{"mean_curvature", vertex_mean_curvature(c)}});
        return 0;
    });
}

int l_clone(lua_State* L) {
    const ClusterHandle& h = self(L);
    push<ClusterHandle>(L, std::make_shared<ClusterHandle>(h), kClusterType);
    return 1;
}

int l_tostring(lua_State* L) {
    const Cluster& c = self(L).cluster;
    lua_pushfstring(L, "froth.Cluster (%d vertices, %d facets, %d surfaces, %d triple lines, "
                       "%d quadruple points, %d bodies, t = %f)",
                    c.n_vertices(), c.n_facets(), c.n_surfaces(),
                    static_cast<int>(c.triple_lines().size()),
                    static_cast<int>(c.quadruple_points().size()), c.n_bodies(), c.time());
    return 1;
}

int l_gc(lua_State* L) {
    // Lua collects a cluster only when nothing refers to it, so a running call (which holds
    // it as argument 1) can meet its own __gc only through debug.getmetatable.
    auto* box = static_cast<Box<ClusterHandle>*>(luaL_checkudata(L, 1, kClusterType));
    if (box->ptr && (box->ptr->changing || box->ptr->querying > 0))
        return luaL_error(L, "%s: cannot destroy a cluster while a call on it is running",
                          kClusterType);
    return collect<ClusterHandle>(L, kClusterType);
}

const luaL_Reg methods[] = {
    {"info", l_info},         {"energy", l_energy},
    {"area", l_area},         {"volumes", l_volumes},
    {"sigma", l_sigma},       {"set_sigma", l_set_sigma},
    {"anisotropy", l_anisotropy}, {"set_anisotropy", l_set_anisotropy},
    {"mobility", l_mobility}, {"set_mobility", l_set_mobility},
    {"ellipsoid_distance", l_ellipsoid_distance},
    {"time", l_time},         {"vertex", l_vertex},
    {"period", l_period},
    {"triple_lines", l_triple_lines}, {"quadruple_points", l_quadruple_points},
    {"bodies", l_bodies},     {"report", l_report},
    {"walls", l_walls},
    {"step", l_step},         {"evolve", l_evolve},
    {"write", l_write},       {"clone", l_clone},
    {nullptr, nullptr},
};

} // namespace

/// evolve's `events`: {{kind, where, t, step, energy_before, energy_after; pops: body,
/// neighbours; absorbs: body, neighbours, into; T1s: line, cells; inverse T1s: surface,
/// cells}, ...}
void push_transition_events(lua_State* L, const std::vector<TransitionEvent>& events) {
    lua_createtable(L, static_cast<int>(events.size()), 0);
    for (std::size_t i = 0; i < events.size(); ++i) {
        const TransitionEvent& e = events[i];
        lua_createtable(L, 0, 8);
        lua_pushstring(L, e.kind.c_str());
        lua_setfield(L, -2, "kind");
        lua_pushstring(L, e.where.c_str());
        lua_setfield(L, -2, "where");
        set_number(L, "t", e.t);
        set_integer(L, "step", e.step);
        if (e.body >= 0) {
            set_integer(L, "body", e.body + 1);
            set_integer(L, "neighbours", e.neighbours);
            if (e.kind == "absorb body") set_integer(L, "into", e.cells[1] + 1);
        }
        if (e.line >= 0 || e.film >= 0) {
            if (e.line >= 0) set_integer(L, "line", e.line + 1);
            if (e.film >= 0) set_integer(L, "surface", e.film + 1);
            push_integers(L, std::vector<int>{e.cells[0] + 1, e.cells[1] + 1});
            lua_setfield(L, -2, "cells");
        }
        set_number(L, "energy_before", e.energy_before);
        set_number(L, "energy_after", e.energy_after);
        lua_rawseti(L, -2, static_cast<lua_Integer>(i + 1));
    }
}

/// Sets t[key] = {min, max, mean, count[, young_error, force_imbalance]}; no angles (nil, not zeros) when
/// there is nothing to measure.
void push_angles(lua_State* L, const AngleStats& a, const char* key, bool with_young) {
    if (a.count == 0) return;
    lua_createtable(L, 0, 6);
    set_number(L, "min", a.min);
    set_number(L, "max", a.max);
    set_number(L, "mean", a.mean);
    set_integer(L, "count", a.count);
    if (with_young) {
        set_number(L, "young_error", a.young_error);
        set_number(L, "force_imbalance", a.force_imbalance);
    }
    lua_setfield(L, -2, key);
}

void push_report(lua_State* L, const Report& r) {
    lua_createtable(L, 0, 12);
    set_number(L, "t", r.t);
    set_number(L, "energy", r.energy);
    push_numbers(L, r.volumes);
    lua_setfield(L, -2, "volumes");
    set_number(L, "volume_loss", r.volume_loss);
    push_angles(L, r.angles, "angles", true);
    push_angles(L, r.quadruple_angles, "quadruple_angles", false);
    lua_createtable(L, 0, 4);
    set_number(L, "min_angle", r.mesh.min_angle);
    set_number(L, "max_angle", r.mesh.max_angle);
    set_number(L, "max_edge_ratio", r.mesh.max_edge_ratio);
    set_number(L, "min_area", r.mesh.min_area);
    lua_setfield(L, -2, "mesh");
    if (r.contact_angles.count > 0) {
        lua_createtable(L, 0, 6);
        set_number(L, "min", r.contact_angles.min);
        set_number(L, "max", r.contact_angles.max);
        set_number(L, "mean", r.contact_angles.mean);
        set_integer(L, "count", r.contact_angles.count);
        set_number(L, "max_deviation", r.contact_angles.young_error);
        set_number(L, "force_imbalance", r.contact_angles.force_imbalance);
        lua_setfield(L, -2, "contact_angles");
        set_number(L, "wall_drift", r.wall_drift);
    }
}

void push_step_report(lua_State* L, const StepReport& r) {
    push_report(L, r);
    lua_pushstring(L, flow_name(r.flow));
    lua_setfield(L, -2, "flow");
    set_number(L, "tau", r.tau);
    set_number(L, "energy_before", r.energy_before);
    set_number(L, "assemble_s", r.assemble_seconds);
    set_number(L, "solve_s", r.solve_seconds);
    set_integer(L, "unknowns", r.unknowns);
    set_integer(L, "solver_iterations", r.solver_iterations);
    lua_pushboolean(L, r.refactorized);
    lua_setfield(L, -2, "refactorized");
    set_integer(L, "fixed_point_iterations", r.fixed_point_iterations);
    set_number(L, "fixed_point_change", r.fixed_point_change);
    set_integer(L, "substeps", r.substeps);
    set_integer(L, "order", r.order);
    if (r.order == 2) set_number(L, "error_estimate", r.error_estimate);
    set_integer(L, "volume_iterations", r.volume_iterations);
    if (r.volume_iterations > 0) set_number(L, "volume_error", r.volume_error);
    if (r.flow == Flow::SurfaceDiffusion) {
        lua_pushstring(L, r.saddle_blocks ? "blocks" : "lu");
        lua_setfield(L, -2, "sd_solver");
    }
}

void register_cluster_type(lua_State* L) {
    register_type(L, kClusterType, methods, l_gc, l_tostring);
    luaL_getmetatable(L, kClusterType);
    lua_getfield(L, -1, "__index");
    add_statics_methods(L);
    add_query_methods(L);
    add_state_methods(L);
    add_snapshot_methods(L);
    lua_pop(L, 2);
}

void push_cluster(lua_State* L, ClusterSpec spec) {
    auto handle = std::make_shared<ClusterHandle>(Cluster(std::move(spec)));
    push<ClusterHandle>(L, std::move(handle), kClusterType);
}

} // namespace froth::lua
