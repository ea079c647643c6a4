#pragma once
/// ParaView output: one cluster as an ASCII XML UnstructuredGrid (.vtu) and time series of
/// such snapshots collected by a .pvd file.

#include <string>
#include <vector>

namespace froth {

class Cluster;

/// A named scalar field with one value per cluster vertex (written as VTK point data).
struct PointField {
    std::string name;
    std::vector<double> values;
};

/// Writes c to path as an ASCII VTK XML UnstructuredGrid: points = the cluster vertices, cells =
/// all facets of all surfaces (VTK_TRIANGLE) in surface order, cell data "surface" = the 1-based
/// surface id (Int32), point data = the given fields (Float64), field data "TimeValue" =
/// c.time(). Numbers are written in shortest round-trip form. The parent directory is created
/// if missing.
/// \throw InvalidInput if a field has an empty or repeated name or not n_vertices() values
/// \throw IoError if the file cannot be written
void write_vtu(const Cluster& c, const std::string& path,
               const std::vector<PointField>& point_data = {});

/// A ParaView time series: PvdSeries("out/run.pvd") writes the snapshots "out/run_000000.vtu",
/// "out/run_000001.vtu", ... and the collection "out/run.pvd" that lists them (by file name,
/// relative to the .pvd's directory) with their times. The .pvd is rewritten atomically after
/// every add(), so it is valid at all times and can be opened while a run is going on.
class PvdSeries {
  public:
    /// Creates the parent directory if missing and writes an empty collection to pvd_path.
    /// \throw InvalidInput unless pvd_path ends in ".pvd"
    /// \throw IoError if the directory or the file cannot be created
    explicit PvdSeries(std::string pvd_path);

    /// Writes snapshot number count() of c at model time `time` (also stored as the
    /// snapshot's TimeValue), then rewrites the .pvd with the new entry. If the snapshot
    /// cannot be written, the series is unchanged.
    /// \throw InvalidInput if time is not finite or a field is malformed (see write_vtu)
    /// \throw IoError if a file cannot be written
    void add(double time, const Cluster& c, const std::vector<PointField>& point_data = {});

    /// Number of snapshots written so far.
    int count() const { return static_cast<int>(entries_.size()); }
    /// The .pvd path as given.
    const std::string& path() const { return path_; }
    /// The path snapshot k is (or will be) written to, e.g. "out/run_000003.vtu".
    std::string snapshot_path(int k) const;

  private:
    struct Entry {
        double time;
        std::string file; ///< relative to the .pvd's directory
    };
    void write_pvd() const;

    std::string path_;
    std::string dir_;  ///< parent directory of path_ ("" for the working directory)
    std::string stem_; ///< file name of path_ without ".pvd"
    std::vector<Entry> entries_;
};

} // namespace froth
