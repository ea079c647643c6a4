#pragma once
/// The froth.Cluster userdata: a cluster together with its time stepper (which caches the
/// cluster's sparsity patterns and symbolic factorisations).

#include "flows/stepper.h"
#include "run/evolve.h"

#include <vector>

struct lua_State;

namespace froth::lua {

struct ClusterHandle {
    Cluster cluster;
    TimeStepper stepper;
    /// What c:evolve{transitions = true} leaves for its next call (run/evolve.h).
    TransitionMemory transitions;
    /// Re-entrancy (docs/lua_api.md, "Callbacks"): the call now changing the cluster
    /// (c:step, c:evolve, c:minimize, c:set_sigma, ...) and the number of queries running a
    /// Lua callback (a wall function in c:volumes). Callbacks may read the cluster, never
    /// change it: a change while either is set is a Lua error.
    const char* changing = nullptr;
    int querying = 0;
    explicit ClusterHandle(Cluster c) : cluster(std::move(c)) {}
    /// c:clone(): the cluster, the stepper's whole state and the transitions' memory, so the
    /// copy steps exactly as the original would; not the re-entrancy marks.
    ClusterHandle(const ClusterHandle& o)
        : cluster(o.cluster), stepper(o.stepper), transitions(o.transitions) {}
};

inline constexpr const char* kClusterType = "froth.Cluster";

/// Pushes a run's transitions as the list evolve and minimize return as `events`.
void push_transition_events(lua_State* L, const std::vector<TransitionEvent>& events);

/// The froth.Cluster in argument idx (a Lua error if it is not one or was destroyed).
ClusterHandle& check_cluster(lua_State* L, int idx);

/// Held by a method that changes the cluster (`op`, e.g. "step") for its whole run; raises a
/// Lua error naming op and the running call if the cluster is being changed or queried.
class ChangeGuard {
  public:
    ChangeGuard(lua_State* L, ClusterHandle& h, const char* op);
    ~ChangeGuard() { h_.changing = nullptr; }
    ChangeGuard(const ChangeGuard&) = delete;
    ChangeGuard& operator=(const ChangeGuard&) = delete;

  private:
    ClusterHandle& h_;
};

/// Held by a query that may run Lua callbacks (wall functions): changes wait for it to end.
class QueryGuard {
  public:
    explicit QueryGuard(ClusterHandle& h) : h_(h) { ++h_.querying; }
    ~QueryGuard() { --h_.querying; }
    QueryGuard(const QueryGuard&) = delete;
    QueryGuard& operator=(const QueryGuard&) = delete;

  private:
    ClusterHandle& h_;
};

/// Creates the froth.Cluster metatable (once per state).
void register_cluster_type(lua_State* L);
/// Validates spec (throws froth errors) and pushes a new froth.Cluster.
void push_cluster(lua_State* L, ClusterSpec spec);

/// beta from a number, "gamma" or a function (nx, ny, nz) -> beta at stack index idx; a Lua
/// error ("set_mobility: ...") for anything else.
Mobility read_mobility(lua_State* L, int idx);

/// Pushes report tables (shared by c:report, c:step and the evolve callback).
void push_report(lua_State* L, const Report& r);
void push_step_report(lua_State* L, const StepReport& r);

} // namespace froth::lua
