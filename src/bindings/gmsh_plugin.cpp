// Loading libfroth_gmsh.so on first use (builders/plugin.h says why).
#include "bindings/gmsh_plugin.h"

#include "core/errors.h"
#include "core/interrupt.h"
#include "bindings/paths.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace froth::lua {
namespace {

const GmshBuilders* load() {
    std::string tried;
    for (const std::string& path : gmsh_plugin_candidates()) {
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            tried += "\n  " + path + ": " + dlerror();
            continue;
        }
        using Entry = const GmshBuilders* (*)();
        auto entry = reinterpret_cast<Entry>(dlsym(handle, "froth_gmsh_builders"));
        if (entry) {
            const GmshBuilders* table = entry();
            table->use_interrupt_flag({&interrupt_requests, &consume_interrupt});
            return table;
        }
        tried += "\n  " + path + ": no symbol froth_gmsh_builders";
    }
    throw IoError("gmsh: cannot load the gmsh builders plugin (set FROTH_GMSH_PLUGIN to "
                  "libfroth_gmsh.so); tried:" + tried);
}

} // namespace

const GmshBuilders& gmsh_builders() {
    static const GmshBuilders* table = load(); // a failed load throws and is retried next time
    return *table;
}

} // namespace froth::lua
