// c:save and froth.load: a cluster and its stepper's history in a state file (io/state_file.h).
#include "bindings/lua_state.h"

#include "bindings/lua_builders.h"
#include "bindings/lua_cluster.h"
#include "bindings/lua_walls.h"
#include "bindings/luax.h"
#include "core/errors.h"
#include "io/state_file.h"
#include "run/evolve.h"

#include <lua.hpp>

namespace froth::lua {
namespace {

/// c:save(path): everything the cluster, its stepper and the transitions' memory need to
/// continue (io/state_file.h).
int l_save(lua_State* L) {
    ClusterHandle& h = check_cluster(L, 1);
    const std::string path = luaL_checkstring(L, 2);
    ChangeGuard change(L, h, "save"); // it drops the stepper's factorisations
    return guarded(L, [&] {
        save_state(path, h.cluster, h.stepper, &h.transitions);
        return 0;
    });
}

/// The entry of option table `table` (a stack index) for item k (0-based) or `name`: [k + 1]
/// first, then [name]. Leaves it on the stack; nil if neither is there.
int push_entry(lua_State* L, int table, int k, const std::string& name) {
    if (lua_isnil(L, table)) {
        lua_pushnil(L);
        return LUA_TNIL;
    }
    if (lua_rawgeti(L, table, k + 1) != LUA_TNIL) return lua_type(L, -1);
    lua_pop(L, 1);
    if (name.empty()) {
        lua_pushnil(L);
        return LUA_TNIL;
    }
    return lua_getfield(L, table, name.c_str());
}

/// The user-function walls the file names, from options.walls (by 1-based wall index or name).
std::vector<WallPtr> given_walls(lua_State* L, int table, const ClusterState& s,
                                 const std::string& path) {
    std::vector<WallPtr> walls(s.walls.size());
    for (std::size_t k = 0; k < s.walls.size(); ++k) {
        const WallParameters& w = s.walls[k];
        if (w.kind != "function") continue;
        if (push_entry(L, table, static_cast<int>(k), w.name) == LUA_TNIL)
            luaL_error(L,
                       "load: '%s' has the Lua function wall '%s' (wall %d), which a file "
                       "cannot hold; give it again: froth.load(path, {walls = {['%s'] = "
                       "froth.wall{...}}})",
                       path.c_str(), w.name.c_str(), static_cast<int>(k) + 1, w.name.c_str());
        const std::string who = "load: walls['" + w.name + "']";
        const std::vector<WallPtr> given = read_walls(L, -1, who.c_str());
        if (given.size() != 1) // an array of walls (or an empty one) where one is needed
            luaL_error(L, "%s must be one wall (froth.wall{F = ...}), got %d", who.c_str(),
                       static_cast<int>(given.size()));
        walls[k] = given.front();
        if (walls[k]->parameters().kind != "function")
            luaL_error(L,
                       "%s must be a function wall (froth.wall{F = ...}) like the saved one, "
                       "got a %s",
                       who.c_str(), walls[k]->parameters().kind.c_str());
        lua_pop(L, 1);
    }
    return walls;
}

/// The function mobilities the file names, from options.mobilities (by 1-based surface id).
std::vector<Mobility> given_mobilities(lua_State* L, int table, const ClusterState& s,
                                       const std::string& path) {
    std::vector<Mobility> beta(s.materials.size());
    for (std::size_t i = 0; i < s.materials.size(); ++i) {
        if (s.materials[i].mobility != Mobility::Kind::Function) continue;
        if (push_entry(L, table, static_cast<int>(i), "") != LUA_TFUNCTION)
            luaL_error(L,
                       "load: '%s' gives surface %d a Lua function mobility, which a file "
                       "cannot hold; give it again: froth.load(path, {mobilities = {[%d] = "
                       "function(nx, ny, nz) ... end}})",
                       path.c_str(), static_cast<int>(i) + 1, static_cast<int>(i) + 1);
        beta[i] = read_mobility(L, lua_gettop(L));
        lua_pop(L, 1);
    }
    return beta;
}

/// The wire curves the file names, from options.curves (by 1-based curve index or name).
std::vector<CurvePtr> given_curves(lua_State* L, int table, const ClusterState& s,
                                   const std::string& path) {
    std::vector<CurvePtr> curves;
    for (std::size_t k = 0; k < s.curve_names.size(); ++k) {
        const std::string& name = s.curve_names[k];
        if (push_entry(L, table, static_cast<int>(k), name) != LUA_TFUNCTION)
            luaL_error(L, "load: '%s' has the wire curve '%s' (curve %d), a Lua function a file "
                          "cannot hold; give it again: froth.load(path, {curves = {['%s'] = "
                          "function(p) return x, y, z end}})",
                       path.c_str(), name.c_str(), static_cast<int>(k) + 1, name.c_str());
        curves.push_back(std::make_shared<const Curve>(curve_function(L, lua_gettop(L), name), name));
        lua_pop(L, 1);
    }
    return curves;
}

/// froth.load(path[, {walls = {...}, mobilities = {...}, curves = {...}}]): the cluster of a state file, its
/// stepper holding the saved history.
int l_load(lua_State* L) {
    const std::string path = luaL_checkstring(L, 1);
    Options o(L, 2, "load", true);
    o.has("walls"); // marks the keys as known
    o.has("mobilities");
    o.has("curves");
    o.finish(); // it pops its own bookkeeping: the options are pushed after it
    lua_getfield(L, 2, "walls");
    const int walls_table = lua_gettop(L);
    lua_getfield(L, 2, "mobilities");
    const int mobilities_table = lua_gettop(L);
    lua_getfield(L, 2, "curves");
    const int curves_table = lua_gettop(L);
    for (int t : {walls_table, mobilities_table, curves_table})
        if (!lua_isnil(L, t) && !lua_istable(L, t))
            luaL_error(L, "load: option '%s' must be a table",
                       t == walls_table ? "walls" : t == curves_table ? "curves" : "mobilities");
    ClusterState state;
    guarded(L, [&] {
        state = read_state_file(path);
        return 0;
    });
    const std::vector<WallPtr> walls = given_walls(L, walls_table, state, path);
    const std::vector<Mobility> beta = given_mobilities(L, mobilities_table, state, path);
    const std::vector<CurvePtr> curves = given_curves(L, curves_table, state, path);
    return guarded(L, [&] {
        const StateResolvers given{[&](int k, const std::string&) { return walls[k]; },
                                   [&](int i) { return beta[i]; },
                                   [&](int k, const std::string&) { return curves[k]; }};
        auto h = std::make_shared<ClusterHandle>(restore_cluster(state, given));
        h->stepper.restore_history(h->cluster, state.history);
        try {
            h->transitions = restore_transition_memory(state.transitions, h->cluster);
        } catch (const InvalidInput& e) { // the file's fault: say which file
            throw InvalidInput("load: '" + path + "': " + e.what());
        }
        push<ClusterHandle>(L, std::move(h), kClusterType);
        return 1;
    });
}

const luaL_Reg methods[] = {{"save", l_save}, {nullptr, nullptr}};
const luaL_Reg functions[] = {{"load", l_load}, {nullptr, nullptr}};

} // namespace

void add_state_methods(lua_State* L) {
    luaL_setfuncs(L, methods, 0);
}

void add_state_functions(lua_State* L) {
    luaL_setfuncs(L, functions, 0);
}

} // namespace froth::lua
