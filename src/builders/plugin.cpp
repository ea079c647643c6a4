// The plugin's entry point: the gmsh builders as one table (builders/plugin.h).
#include "builders/plugin.h"

namespace froth {
namespace {

// What the froth executable calls: each build in a child process (builders/isolated.h), so
// Ctrl-C stops a long mesh generation and a crash in gmsh is an error, not the end of froth.
ClusterSpec isolated_double_bubble(const DoubleBubbleOptions& o) {
    return run_isolated("double_bubble", [&] { return build_double_bubble(o); });
}
ClusterSpec isolated_sphere(const SphereOptions& o) {
    return run_isolated("sphere", [&] { return build_sphere(o); });
}
ClusterSpec isolated_fragment(const FragmentOptions& o) {
    return run_isolated(o.op, [&] { return build_fragment(o); });
}
ClusterSpec isolated_planar_polygons(const PlanarPolygonsOptions& o) {
    return run_isolated("foam mesher", [&] { return build_planar_polygons(o); });
}

} // namespace

const GmshBuilders& gmsh_builders_table() {
    static const GmshBuilders table{&isolated_double_bubble, &isolated_sphere, &isolated_fragment,
                                    &isolated_planar_polygons, &use_interrupt_flag};
    return table;
}

} // namespace froth

extern "C" __attribute__((visibility("default"))) const froth::GmshBuilders* froth_gmsh_builders() {
    return &froth::gmsh_builders_table();
}
