// The search paths of bindings/paths.h. FROTH_INSTALL_* are the install layout relative to the
// installed executable's folder (src/CMakeLists.txt computes them from GNUInstallDirs).
#include "bindings/paths.h"

#include <unistd.h>

#include <cstdlib>
#include <filesystem>

namespace froth::lua {

std::string executable_dir() {
    std::vector<char> buf(4096);
    const ssize_t n = readlink("/proc/self/exe", buf.data(), buf.size() - 1);
    if (n <= 0) return "";
    std::string path(buf.data(), static_cast<std::size_t>(n));
    return path.substr(0, path.find_last_of('/'));
}

namespace {

std::vector<std::string> candidates(const char* variable, std::vector<std::string> relative,
                                    const char* build_tree) {
    if (const char* env = std::getenv(variable); env && *env) return {env};
    std::vector<std::string> paths;
    if (const std::string dir = executable_dir(); !dir.empty())
        for (const std::string& r : relative)
            paths.push_back(std::filesystem::path(dir + "/" + r).lexically_normal().string());
    paths.push_back(build_tree);
    return paths;
}

} // namespace

std::vector<std::string> lua_dir_candidates() {
    return candidates("FROTH_LUA_DIR", {FROTH_INSTALL_LUA_REL}, FROTH_LUA_DIR);
}

std::vector<std::string> manual_candidates() {
    return candidates("FROTH_MANUAL", {FROTH_INSTALL_MANUAL_REL}, FROTH_SOURCE_MANUAL);
}

std::vector<std::string> gmsh_plugin_candidates() {
    return candidates("FROTH_GMSH_PLUGIN", {"libfroth_gmsh.so", FROTH_INSTALL_PLUGIN_REL},
                      FROTH_GMSH_PLUGIN_PATH);
}

} // namespace froth::lua
