#pragma once
/// The gmsh builders as a plugin. Debian's libgmsh pulls in about 90 shared libraries
/// (OpenCASCADE, FLTK, ...) whose loading and static initialisation cost 0.13 s, most of
/// froth's start-up; the froth executable therefore does not link gmsh but loads
/// libfroth_gmsh.so (this module built as a shared object) the first time a script meshes
/// something. The plugin exports one C symbol, froth_gmsh_builders, returning this table.

#include "builders/fragment.h"
#include "builders/gmsh_builder.h"
#include "builders/isolated.h"

namespace froth {

struct GmshBuilders {
    ClusterSpec (*double_bubble)(const DoubleBubbleOptions&);
    ClusterSpec (*sphere)(const SphereOptions&);
    ClusterSpec (*fragment)(const FragmentOptions&);
    ClusterSpec (*planar_polygons)(const PlanarPolygonsOptions&);
    /// The plugin links its own copy of froth_core, so its Ctrl-C flag is not the
    /// executable's: the loader hands over the executable's (builders/isolated.h polls it).
    void (*use_interrupt_flag)(const InterruptFlag&);
};

/// The table of this module's builders (what the plugin's entry point returns).
const GmshBuilders& gmsh_builders_table();

} // namespace froth

/// The plugin's entry point (dlsym name "froth_gmsh_builders").
extern "C" const froth::GmshBuilders* froth_gmsh_builders();
