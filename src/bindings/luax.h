#pragma once
/// The binding toolkit: userdata boxes, error translation and option-table readers. Only the
/// bindings include Lua. Lua is the C++ build (lua5.4-c++), so its errors are C++ exceptions:
/// no catch-all handlers here, and we raise Lua errors only outside catch blocks (cf. LOVE's
/// luax_catchexcept).

#include <lua.hpp>

#include <Eigen/Core>

#include <cstdio>
#include <memory>
#include <new>
#include <string>
#include <utility>
#include <vector>

namespace froth::lua {

/// The userdata payload: a shared owner of one engine object.
template <class T> struct Box {
    std::shared_ptr<T> ptr;
};

/// The owner in argument idx. A destroyed box (its __gc has run: Lua calls it once when the
/// object is collected, but debug.getmetatable can reach it earlier) raises a Lua error
/// instead of touching freed memory.
template <class T> std::shared_ptr<T>& check_ptr(lua_State* L, int idx, const char* type_name) {
    auto* box = static_cast<Box<T>*>(luaL_checkudata(L, idx, type_name));
    if (!box->ptr) luaL_error(L, "%s: the object has been destroyed (its __gc ran)", type_name);
    return box->ptr;
}

template <class T> T& check(lua_State* L, int idx, const char* type_name) {
    return *check_ptr<T>(L, idx, type_name);
}

/// As check_ptr, but nullptr (no error) if argument idx is not a type_name at all.
template <class T> std::shared_ptr<T>* test_ptr(lua_State* L, int idx, const char* type_name) {
    auto* box = static_cast<Box<T>*>(luaL_testudata(L, idx, type_name));
    if (!box) return nullptr;
    if (!box->ptr) luaL_error(L, "%s: the object has been destroyed (its __gc ran)", type_name);
    return &box->ptr;
}

template <class T> void push(lua_State* L, std::shared_ptr<T> obj, const char* type_name) {
    void* mem = lua_newuserdatauv(L, sizeof(Box<T>), 0);
    auto* box = new (mem) Box<T>{};
    luaL_setmetatable(L, type_name);
    box->ptr = std::move(obj);
}

/// __gc: releases the owner and marks the box destroyed, so a second call is harmless. The
/// Box itself is left to Lua's allocator: an empty shared_ptr owns nothing.
template <class T> int collect(lua_State* L, const char* type_name) {
    static_cast<Box<T>*>(luaL_checkudata(L, 1, type_name))->ptr.reset();
    return 0;
}

/// Runs fn (which returns its number of results); a std::exception becomes a Lua error with
/// the same message, raised after the catch block has ended.
template <class Fn> int guarded(lua_State* L, Fn&& fn) {
    std::string message;
    try {
        return std::forward<Fn>(fn)();
    } catch (const std::exception& e) {
        message = e.what();
    }
    lua_pushstring(L, message.c_str());
    return lua_error(L);
}

/// Reads option tables such as c:step{flow = "sd", tau = 1e-3}. Every read marks the key as
/// known; finish() raises an error naming any key that was never read (typos must not pass).
class Options {
  public:
    /// `idx` must be a table (or absent when `optional`); `op` prefixes messages ("step").
    Options(lua_State* L, int idx, const char* op, bool optional = false);
    bool has(const char* key);
    double number(const char* key);                      ///< required
    double number(const char* key, double fallback);
    long long integer(const char* key);                  ///< required
    long long integer(const char* key, long long fallback);
    std::string string(const char* key);                 ///< required
    std::string string(const char* key, const char* fallback);
    bool boolean(const char* key, bool fallback);
    /// Pushes the field (nil if absent) and marks it known.
    int push(const char* key);
    [[noreturn]] void error(const char* key, const char* what);
    void finish();

  private:
    int type_of(const char* key);
    lua_State* L_;
    int idx_;
    const char* op_;
    int known_; ///< registry-free: a table on the stack of keys read
};

/// Pushes a Lua array of numbers.
template <class Range> void push_numbers(lua_State* L, const Range& values) {
    lua_createtable(L, static_cast<int>(std::size(values)), 0);
    int i = 0;
    for (double v : values) {
        lua_pushnumber(L, v);
        lua_rawseti(L, -2, ++i);
    }
}

/// Pushes a Lua array of integers, adding `offset` (1 turns 0-based ids into Lua ids).
template <class Range> void push_integers(lua_State* L, const Range& values, long long offset = 0) {
    lua_createtable(L, static_cast<int>(std::size(values)), 0);
    int i = 0;
    for (auto v : values) {
        lua_pushinteger(L, static_cast<lua_Integer>(v) + offset);
        lua_rawseti(L, -2, ++i);
    }
}

/// A Lua function kept in the registry for the life of an engine object (a user wall, a
/// mobility), called back from the engine on the main thread, protected: its errors become
/// InvalidInput naming the owner ("wall 'w': F(1, 2, 3) failed: ...").
class LuaFunction {
  public:
    LuaFunction(lua_State* L, int idx, std::string owner, std::string what);
    ~LuaFunction();
    LuaFunction(const LuaFunction&) = delete;
    LuaFunction& operator=(const LuaFunction&) = delete;
    /// Calls f(x, y, z) for n number results. \throw InvalidInput on a Lua error or a non-number.
    std::vector<double> call(double x, double y, double z, int n) const;

  private:
    lua_State* L_;
    int ref_;
    std::string owner_, what_;
};

/// Creates the metatable `type_name` once per state: __index = the methods, __gc, __tostring,
/// and __metatable = type_name, so getmetatable() shows the type but cannot reach __gc.
void register_type(lua_State* L, const char* type_name, const luaL_Reg* methods,
                   lua_CFunction gc, lua_CFunction tostring);

/// Checks that argument idx is an integer id in 1..n and returns it 0-based; the message
/// names the kind ("surface 7 does not exist (the cluster has surfaces 1..3)").
int check_id(lua_State* L, int idx, int n, const char* kind, const char* kinds);

/// Reads {x, y, z} (a table of three numbers) or three numbers starting at idx; a table with a
/// missing or non-number entry raises `message` (e.g. "expected a point {x, y, z}").
Eigen::Vector3d read_xyz(lua_State* L, int idx, const char* message);

/// Option `key` of o as {x, y, z} (fallback if absent); an option error otherwise.
Eigen::Vector3d vector_option(lua_State* L, Options& o, const char* key,
                              const Eigen::Vector3d& fallback);

/// t[key] = an array of integers plus offset (1 turns 0-based ids into Lua ids).
template <class Range>
void set_integers(lua_State* L, const char* key, const Range& values, long long offset = 0) {
    push_integers(L, values, offset);
    lua_setfield(L, -2, key);
}

inline void set_number(lua_State* L, const char* key, double value) {
    lua_pushnumber(L, value);
    lua_setfield(L, -2, key);
}
inline void set_integer(lua_State* L, const char* key, long long value) {
    lua_pushinteger(L, value);
    lua_setfield(L, -2, key);
}

} // namespace froth::lua
