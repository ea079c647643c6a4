// Loading libfroth_gmsh.so on first use (builders/plugin.h says why).
#include "bindings/gmsh_plugin.h"

#include "core/errors.h"
#include "core/interrupt.h"

#include <dlfcn.h>
#include <unistd.h>

#include <cstdlib>
#include <string>
#include <vector>

namespace froth::lua {
namespace {

std::string executable_dir() {
    std::vector<char> buf(4096);
    const ssize_t n = readlink("/proc/self/exe", buf.data(), buf.size() - 1);
    if (n <= 0) return "";
    std::string path(buf.data(), static_cast<std::size_t>(n));
    return path.substr(0, path.find_last_of('/'));
}

const GmshBuilders* load() {
    std::vector<std::string> paths;
    if (const char* env = std::getenv("FROTH_GMSH_PLUGIN"); env && *env) {
        paths.push_back(env);
    } else {
        if (const std::string dir = executable_dir(); !dir.empty()) paths.push_back(dir + "/libfroth_gmsh.so");
#ifdef FROTH_GMSH_PLUGIN_PATH
        paths.push_back(FROTH_GMSH_PLUGIN_PATH);
#endif
    }
    std::string tried;
    for (const std::string& path : paths) {
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
