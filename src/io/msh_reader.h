#pragma once
/// froth's own reader of gmsh MSH files (ASCII 4.1, which froth and gmsh write, and ASCII 2.2).
/// It replaced gmsh::open for untrusted input: libgmsh crashes the process on malformed files
/// (issue 17: 88 of 3709 mutated files), which no Lua pcall can catch. Every count is checked
/// against the bytes left in the file before anything is allocated, every node reference and
/// number is validated, and only regular files up to max_bytes are read, so no file can crash,
/// hang or exhaust the process.

#include "mesh/cluster.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace froth {

struct MshReadLimits {
    std::uintmax_t max_bytes = std::uintmax_t(1) << 31; ///< larger files are refused (2 GiB)
};

/// Reads path (an MSH file). Only 3-node triangles become facets; other elements are skipped.
/// Surfaces: the physical surfaces in order of physical tag (all their entities merged into one
/// consistently oriented surface), or, if there are none, each surface entity with triangles in
/// order of entity tag. Bodies (MSH 4.1 only: 2.2 has no entity boundaries): the physical
/// volumes in order of tag (or, if none, each volume entity); a body's surfaces are those
/// holding an entity on the boundary of its volumes. Vertices are the nodes the triangles use,
/// numbered in increasing node tag. Sigma is 1 everywhere.
/// \throw IoError "read: cannot open 'p': ..." (missing, a directory, not a regular file, too
///        large), "read: 'p' is not a readable mesh: line N: ..." (malformed), "read: 'p' has
///        no triangles"; TopologyError if a merged surface cannot be oriented consistently.
ClusterSpec read_msh(const std::string& path, const MshReadLimits& limits = {});

/// The same for the file's contents already in memory (the fuzz driver's entry point); `name`
/// stands for the path in messages.
ClusterSpec parse_msh(std::string_view text, const std::string& name);

} // namespace froth
