// froth.Wall constructors and methods. A wall from Lua functions (froth.wall) calls back into
// Lua from the engine's steps: the functions are called protected, and their errors become
// froth errors naming the wall, so a failing F ends a step like any other bad input.
#include "bindings/lua_walls.h"

#include "bindings/luax.h"
#include "core/errors.h"
#include "core/format.h"

#include <cmath>
#include <string>

namespace froth::lua {
namespace {

using WallHandle = const Wall;

WallPtr& self_ptr(lua_State* L, int idx = 1) {
    return check_ptr<WallHandle>(L, idx, kWallType);
}

/// Reads {x, y, z} (a table) or three numbers starting at idx.
Vec3 read_point(lua_State* L, int idx) {
    return read_xyz(L, idx, "expected a point {x, y, z}");
}

int l_plane(lua_State* L) {
    Options o(L, 1, "plane", true);
    const Vec3 n = vector_option(L, o, "normal", Vec3::UnitZ());
    const double offset = o.number("offset", 0.0);
    o.finish();
    return guarded(L, [&] {
        push_wall(L, make_plane(n, offset));
        return 1;
    });
}

int l_slab(lua_State* L) {
    Options o(L, 1, "slab");
    const Vec3 n = vector_option(L, o, "normal", Vec3::UnitZ());
    const double lo = o.number("from", 0.0);
    const double hi = o.number("to");
    o.finish();
    return guarded(L, [&] {
        push_wall(L, make_slab(n, lo, hi));
        return 1;
    });
}

int l_sphere_wall(lua_State* L) {
    Options o(L, 1, "sphere_wall");
    const Vec3 c = vector_option(L, o, "center", Vec3::Zero());
    const double r = o.number("radius");
    o.finish();
    return guarded(L, [&] {
        push_wall(L, make_sphere_wall(c, r));
        return 1;
    });
}

int l_cylinder_wall(lua_State* L) {
    Options o(L, 1, "cylinder_wall");
    const Vec3 p = vector_option(L, o, "point", Vec3::Zero());
    const Vec3 a = vector_option(L, o, "axis", Vec3::UnitZ());
    const double r = o.number("radius");
    o.finish();
    return guarded(L, [&] {
        push_wall(L, make_cylinder_wall(p, a, r));
        return 1;
    });
}

int l_wall(lua_State* L) {
    Options o(L, 1, "wall");
    const std::string name = o.string("name", "user wall");
    if (o.push("F") != LUA_TFUNCTION) o.error("F", "must be a function (x, y, z) -> F");
    auto F = std::make_shared<LuaFunction>(L, -1, "wall '" + name + "'", "F");
    lua_pop(L, 1);
    std::shared_ptr<LuaFunction> grad;
    const int t = o.push("gradient");
    if (t == LUA_TFUNCTION)
        grad = std::make_shared<LuaFunction>(L, -1, "wall '" + name + "'", "gradient");
    else if (t != LUA_TNIL) o.error("gradient", "must be a function (x, y, z) -> gx, gy, gz");
    lua_pop(L, 1);
    const double step = o.number("fd_step", 1e-6);
    o.finish();
    std::function<Vec3(const Vec3&)> g;
    if (grad) g = [grad](const Vec3& x) {
        const std::vector<double> v = grad->call(x[0], x[1], x[2], 3);
        return Vec3(v[0], v[1], v[2]);
    };
    return guarded(L, [&] {
        push_wall(L, make_function_wall([F](const Vec3& x) { return F->call(x[0], x[1], x[2], 1)[0]; }, g,
                                        name, step));
        return 1;
    });
}

int l_value(lua_State* L) {
    const WallPtr& w = self_ptr(L);
    const Vec3 x = read_point(L, 2);
    return guarded(L, [&] {
        lua_pushnumber(L, w->value(x));
        return 1;
    });
}

int l_gradient(lua_State* L) {
    const WallPtr& w = self_ptr(L);
    const Vec3 x = read_point(L, 2);
    return guarded(L, [&] {
        const Vec3 g = w->gradient(x);
        push_numbers(L, std::vector<double>{g[0], g[1], g[2]});
        return 1;
    });
}

int l_distance(lua_State* L) {
    const WallPtr& w = self_ptr(L);
    const Vec3 x = read_point(L, 2);
    return guarded(L, [&] {
        lua_pushnumber(L, w->distance(x));
        return 1;
    });
}

int l_project(lua_State* L) {
    const WallPtr& w = self_ptr(L);
    const Vec3 x = read_point(L, 2);
    return guarded(L, [&] {
        const Vec3 p = w->project(x);
        push_numbers(L, std::vector<double>{p[0], p[1], p[2]});
        return 1;
    });
}

int l_tostring(lua_State* L) {
    const std::string text = "froth.Wall (" + self_ptr(L)->describe() + ")";
    lua_pushstring(L, text.c_str());
    return 1;
}

int l_gc(lua_State* L) { return collect<WallHandle>(L, kWallType); }

const luaL_Reg methods[] = {
    {"F", l_value},         {"gradient", l_gradient}, {"distance", l_distance},
    {"project", l_project}, {nullptr, nullptr},
};

const luaL_Reg constructors[] = {
    {"plane", l_plane},
    {"slab", l_slab},
    {"sphere_wall", l_sphere_wall},
    {"cylinder_wall", l_cylinder_wall},
    {"wall", l_wall},
    {nullptr, nullptr},
};

} // namespace

void register_wall_type(lua_State* L) { register_type(L, kWallType, methods, l_gc, l_tostring); }

void add_wall_constructors(lua_State* L) { luaL_setfuncs(L, constructors, 0); }

void push_wall(lua_State* L, WallPtr wall) {
    push<WallHandle>(L, std::move(wall), kWallType);
}

std::vector<WallPtr> read_walls(lua_State* L, int idx, const char* who) {
    std::vector<WallPtr> walls;
    idx = lua_absindex(L, idx);
    if (lua_isnil(L, idx)) return walls;
    if (WallPtr* w = test_ptr<WallHandle>(L, idx, kWallType)) {
        walls.push_back(*w);
        return walls;
    }
    if (!lua_istable(L, idx))
        luaL_error(L, "%s must be a wall or an array of walls (froth.plane{...}, ...), got %s", who,
                   luaL_typename(L, idx));
    for (int k = 1; k <= luaL_len(L, idx); ++k) {
        lua_rawgeti(L, idx, k);
        WallPtr* w = test_ptr<WallHandle>(L, -1, kWallType);
        if (!w)
            luaL_error(L, "%s[%d] must be a wall (froth.plane{...}, ...), got %s", who, k,
                       luaL_typename(L, -1));
        walls.push_back(*w);
        lua_pop(L, 1);
    }
    return walls;
}

} // namespace froth::lua
