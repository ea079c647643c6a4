#include "bindings/luax.h"

#include "core/errors.h"
#include "core/format.h"

#include <climits>
#include <cmath>

namespace froth::lua {

Eigen::Vector3d read_xyz(lua_State* L, int idx, const char* message) {
    Eigen::Vector3d x;
    if (lua_istable(L, idx)) {
        for (int d = 0; d < 3; ++d) {
            if (lua_rawgeti(L, idx, d + 1) != LUA_TNUMBER) luaL_error(L, "%s", message);
            x[d] = lua_tonumber(L, -1);
            lua_pop(L, 1);
        }
    } else {
        for (int d = 0; d < 3; ++d)
            x[d] = luaL_checknumber(L, idx + d);
    }
    return x;
}

int check_id(lua_State* L, int idx, int n, const char* kind, const char* kinds) {
    const lua_Integer i = luaL_checkinteger(L, idx);
    if (i < 1 || i > n)
        luaL_error(L, "%s %I does not exist (the cluster has %s 1..%d)", kind,
                   static_cast<LUAI_UACINT>(i), kinds, n);
    return static_cast<int>(i - 1);
}

Options::Options(lua_State* L, int idx, const char* op, bool optional)
    : L_(L), idx_(lua_absindex(L, idx)), op_(op) {
    if (optional && lua_isnoneornil(L, idx_)) {
        if (lua_gettop(L) < idx_) lua_settop(L, idx_);
        lua_newtable(L);
        lua_replace(L, idx_);
    }
    if (!lua_istable(L, idx_))
        luaL_error(L, "%s: expected an option table {...}, got %s", op_, luaL_typename(L, idx_));
    lua_newtable(L);
    known_ = lua_gettop(L);
}

int Options::type_of(const char* key) {
    lua_pushboolean(L_, 1);
    lua_setfield(L_, known_, key);
    const int t = lua_getfield(L_, idx_, key);
    lua_pop(L_, 1);
    return t;
}

bool Options::has(const char* key) { return type_of(key) != LUA_TNIL; }

void Options::error(const char* key, const char* what) {
    luaL_error(L_, "%s: option '%s' %s", op_, key, what);
    std::abort(); // not reached: luaL_error throws
}

double Options::number(const char* key) {
    if (type_of(key) == LUA_TNIL) error(key, "is required");
    return number(key, 0.0);
}

double Options::number(const char* key, double fallback) {
    const int t = type_of(key);
    if (t == LUA_TNIL) return fallback;
    lua_getfield(L_, idx_, key);
    int ok = 0;
    const double v = lua_tonumberx(L_, -1, &ok);
    lua_pop(L_, 1);
    if (!ok || t != LUA_TNUMBER) error(key, "must be a number");
    return v;
}

long long Options::integer(const char* key) {
    if (type_of(key) == LUA_TNIL) error(key, "is required");
    return integer(key, 0);
}

long long Options::integer(const char* key, long long fallback) {
    if (type_of(key) == LUA_TNIL) return fallback;
    lua_getfield(L_, idx_, key);
    int ok = 0;
    const lua_Integer v = lua_tointegerx(L_, -1, &ok);
    lua_pop(L_, 1);
    if (!ok) error(key, "must be an integer");
    if (v < INT_MIN || v > INT_MAX) error(key, "is out of range");
    return v;
}

std::string Options::string(const char* key) {
    if (type_of(key) == LUA_TNIL) error(key, "is required");
    return string(key, "");
}

std::string Options::string(const char* key, const char* fallback) {
    const int t = type_of(key);
    if (t == LUA_TNIL) return fallback;
    if (t != LUA_TSTRING) error(key, "must be a string");
    lua_getfield(L_, idx_, key);
    std::string s = lua_tostring(L_, -1);
    lua_pop(L_, 1);
    return s;
}

bool Options::boolean(const char* key, bool fallback) {
    const int t = type_of(key);
    if (t == LUA_TNIL) return fallback;
    if (t != LUA_TBOOLEAN) error(key, "must be true or false");
    lua_getfield(L_, idx_, key);
    const bool b = lua_toboolean(L_, -1);
    lua_pop(L_, 1);
    return b;
}

int Options::push(const char* key) {
    type_of(key);
    return lua_getfield(L_, idx_, key);
}

void Options::finish() {
    lua_pushnil(L_);
    while (lua_next(L_, idx_)) {
        lua_pop(L_, 1);
        if (lua_type(L_, -1) != LUA_TSTRING) luaL_error(L_, "%s: option keys must be names", op_);
        lua_pushvalue(L_, -1);
        if (lua_rawget(L_, known_) == LUA_TNIL)
            luaL_error(L_, "%s: unknown option '%s'", op_, lua_tostring(L_, -2));
        lua_pop(L_, 1);
    }
    lua_remove(L_, known_);
}

void register_type(lua_State* L, const char* type_name, const luaL_Reg* methods,
                   lua_CFunction gc, lua_CFunction tostring) {
    if (!luaL_newmetatable(L, type_name)) {
        lua_pop(L, 1);
        return;
    }
    lua_newtable(L);
    luaL_setfuncs(L, methods, 0);
    lua_setfield(L, -2, "__index");
    lua_pushcfunction(L, gc);
    lua_setfield(L, -2, "__gc");
    lua_pushcfunction(L, tostring);
    lua_setfield(L, -2, "__tostring");
    lua_pushstring(L, type_name);
    lua_setfield(L, -2, "__metatable");
    lua_pop(L, 1);
}

LuaFunction::LuaFunction(lua_State* L, int idx, std::string owner, std::string what)
    : owner_(std::move(owner)), what_(std::move(what)) {
    lua_rawgeti(L, LUA_REGISTRYINDEX, LUA_RIDX_MAINTHREAD);
    L_ = lua_tothread(L, -1);
    lua_pop(L, 1);
    lua_pushvalue(L, idx);
    ref_ = luaL_ref(L, LUA_REGISTRYINDEX);
}

LuaFunction::~LuaFunction() { luaL_unref(L_, LUA_REGISTRYINDEX, ref_); }

std::vector<double> LuaFunction::call(double x, double y, double z, int n) const {
    const int top = lua_gettop(L_);
    lua_rawgeti(L_, LUA_REGISTRYINDEX, ref_);
    lua_pushnumber(L_, x), lua_pushnumber(L_, y), lua_pushnumber(L_, z);
    std::string failure;
    if (lua_pcall(L_, 3, n, 0) != LUA_OK) {
        const char* msg = lua_tostring(L_, -1);
        failure = msg ? msg : "(error object is not a string)";
    }
    std::vector<double> out(n);
    for (int k = 0; k < n && failure.empty(); ++k) {
        if (lua_type(L_, top + 1 + k) != LUA_TNUMBER)
            failure = std::string("returned ") + luaL_typename(L_, top + 1 + k) +
                      " where a number was expected";
        out[k] = lua_tonumber(L_, top + 1 + k);
    }
    lua_settop(L_, top);
    if (!failure.empty())
        throw InvalidInput(owner_ + ": " + what_ + "(" + fmt(x) + ", " + fmt(y) + ", " + fmt(z) +
                           ") failed: " + failure);
    return out;
}

Eigen::Vector3d vector_option(lua_State* L, Options& o, const char* key,
                              const Eigen::Vector3d& fallback) {
    const int t = o.push(key);
    Eigen::Vector3d v = fallback;
    if (t != LUA_TNIL) {
        if (t != LUA_TTABLE || luaL_len(L, -1) != 3) o.error(key, "must be {x, y, z}");
        for (int d = 0; d < 3; ++d) {
            if (lua_rawgeti(L, -1, d + 1) != LUA_TNUMBER) o.error(key, "must be {x, y, z}");
            v[d] = lua_tonumber(L, -1);
            lua_pop(L, 1);
        }
    }
    lua_pop(L, 1);
    return v;
}

} // namespace froth::lua
