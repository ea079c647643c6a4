#pragma once
/// froth's state files (c:save, froth.load; `.froth`): everything a cluster and its stepper need
/// to continue a run bit for bit: positions, surfaces with their tensions, anisotropies and
/// mobilities, bodies, walls (presets by their numbers, user functions by name), fixed
/// vertices, time, the reference area and volumes, the target volumes, the schemes' history
/// (flows/stepper.h TimeStepper::history) and the transitions' memory (run/evolve.h). Numbers
/// are written in the shortest form that reads back to the same double; ids are 1-based as
/// everywhere users see them.
///
/// The format is versioned text (first line "froth-state 4") ending in an FNV-1a 64 checksum of
/// everything before it: a truncated or edited file is refused before it is parsed, a file of a
/// newer format is refused by its version, and the parser validates every count and id as the
/// MSH reader does (io/tokens.h), so no file can crash or exhaust the process.

#include "mesh/cluster.h"

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace froth {

/// 2 adds the bodies' volconst (format 1 files are read as bodies without one); 3 the period and
/// facet offsets of a periodic cluster (formats 1 and 2 are read as clusters in space); 4 the
/// memory of the transitions runs make (formats 1-3 are read without one: a fresh memory).
inline constexpr int kStateFormatVersion = 4;

/// The saved state, between a Cluster and its file.
struct ClusterState {
    /// Vertices, surfaces (triangles, sigma), bodies (surface ids), the wall attachments, fixed
    /// vertices, the curve points; no walls and no curves.
    ClusterSpec spec;
    std::vector<WallParameters> walls;
    std::vector<std::string> curve_names; ///< wire curves (Lua functions: given again by name)
    struct Material {
        std::vector<Eigen::Matrix3d> G; ///< empty: isotropic
        double r = 1.0;
        Mobility::Kind mobility = Mobility::Kind::Constant;
        double mobility_value = 1.0; ///< Constant only
    };
    std::vector<Material> materials; ///< one per surface
    double time = 0, initial_area = 0;
    std::vector<double> initial_volumes, target_volumes;
    std::vector<NamedValues> history;
    /// What evolve with transitions remembers between calls (run/evolve.h TransitionMemory),
    /// as named arrays; empty: none.
    std::vector<NamedValues> transitions;
};

/// The state of c, with the stepper's history. \throw InvalidInput if a user wall's name holds
/// a line break (it could not be read back).
ClusterState capture_state(const Cluster& c, std::vector<NamedValues> history);

/// What a file names but cannot hold: the user-function walls (by their 0-based index in the
/// cluster's wall list and their name), the function mobilities (by 0-based surface id) and
/// the wire curves (by index and name).
/// Each may throw InvalidInput saying what is missing.
struct StateResolvers {
    std::function<WallPtr(int index, const std::string& name)> wall;
    std::function<Mobility(int surface)> mobility;
    std::function<CurvePtr(int index, const std::string& name)> curve;
};

/// The cluster of a saved state (its history stays in the state for the stepper).
/// \throw what the Cluster constructor throws, InvalidInput from the resolvers or for saved
///        values that no cluster accepts.
Cluster restore_cluster(const ClusterState& state, const StateResolvers& resolvers);

/// Writes state to path atomically (io/text_file.h). \throw IoError
void write_state_file(const std::string& path, const ClusterState& state);

/// Reads a state file: a regular file of at most max_bytes.
/// \throw IoError "load: cannot open 'p': ...", "load: 'p' is not a froth state file ...",
///        "load: 'p' was written by a newer froth (format N; this one reads 2)",
///        "load: 'p' is truncated or corrupted (checksum ...)", "load: 'p': line N: ...".
ClusterState read_state_file(const std::string& path, std::uintmax_t max_bytes = std::uintmax_t(1)
                                                                                 << 31);
/// The same for contents in memory (the fuzz driver's entry point); `name` stands for the path.
ClusterState parse_state_file(std::string_view text, const std::string& name);

/// The checksum line's value for a file whose text before "checksum " is `body` (16 hex
/// digits); the fuzz driver re-seals mutated files with it to reach the parser.
std::string state_checksum(std::string_view body);

} // namespace froth
