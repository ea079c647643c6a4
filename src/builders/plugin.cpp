// The plugin's entry point: the gmsh builders as one table (builders/plugin.h).
#include "builders/plugin.h"

namespace froth {

const GmshBuilders& gmsh_builders_table() {
    static const GmshBuilders table{&build_double_bubble, &build_sphere, &build_fragment};
    return table;
}

} // namespace froth

extern "C" __attribute__((visibility("default"))) const froth::GmshBuilders* froth_gmsh_builders() {
    return &froth::gmsh_builders_table();
}
