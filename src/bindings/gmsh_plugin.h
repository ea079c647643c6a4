#pragma once
/// Loads the gmsh builders plugin (builders/plugin.h) on first use.

#include "builders/plugin.h"

namespace froth::lua {

/// The builders of libfroth_gmsh.so, loaded once: from $FROTH_GMSH_PLUGIN if set, else beside
/// the froth executable, else from the build tree the executable was built in.
/// \throw IoError naming the paths tried and dlopen's reason if none loads.
const GmshBuilders& gmsh_builders();

} // namespace froth::lua
