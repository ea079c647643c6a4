// froth.Cluster methods for statics: equilibria at fixed volumes, pressures, target volumes.
#include "bindings/lua_statics.h"

#include "bindings/lua_cluster.h"
#include "bindings/luax.h"
#include "flows/minimize.h"
#include "run/minimize_transitions.h"
#include "mesh/transitions.h"

#include <algorithm>
#include <cmath>

namespace froth::lua {
namespace {

ClusterHandle& self(lua_State* L) { return check_cluster(L, 1); }

/// minimize's result table; with transitions also rounds, events and the upkeep counts.
void push_minimize_result(lua_State* L, const MinimizeResult& r,
                          const TransitionMinimizeResult* t) {
    lua_createtable(L, 0, 14);
    set_number(L, "energy", r.energy);
    push_numbers(L, r.volumes);
    lua_setfield(L, -2, "volumes");
    push_numbers(L, r.pressures);
    lua_setfield(L, -2, "pressures");
    set_number(L, "residual", r.residual);
    set_number(L, "volume_error", r.volume_error);
    set_integer(L, "iterations", r.iterations);
    set_integer(L, "rejected", r.rejected);
    set_integer(L, "hessian_steps", r.hessian_steps);
    set_number(L, "wall_s", r.wall_seconds);
    lua_pushboolean(L, r.converged);
    lua_setfield(L, -2, "converged");
    lua_pushstring(L, r.stop_reason.c_str());
    lua_setfield(L, -2, "stop_reason");
    if (!t) return;
    set_integer(L, "rounds", t->rounds);
    set_integer(L, "collapsed_edges", t->collapsed_edges);
    set_integer(L, "flipped_edges", t->flipped_edges);
    set_integer(L, "relaxed_vertices", t->relaxed_vertices);
    set_integer(L, "deferred", t->deferred);
    push_transition_events(L, t->events);
    lua_setfield(L, -2, "events");
}

/// c:minimize{tol, max_iterations, tau_start, tau_growth, tau_max, volume_tol, settle,
/// settle_window, hessian, hessian_below, transitions, min_line_fraction}
int l_minimize(lua_State* L) {
    ClusterHandle& h = self(L);
    ChangeGuard change(L, h, "minimize");
    Options o(L, 2, "minimize", true);
    TransitionMinimizeOptions t;
    MinimizeOptions& m = t.minimize;
    m.tol = o.number("tol", m.tol);
    m.max_iterations = static_cast<int>(o.integer("max_iterations", m.max_iterations));
    m.tau_start = o.number("tau_start", m.tau_start);
    m.tau_growth = o.number("tau_growth", m.tau_growth);
    m.tau_max = o.number("tau_max", m.tau_max);
    m.volume_tol = o.number("volume_tol", m.volume_tol);
    m.settle = o.number("settle", m.settle);
    m.settle_window = static_cast<int>(o.integer("settle_window", m.settle_window));
    m.hessian = o.boolean("hessian", m.hessian);
    m.hessian_below = o.number("hessian_below", m.hessian_below);
    const bool transitions = o.boolean("transitions", false);
    t.min_line_fraction = o.number("min_line_fraction", t.min_line_fraction);
    if (!(t.min_line_fraction > 0 && t.min_line_fraction < 1))
        o.error("min_line_fraction", "must lie in (0, 1)");
    o.finish();
    return guarded(L, [&] {
        if (!transitions) {
            push_minimize_result(L, minimize(h.cluster, m), nullptr);
            return 1;
        }
        h.stepper.reset(); // transitions change the mesh
        const TransitionMinimizeResult r = minimize_with_transitions(h.cluster, t);
        push_minimize_result(L, r.result, &r);
        return 1;
    });
}

/// c:pressures() -> {p_1, ..., p_n}, residual
int l_pressures(lua_State* L) {
    ClusterHandle& h = self(L);
    const Cluster& c = h.cluster;
    QueryGuard query(h);
    return guarded(L, [&] {
        const EquilibriumState s = equilibrium_state(c);
        push_numbers(L, s.pressures);
        lua_pushnumber(L, s.residual);
        return 2;
    });
}

/// c:body_report() -> {{body, volume, target, pressure, surfaces}, ...}: Evolver's `v`.
int l_body_report(lua_State* L) {
    ClusterHandle& h = self(L);
    const Cluster& c = h.cluster;
    QueryGuard query(h);
    return guarded(L, [&] {
        const std::vector<double> volumes = body_volumes(c);
        const std::vector<double> pressures =
            c.n_bodies() > 0 ? equilibrium_state(c).pressures : std::vector<double>{};
        lua_createtable(L, c.n_bodies(), 0);
        for (int b = 0; b < c.n_bodies(); ++b) {
            lua_createtable(L, 0, 5);
            set_integer(L, "body", b + 1);
            set_number(L, "volume", volumes[b]);
            set_number(L, "target", c.target_volumes()[b]);
            set_number(L, "pressure", pressures[b]);
            std::vector<int> surfaces;
            for (const BodyFace& f : c.bodies()[b].faces) surfaces.push_back(f.sign * (f.surface + 1));
            push_integers(L, surfaces);
            lua_setfield(L, -2, "surfaces");
            lua_rawseti(L, -2, b + 1);
        }
        return 1;
    });
}

/// c:set_volume(body, v)
int l_set_volume(lua_State* L) {
    ClusterHandle& h = self(L);
    Cluster& c = h.cluster;
    ChangeGuard change(L, h, "set_volume");
    if (c.n_bodies() == 0) return luaL_error(L, "set_volume: the cluster has no bodies");
    const int b = check_id(L, 2, c.n_bodies(), "body", "bodies");
    if (lua_type(L, 3) != LUA_TNUMBER)
        return luaL_error(L, "set_volume: body %d: expected a volume (a number), got %s", b + 1,
                          luaL_typename(L, 3));
    const double v = lua_tonumber(L, 3);
    return guarded(L, [&] {
        c.set_target_volume(b, v);
        return 0;
    });
}

int l_target_volumes(lua_State* L) {
    push_numbers(L, self(L).cluster.target_volumes());
    return 1;
}

/// max_b |V_b(after) - V_b(before)| / |V_b(before)|
double volume_change(const Cluster& before, const Cluster& after) {
    const std::vector<double> v0 = body_volumes(before), v1 = body_volumes(after);
    double change = 0;
    for (std::size_t b = 0; b < v1.size(); ++b)
        change = std::max(change, std::abs(v1[b] - v0[b]) / std::abs(v0[b]));
    return change;
}

/// An upkeep's cluster (none: nothing changed) replaces h's, the stepper starting afresh; the
/// largest relative change of a body volume it made.
double take_change(ClusterHandle& h, std::optional<Cluster>& changed) {
    if (!changed) return 0;
    const double change = volume_change(h.cluster, *changed);
    h.cluster = std::move(*changed);
    h.stepper.reset();
    return change;
}

/// c:refine() -> {vertices, facets, volume_change}
int l_refine(lua_State* L) {
    ClusterHandle& h = self(L);
    ChangeGuard changing(L, h, "refine");
    return guarded(L, [&] {
        Cluster refined = refine(h.cluster); // throws before anything changes
        const double change = volume_change(h.cluster, refined);
        h.cluster = std::move(refined);
        h.stepper.reset();
        lua_createtable(L, 0, 3);
        set_integer(L, "vertices", h.cluster.n_vertices());
        set_integer(L, "facets", h.cluster.n_facets());
        set_number(L, "volume_change", change);
        return 1;
    });
}

/// Replaces h's cluster by the one a transition made, and pushes the result table with the
/// fields every transition has: {point, where, removed_vertices, energy_before, energy_after}.
void apply_transition(lua_State* L, ClusterHandle& h, Cluster changed,
                      const TransitionRecord& record) {
    const double before = energy(h.cluster), after = energy(changed);
    h.cluster = std::move(changed);
    h.stepper.reset();
    lua_createtable(L, 0, 8);
    push_numbers(L, std::vector<double>{record.point.x(), record.point.y(), record.point.z()});
    lua_setfield(L, -2, "point");
    lua_pushstring(L, record.where.c_str());
    lua_setfield(L, -2, "where");
    set_integer(L, "removed_vertices", record.removed_vertices);
    set_number(L, "energy_before", before);
    set_number(L, "energy_after", after);
}

/// c:pop_body(b) -> {body, neighbours, point, where, removed_vertices, removed_facets,
/// energy_before, energy_after}: Evolver's `pop` of a vanishing cell.
int l_pop_body(lua_State* L) {
    ClusterHandle& h = self(L);
    ChangeGuard changing(L, h, "pop_body");
    if (h.cluster.n_bodies() == 0) return luaL_error(L, "pop_body: the cluster has no bodies");
    const int b = check_id(L, 2, h.cluster.n_bodies(), "body", "bodies");
    return guarded(L, [&] {
        TransitionRecord record;
        apply_transition(L, h, pop_body(h.cluster, b, &record), record); // throws first
        set_integer(L, "body", b + 1);
        set_integer(L, "neighbours", record.neighbours);
        set_integer(L, "removed_facets", record.removed_facets);
        return 1;
    });
}

/// c:absorb_body(b [, into]) -> {body, into, neighbours, point, where, removed_vertices,
/// removed_facets, energy_before, energy_after}: a vanishing cell joins a neighbour.
int l_absorb_body(lua_State* L) {
    ClusterHandle& h = self(L);
    ChangeGuard changing(L, h, "absorb_body");
    if (h.cluster.n_bodies() == 0) return luaL_error(L, "absorb_body: the cluster has no bodies");
    const int b = check_id(L, 2, h.cluster.n_bodies(), "body", "bodies");
    const int into = lua_isnoneornil(L, 3) ? -1
                                           : check_id(L, 3, h.cluster.n_bodies(), "body", "bodies");
    return guarded(L, [&] {
        TransitionRecord record;
        apply_transition(L, h, absorb_body(h.cluster, b, into, &record), record); // throws first
        set_integer(L, "body", b + 1);
        // the bodies after b move down one
        const int into_now = record.cells[1] - (record.cells[1] > b ? 1 : 0);
        set_integer(L, "into", into_now + 1);
        set_integer(L, "neighbours", record.neighbours);
        set_integer(L, "removed_facets", record.removed_facets);
        return 1;
    });
}

/// c:t1(line) -> {line, cells, point, where, removed_vertices, energy_before, energy_after}:
/// a triple line between two quadruple points becomes a triangular film.
int l_t1(lua_State* L) {
    ClusterHandle& h = self(L);
    ChangeGuard changing(L, h, "t1");
    const int n = static_cast<int>(h.cluster.triple_lines().size());
    if (n == 0) return luaL_error(L, "t1: the cluster has no triple lines");
    const int line = check_id(L, 2, n, "triple line", "triple lines");
    return guarded(L, [&] {
        TransitionRecord record;
        apply_transition(L, h, t1_line_to_film(h.cluster, line, &record), record); // throws first
        set_integer(L, "line", line + 1);
        push_integers(L, std::vector<int>{record.cells[0] + 1, record.cells[1] + 1});
        lua_setfield(L, -2, "cells");
        return 1;
    });
}

/// c:t1_inverse(surface), c:collapse_two_sided_film(surface), c:collapse_disc_film(surface) ->
/// {surface, cells, point, where, removed_vertices, energy_before, energy_after}: a film
/// between two cells goes.
template <class Collapse>
int film_collapse(lua_State* L, const char* op, Collapse collapse) {
    ClusterHandle& h = self(L);
    ChangeGuard changing(L, h, op);
    const int film = check_id(L, 2, h.cluster.n_surfaces(), "surface", "surfaces");
    return guarded(L, [&] {
        TransitionRecord record;
        apply_transition(L, h, collapse(h.cluster, film, &record), record); // throws first
        set_integer(L, "surface", film + 1);
        push_integers(L, std::vector<int>{record.cells[0] + 1, record.cells[1] + 1});
        lua_setfield(L, -2, "cells");
        return 1;
    });
}

/// c:t1_inverse(surface): a triangular film becomes a triple line (the inverse T1).
int l_t1_inverse(lua_State* L) {
    return film_collapse(L, "t1_inverse", [](const Cluster& c, int film, TransitionRecord* r) {
        return t1_film_to_line(c, film, r);
    });
}

/// c:collapse_two_sided_film(surface): a lens between two quadruple points goes.
int l_collapse_two_sided_film(lua_State* L) {
    return film_collapse(L, "collapse_two_sided_film",
                         [](const Cluster& c, int film, TransitionRecord* r) {
                             return collapse_two_sided_film(c, film, r);
                         });
}

/// c:collapse_disc_film(surface): a disc bounded by one closed triple line goes: its loop
/// collapses, or where the mesh refuses that, caps close it.
int l_collapse_disc_film(lua_State* L) {
    return film_collapse(L, "collapse_disc_film",
                         [](const Cluster& c, int film, TransitionRecord* r) {
                             return close_disc_film(c, film, r);
                         });
}

/// c:pinch_film(u, w) -> {surface, cells, size, point, where, removed_vertices, energy_before,
/// energy_after}: the film across which the edge (u, w) joins two of its triple lines is
/// pinched there, and the cells beyond the lines meet in a two-sided film.
int l_pinch_film(lua_State* L) {
    ClusterHandle& h = self(L);
    ChangeGuard changing(L, h, "pinch_film");
    const int u = check_id(L, 2, h.cluster.n_vertices(), "vertex", "vertices");
    const int w = check_id(L, 3, h.cluster.n_vertices(), "vertex", "vertices");
    return guarded(L, [&] {
        TransitionRecord record;
        apply_transition(L, h, pinch_film(h.cluster, u, w, &record), record); // throws first
        set_integer(L, "surface", record.film + 1);
        push_integers(L, std::vector<int>{record.cells[0] + 1, record.cells[1] + 1});
        lua_setfield(L, -2, "cells");
        set_number(L, "size", record.size);
        return 1;
    });
}

/// The one length option of c:split_edges, positive and finite.
double edge_length_option(lua_State* L, const char* op, const char* key) {
    Options o(L, 2, op);
    const double length = o.number(key);
    o.finish();
    if (!(std::isfinite(length) && length > 0))
        luaL_error(L, "%s: %s must be positive and finite, got %f", op, key, length);
    return length;
}

/// c:split_edges: one length option, one upkeep pass that returns a new cluster (or none) and
/// a count; the result is {<what> = count, vertices}.
template <class Upkeep>
int edge_upkeep(lua_State* L, const char* op, const char* key, const char* what, Upkeep upkeep) {
    ClusterHandle& h = self(L);
    const double length = edge_length_option(L, op, key);
    ChangeGuard changing(L, h, op);
    return guarded(L, [&] {
        auto [cluster, count] = upkeep(h.cluster, length);
        if (cluster) {
            h.cluster = std::move(*cluster);
            h.stepper.reset();
        }
        lua_createtable(L, 0, 2);
        set_integer(L, what, count);
        set_integer(L, "vertices", h.cluster.n_vertices());
        return 1;
    });
}

/// c:collapse_edges{shorter_than, needles, valence_three} -> {collapsed, vertices}: Evolver's
/// `t`, with the short sides of needles and film vertices of three neighbours.
int l_collapse_edges(lua_State* L) {
    ClusterHandle& h = self(L);
    Options o(L, 2, "collapse_edges");
    EdgeCollapseCriteria criteria;
    const bool by_length = o.has("shorter_than"), by_angle = o.has("needles");
    const bool any = by_length || by_angle || o.has("valence_three");
    criteria.min_length = o.number("shorter_than", 0);
    criteria.needle_angle = o.number("needles", 0);
    criteria.valence_three = o.boolean("valence_three", false);
    o.finish();
    if (!any)
        return luaL_error(L, "collapse_edges: give shorter_than, needles or valence_three");
    if (by_length && !(std::isfinite(criteria.min_length) && criteria.min_length > 0))
        return luaL_error(L, "collapse_edges: shorter_than must be positive and finite, got %f",
                          criteria.min_length);
    if (by_angle && !(criteria.needle_angle > 0 && criteria.needle_angle < 60))
        return luaL_error(L, "collapse_edges: needles must be an angle in (0, 60) degrees, got %f",
                          criteria.needle_angle);
    ChangeGuard changing(L, h, "collapse_edges");
    return guarded(L, [&] {
        EdgeCollapseResult r = collapse_edges(h.cluster, criteria);
        if (r.cluster) {
            h.cluster = std::move(*r.cluster);
            h.stepper.reset();
        }
        lua_createtable(L, 0, 2);
        set_integer(L, "collapsed", r.collapsed);
        set_integer(L, "vertices", h.cluster.n_vertices());
        return 1;
    });
}

/// c:relax_flat_corners{angle} -> {moved}: flat caps' corners move in their tangent planes.
int l_relax_flat_corners(lua_State* L) {
    ClusterHandle& h = self(L);
    Options o(L, 2, "relax_flat_corners", true);
    const double angle = o.number("angle", 5);
    o.finish();
    if (!(angle > 0 && angle < 60))
        return luaL_error(L, "relax_flat_corners: angle must be in (0, 60) degrees, got %f", angle);
    ChangeGuard changing(L, h, "relax_flat_corners");
    return guarded(L, [&] {
        VertexRelaxResult r = relax_flat_corners(h.cluster, angle);
        const double change = take_change(h, r.cluster);
        lua_createtable(L, 0, 2);
        set_integer(L, "moved", r.moved);
        set_number(L, "volume_change", change);
        return 1;
    });
}

/// c:split_edges{longer_than} -> {split, vertices}: Evolver's `l`.
int l_split_edges(lua_State* L) {
    return edge_upkeep(L, "split_edges", "longer_than", "split", [](const Cluster& c, double l) {
        EdgeSplitResult r = split_long_edges(c, l);
        return std::make_pair(std::move(r.cluster), r.split);
    });
}

/// c:equiangulate{max_sweeps} -> {flips, sweeps, volume_change}
int l_equiangulate(lua_State* L) {
    ClusterHandle& h = self(L);
    Options o(L, 2, "equiangulate", true);
    const long long max_sweeps = o.integer("max_sweeps", 100);
    o.finish();
    if (max_sweeps < 1 || max_sweeps > 1000000)
        return luaL_error(L, "equiangulate: max_sweeps must be in 1..1000000, got %I",
                          static_cast<lua_Integer>(max_sweeps));
    ChangeGuard changing(L, h, "equiangulate");
    return guarded(L, [&] {
        EquiangulateResult r = equiangulate(h.cluster, static_cast<int>(max_sweeps));
        const double change = take_change(h, r.cluster);
        lua_createtable(L, 0, 3);
        set_integer(L, "flips", r.flips);
        set_integer(L, "sweeps", r.sweeps);
        set_number(L, "volume_change", change);
        return 1;
    });
}

const luaL_Reg methods[] = {
    {"refine", l_refine},
    {"equiangulate", l_equiangulate},
    {"pop_body", l_pop_body},
    {"absorb_body", l_absorb_body},
    {"t1", l_t1},
    {"t1_inverse", l_t1_inverse},
    {"collapse_two_sided_film", l_collapse_two_sided_film},
    {"collapse_disc_film", l_collapse_disc_film},
    {"pinch_film", l_pinch_film},
    {"collapse_edges", l_collapse_edges},
    {"split_edges", l_split_edges},
    {"relax_flat_corners", l_relax_flat_corners},
    {"minimize", l_minimize},
    {"pressures", l_pressures},
    {"body_report", l_body_report},
    {"set_volume", l_set_volume},
    {"target_volumes", l_target_volumes},
    {nullptr, nullptr},
};

} // namespace

void add_statics_methods(lua_State* L) { luaL_setfuncs(L, methods, 0); }

} // namespace froth::lua
