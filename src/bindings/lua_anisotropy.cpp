// froth.Anisotropy: froth.anisotropy{...} builds gamma of (1.15) from matrices G_l or from the
// angles of (1.17); froth.anisotropies holds the seed's presets. Methods evaluate gamma, gamma'
// and gamma* (1.16) at a vector.
#include "bindings/lua_anisotropy.h"

#include "bindings/luax.h"
#include "core/errors.h"
#include "core/format.h"

#include <string>

namespace froth::lua {
namespace {

using AnisotropyHandle = const Anisotropy;
using Eigen::Matrix3d;
using Eigen::Vector3d;

const Anisotropy& self(lua_State* L) { return check<AnisotropyHandle>(L, 1, kAnisotropyType); }

/// Reads {x, y, z} (a table) or three numbers starting at idx.
Vector3d read_vector(lua_State* L, int idx) {
    return read_xyz(L, idx, "anisotropy: expected a vector {x, y, z}");
}

/// The number at t[i] (1-based), or an error naming `what`.
double number_at(lua_State* L, int t, int i, const std::string& what) {
    if (lua_rawgeti(L, t, i) != LUA_TNUMBER)
        luaL_error(L, "%s: entry %d must be a number", what.c_str(), i);
    const double x = lua_tonumber(L, -1);
    lua_pop(L, 1);
    return x;
}

/// A 3x3 matrix {{a,b,c},{d,e,f},{g,h,i}} or a diagonal {a, b, c} at idx.
Matrix3d read_matrix(lua_State* L, int idx, const std::string& what) {
    idx = lua_absindex(L, idx);
    if (!lua_istable(L, idx) || luaL_len(L, idx) != 3)
        luaL_error(L, "%s must be a 3x3 table {{...},{...},{...}} or a diagonal {a, b, c}",
                   what.c_str());
    Matrix3d G = Matrix3d::Zero();
    lua_rawgeti(L, idx, 1);
    const bool diagonal = lua_type(L, -1) == LUA_TNUMBER;
    lua_pop(L, 1);
    for (int r = 0; r < 3; ++r) {
        if (diagonal) {
            G(r, r) = number_at(L, idx, r + 1, what);
            continue;
        }
        if (lua_rawgeti(L, idx, r + 1) != LUA_TTABLE || luaL_len(L, -1) != 3)
            luaL_error(L, "%s: row %d must be a table of 3 numbers", what.c_str(), r + 1);
        for (int c = 0; c < 3; ++c)
            G(r, c) = number_at(L, lua_gettop(L), c + 1, what + " row " + std::to_string(r + 1));
        lua_pop(L, 1);
    }
    return G;
}

/// One term of froth.anisotropy{...}: {G = ...} or {eps = ..., theta = {t1, t2, t3}}.
struct Term {
    Matrix3d G;
    bool from_angles = false;
    double eps = 0;
    Vector3d theta = Vector3d::Zero();
};

Term read_term(lua_State* L, int idx, int l) {
    const std::string name = "anisotropy: term " + std::to_string(l);
    Options o(L, idx, name.c_str());
    Term term;
    if (o.has("G")) {
        if (o.has("eps") || o.has("theta")) o.error("G", "excludes eps and theta");
        o.push("G");
        term.G = read_matrix(L, -1, name + ": G");
        lua_pop(L, 1);
    } else {
        term.from_angles = true;
        term.eps = o.number("eps");
        const int t = o.push("theta");
        if (t == LUA_TTABLE) term.theta = read_vector(L, lua_gettop(L));
        else if (t != LUA_TNIL) o.error("theta", "must be a table {t1, t2, t3} of angles");
        lua_pop(L, 1);
    }
    o.finish();
    return term;
}

/// froth.anisotropy{ term, term, ..., r = 1 }: (1.15) with G_l given or from (1.17).
int l_anisotropy(lua_State* L) {
    luaL_checktype(L, 1, LUA_TTABLE);
    const lua_Integer n = luaL_len(L, 1);
    std::vector<Term> terms;
    for (lua_Integer l = 1; l <= n; ++l) {
        if (lua_rawgeti(L, 1, l) != LUA_TTABLE)
            luaL_error(L, "anisotropy: term %d must be a table {G = ...} or {eps = ..., theta = ...}",
                       static_cast<int>(l));
        terms.push_back(read_term(L, -1, static_cast<int>(l)));
        lua_pop(L, 1);
    }
    // Only r may sit beside the array part.
    lua_pushnil(L);
    while (lua_next(L, 1)) {
        lua_pop(L, 1);
        if (lua_type(L, -1) == LUA_TSTRING && std::string(lua_tostring(L, -1)) == "r") continue;
        if (lua_isinteger(L, -1) && lua_tointeger(L, -1) >= 1 && lua_tointeger(L, -1) <= n) continue;
        const std::string key = luaL_tolstring(L, -1, nullptr);
        luaL_error(L, "anisotropy: unknown option '%s' (terms and r only)", key.c_str());
    }
    const int rt = lua_getfield(L, 1, "r");
    if (rt != LUA_TNIL && rt != LUA_TNUMBER)
        luaL_error(L, "anisotropy: r must be a number >= 1, got %s", luaL_typename(L, -1));
    const double r = rt == LUA_TNIL ? 1.0 : lua_tonumber(L, -1);
    lua_pop(L, 1);
    return guarded(L, [&] {
        std::vector<Matrix3d> G;
        for (const Term& t : terms)
            G.push_back(t.from_angles ? Anisotropy::from_angles(t.eps, {t.theta}).G(0) : t.G);
        push_anisotropy(L, std::make_shared<const Anisotropy>(std::move(G), r));
        return 1;
    });
}

/// Presets read {eps = ..., r = ...} where the seed's example has them.
int preset(lua_State* L, const char* name, double eps_default, bool has_r) {
    Options o(L, 1, name, true);
    const double eps = o.number("eps", eps_default);
    const double r = has_r ? o.number("r", 1.0) : 1.0;
    o.finish();
    return guarded(L, [&] {
        const std::string n = name;
        Anisotropy a = n == "l1"           ? Anisotropy::l1(eps, r)
                       : n == "hexagonal"  ? Anisotropy::hexagonal(eps)
                       : n == "fig3_left"  ? Anisotropy::fig3_left(eps)
                                           : Anisotropy::fig3_right(eps);
        push_anisotropy(L, std::make_shared<const Anisotropy>(std::move(a)));
        return 1;
    });
}

int l_isotropic(lua_State* L) {
    const double sigma = luaL_optnumber(L, 1, 1.0);
    return guarded(L, [&] {
        push_anisotropy(L, std::make_shared<const Anisotropy>(Anisotropy::isotropic(sigma)));
        return 1;
    });
}

int l_ellipsoidal(lua_State* L) {
    const Matrix3d G = read_matrix(L, 1, "ellipsoidal: G");
    return guarded(L, [&] {
        push_anisotropy(L, std::make_shared<const Anisotropy>(Anisotropy::ellipsoidal(G)));
        return 1;
    });
}

int l_l1(lua_State* L) { return preset(L, "l1", 0.1, true); }
int l_hexagonal(lua_State* L) { return preset(L, "hexagonal", 1e-2, false); }
int l_fig3_left(lua_State* L) { return preset(L, "fig3_left", 1e-2, false); }
int l_fig3_right(lua_State* L) { return preset(L, "fig3_right", 1e-2, false); }

int l_gamma(lua_State* L) {
    const Anisotropy& g = self(L);
    const Vector3d p = read_vector(L, 2);
    return guarded(L, [&] {
        lua_pushnumber(L, g.gamma(p));
        return 1;
    });
}

int l_gamma_prime(lua_State* L) {
    const Anisotropy& g = self(L);
    const Vector3d p = read_vector(L, 2);
    return guarded(L, [&] {
        const Vector3d d = g.gamma_prime(p);
        push_numbers(L, std::vector<double>{d[0], d[1], d[2]});
        return 1;
    });
}

int l_gamma_star(lua_State* L) {
    const Anisotropy& g = self(L);
    const Vector3d q = read_vector(L, 2);
    return guarded(L, [&] {
        lua_pushnumber(L, g.gamma_star(q));
        return 1;
    });
}

int l_r(lua_State* L) {
    lua_pushnumber(L, self(L).r());
    return 1;
}

int l_terms(lua_State* L) {
    const Anisotropy& g = self(L);
    lua_createtable(L, g.n_terms(), 0);
    for (int l = 0; l < g.n_terms(); ++l) {
        lua_createtable(L, 3, 0);
        for (int r = 0; r < 3; ++r) {
            push_numbers(L, std::vector<double>{g.G(l)(r, 0), g.G(l)(r, 1), g.G(l)(r, 2)});
            lua_rawseti(L, -2, r + 1);
        }
        lua_rawseti(L, -2, l + 1);
    }
    return 1;
}

int l_tostring(lua_State* L) {
    const Anisotropy& g = self(L);
    const std::string text = "froth.Anisotropy (" + std::to_string(g.n_terms()) +
                             (g.n_terms() == 1 ? " term" : " terms") + ", r = " + fmt(g.r()) +
                             (g.is_isotropic() ? ", isotropic" : "") + ")";
    lua_pushstring(L, text.c_str());
    return 1;
}

int l_gc(lua_State* L) { return collect<AnisotropyHandle>(L, kAnisotropyType); }

const luaL_Reg methods[] = {
    {"gamma", l_gamma}, {"gamma_prime", l_gamma_prime}, {"gamma_star", l_gamma_star},
    {"r", l_r},         {"terms", l_terms},             {nullptr, nullptr},
};

const luaL_Reg presets[] = {
    {"isotropic", l_isotropic}, {"ellipsoidal", l_ellipsoidal}, {"l1", l_l1},
    {"hexagonal", l_hexagonal}, {"fig3_left", l_fig3_left},     {"fig3_right", l_fig3_right},
    {nullptr, nullptr},
};

} // namespace

void register_anisotropy_type(lua_State* L) {
    register_type(L, kAnisotropyType, methods, l_gc, l_tostring);
}

void add_anisotropy_constructors(lua_State* L) {
    lua_pushcfunction(L, l_anisotropy);
    lua_setfield(L, -2, "anisotropy");
    luaL_newlib(L, presets);
    lua_setfield(L, -2, "anisotropies");
}

void push_anisotropy(lua_State* L, std::shared_ptr<const Anisotropy> gamma) {
    push<AnisotropyHandle>(L, std::move(gamma), kAnisotropyType);
}

std::shared_ptr<const Anisotropy> check_anisotropy(lua_State* L, int idx, const char* who) {
    auto* ptr = test_ptr<AnisotropyHandle>(L, idx, kAnisotropyType);
    if (!ptr)
        luaL_error(L, "%s: expected a froth.Anisotropy (from froth.anisotropy or "
                      "froth.anisotropies), got %s",
                   who, luaL_typename(L, idx));
    return *ptr;
}

} // namespace froth::lua
