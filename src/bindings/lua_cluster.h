#pragma once
/// The froth.Cluster userdata: a cluster together with its time stepper (which caches the
/// cluster's sparsity patterns and symbolic factorisations).

#include "flows/stepper.h"

struct lua_State;

namespace froth::lua {

struct ClusterHandle {
    Cluster cluster;
    TimeStepper stepper;
    explicit ClusterHandle(Cluster c) : cluster(std::move(c)) {}
};

inline constexpr const char* kClusterType = "froth.Cluster";

/// Creates the froth.Cluster metatable (once per state).
void register_cluster_type(lua_State* L);
/// Validates spec (throws froth errors) and pushes a new froth.Cluster.
void push_cluster(lua_State* L, ClusterSpec spec);

/// Pushes report tables (shared by c:report, c:step and the evolve callback).
void push_report(lua_State* L, const Report& r);
void push_step_report(lua_State* L, const StepReport& r);

} // namespace froth::lua
