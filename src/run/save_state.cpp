// State files of a run: the cluster, the stepper's history and the transitions' memory
// (run/evolve.h save_state; the format is io/state_file.h's).
#include "core/errors.h"
#include "io/state_file.h"
#include "run/evolve.h"

namespace froth {

std::vector<NamedValues> save_transition_memory(const TransitionMemory& memory) {
    std::vector<NamedValues> out;
    if (!memory.junctions) return out;
    memory.junctions->save(out);
    out.push_back({"transitions.run",
                   {memory.longest_edge, memory.transitions_made ? 1.0 : 0.0, memory.tau_scale}});
    return out;
}

TransitionMemory restore_transition_memory(const std::vector<NamedValues>& arrays,
                                           const Cluster& c) {
    TransitionMemory m;
    m.junctions = JunctionTransitions::restore(arrays, c.n_bodies());
    const std::vector<double>* run = find_named(arrays, "transitions.run");
    if (!m.junctions && !run) return m;
    if (!m.junctions || !run || run->size() != 3 || !((*run)[0] >= 0 && (*run)[0] < 1e300) ||
        ((*run)[1] != 0 && (*run)[1] != 1) || !((*run)[2] > 0 && (*run)[2] <= 1))
        throw InvalidInput("transition memory: transitions.run must come with junctions.scalars "
                           "and hold the longest edge, 0 or 1 and a tau scale in (0, 1]");
    m.longest_edge = (*run)[0];
    m.transitions_made = (*run)[1] == 1;
    m.tau_scale = (*run)[2];
    return m;
}

void save_state(const std::string& path, const Cluster& c, TimeStepper& stepper,
                const TransitionMemory* memory) {
    ClusterState s = capture_state(c, stepper.history(c));
    if (memory) s.transitions = save_transition_memory(*memory);
    write_state_file(path, s);
    stepper.drop_factorizations();
}

} // namespace froth
