#pragma once
/// Where froth finds its own files: relative to the executable first, so that an installed
/// prefix works wherever it is moved (no environment variables, no source tree), then the
/// build tree it was built from.

#include <string>
#include <vector>

namespace froth::lua {

/// The folder of the running executable (/proc/self/exe), "" if unknown.
std::string executable_dir();

/// Candidates for froth's Lua library folder, in order: $FROTH_LUA_DIR if set (alone), else
/// <exe>/../share/froth/lua (an installed prefix) and the source tree's lua/.
std::vector<std::string> lua_dir_candidates();

/// Candidates for libfroth_gmsh.so: $FROTH_GMSH_PLUGIN if set (alone), else beside the
/// executable (the build tree), <exe>/../lib/froth (an installed prefix), the build tree.
std::vector<std::string> gmsh_plugin_candidates();

/// Candidates for the manual lua_api.md that help() prints from: <exe>/../share/doc/froth
/// (an installed prefix), then the source tree's docs/.
std::vector<std::string> manual_candidates();

} // namespace froth::lua
