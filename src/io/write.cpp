#include "io/write.h"

#include "core/errors.h"
#include "io/msh_writer.h"
#include "io/off_ply.h"
#include "io/text_file.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace froth {

void write_cluster(const Cluster& c, const std::string& path,
                   const std::vector<PointField>& point_data) {
    const std::string given = std::filesystem::path(path).extension().string();
    std::string ext = given;
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char ch) { return static_cast<char>(std::tolower(ch)); });
    const char* const kinds = " (use .vtu, .off, .ply or .msh)";
    if (given.empty())
        throw InvalidInput("write: '" + path + "' has no file extension" + kinds);
    if (ext != ".vtu" && ext != ".off" && ext != ".ply" && ext != ".msh")
        throw InvalidInput("write: unknown file type '" + given + "'" + kinds);
    io::ensure_parent_directory(path, "write");
    if (ext == ".vtu")
        write_vtu(c, path, point_data);
    else if (ext == ".off")
        write_off(c, path);
    else if (ext == ".ply")
        write_ply(c, path);
    else
        write_msh(c, path);
}

} // namespace froth
