// Wulff shapes and Frank diagrams from Lua: each builds a one-body froth.Cluster (so c:write,
// c:volumes, c:energy work on it), and cahn_hoffmann_check measures a convex cluster against
// the Wulff shape (wulff/wulff.h says what each number means).
#include "bindings/lua_wulff.h"

#include "bindings/lua_anisotropy.h"
#include "bindings/lua_cluster.h"
#include "bindings/luax.h"
#include "wulff/wulff.h"

namespace froth::lua {
namespace {

// froth.wulff_shape(gamma, {subdivisions = k | directions = n, scale = r, facet_directions})
int l_wulff_shape(lua_State* L) {
    const auto gamma = check_anisotropy(L, 1, "wulff_shape");
    Options o(L, 2, "wulff_shape", true);
    WulffOptions w;
    if (o.has("directions")) {
        if (o.has("subdivisions"))
            o.error("directions", "and option 'subdivisions' exclude each other; give one");
        w.directions = static_cast<int>(o.integer("directions"));
    } else {
        w.subdivisions = static_cast<int>(o.integer("subdivisions", w.subdivisions));
    }
    w.scale = o.number("scale", w.scale);
    w.facet_directions = o.boolean("facet_directions", w.facet_directions);
    o.finish();
    return guarded(L, [&] {
        push_cluster(L, wulff_shape(*gamma, w));
        return 1;
    });
}

// froth.frank_diagram(gamma, {subdivisions = k})
int l_frank_diagram(lua_State* L) {
    const auto gamma = check_anisotropy(L, 1, "frank_diagram");
    Options o(L, 2, "frank_diagram", true);
    const int k = static_cast<int>(o.integer("subdivisions", 4));
    o.finish();
    return guarded(L, [&] {
        push_cluster(L, frank_diagram(*gamma, k));
        return 1;
    });
}

// froth.cahn_hoffmann_check(gamma, cluster, {scale = r, samples = n}) -> table
int l_cahn_hoffmann_check(lua_State* L) {
    const auto gamma = check_anisotropy(L, 1, "cahn_hoffmann_check");
    const Cluster& c = check<ClusterHandle>(L, 2, kClusterType).cluster;
    Options o(L, 3, "cahn_hoffmann_check", true);
    const double scale = o.number("scale", 1.0);
    const int samples = static_cast<int>(o.integer("samples", 1000));
    o.finish();
    std::vector<Tri> triangles;
    for (const Surface& s : c.surfaces())
        triangles.insert(triangles.end(), s.triangles.begin(), s.triangles.end());
    return guarded(L, [&] {
        const CahnHoffmannCheck r =
            cahn_hoffmann_check(*gamma, c.positions(), triangles, scale, samples);
        lua_createtable(L, 0, 5);
        set_number(L, "max_distance", r.max_distance);
        set_number(L, "max_outside", r.max_outside);
        set_number(L, "max_support_error", r.max_support_error);
        set_number(L, "energy_defect", r.energy_defect);
        set_integer(L, "samples", r.samples);
        return 1;
    });
}

const luaL_Reg functions[] = {
    {"wulff_shape", l_wulff_shape},
    {"frank_diagram", l_frank_diagram},
    {"cahn_hoffmann_check", l_cahn_hoffmann_check},
    {nullptr, nullptr},
};

} // namespace

void add_wulff_functions(lua_State* L) {
    luaL_setfuncs(L, functions, 0);
}

} // namespace froth::lua
