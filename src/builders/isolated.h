#pragma once
/// Meshing in a child process. gmsh offers no way to stop a running mesh generation, and a
/// crash inside it (OpenCASCADE on an odd geometry) would take froth and its Lua session
/// down. Each builder therefore runs in a fork()ed child that sends the ClusterSpec back
/// through a pipe, while the parent waits, serving Ctrl-C (it kills the child: the build stops
/// at once, and nothing in the parent is half-changed) and turning a crash into an error.

#include "mesh/cluster.h"

#include <functional>
#include <string>

namespace froth {

/// The Ctrl-C flag run_isolated polls (core/interrupt.h's functions of the executable).
struct InterruptFlag {
    int (*requests)() noexcept;
    bool (*consume)() noexcept;
};
/// Sets the flag to poll; by default this module's own copy of core/interrupt.h.
void use_interrupt_flag(const InterruptFlag& flag);

/// Runs build() in a child process and returns its result (vertices, surfaces with sigma,
/// bodies; walls are not transferred). froth errors thrown by build() are rethrown in the
/// parent with their type and message.
/// \throw Interrupted "<op>: interrupted (Ctrl-C) while gmsh was meshing; nothing was built"
/// \throw GeometryError "<op>: gmsh crashed while meshing (signal 11: ...)"
ClusterSpec run_isolated(const std::string& op, const std::function<ClusterSpec()>& build);

} // namespace froth
