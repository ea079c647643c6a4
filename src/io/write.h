#pragma once
/// write_cluster: one entry point for all output formats, chosen by the file extension.

#include "io/vtk_writer.h"

#include <string>
#include <vector>

namespace froth {

class Cluster;

/// Writes c to path in the format its extension names (case-insensitive):
///   .vtu  ParaView UnstructuredGrid with the point fields (write_vtu)
///   .off  OFF triangle mesh (write_off)
///   .ply  ASCII PLY with per-face surface ids (write_ply)
///   .msh  gmsh mesh (write_msh)
/// point_data is used only by .vtu; the other formats carry no vertex fields and ignore it.
/// A missing parent directory is created.
/// \throw InvalidInput "write: unknown file type '.xyz' (use .vtu, .off, .ply or .msh)", or for
///        a malformed point field
/// \throw IoError if the file cannot be written
void write_cluster(const Cluster& c, const std::string& path,
                   const std::vector<PointField>& point_data = {});

} // namespace froth
