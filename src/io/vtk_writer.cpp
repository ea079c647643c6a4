#include "io/vtk_writer.h"

#include "core/errors.h"
#include "io/text_file.h"
#include "mesh/cluster.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

namespace froth {
namespace {

constexpr int kVtkTriangle = 5;
constexpr int kPerLine = 8; // scalars per line in the ASCII arrays

void check_fields(const Cluster& c, const std::vector<PointField>& fields, const char* op) {
    std::set<std::string> seen;
    for (const PointField& f : fields) {
        if (f.name.empty()) throw InvalidInput(std::string(op) + ": a point field has no name");
        if (!seen.insert(f.name).second)
            throw InvalidInput(std::string(op) + ": point field '" + f.name + "' is given twice");
        if (static_cast<int>(f.values.size()) != c.n_vertices())
            throw InvalidInput(std::string(op) + ": point field '" + f.name + "' has " +
                               std::to_string(f.values.size()) + " values, but the cluster has " +
                               std::to_string(c.n_vertices()) + " vertices");
    }
}

void begin_array(io::TextBuffer& b, const char* type, std::string_view name, int components = 1) {
    b << "        <DataArray type=\"" << type << "\" Name=\"";
    b.xml_escaped(name) << '"';
    if (components > 1) b << " NumberOfComponents=\"" << components << '"';
    b << " format=\"ascii\">\n";
}

void end_array(io::TextBuffer& b) { b << "\n        </DataArray>\n"; }

void put_points(io::TextBuffer& b, const DisplayMesh& m) {
    b << "      <Points>\n";
    begin_array(b, "Float64", "Points", 3);
    bool first = true;
    for (const Vec3& x : m.points) {
        if (!first) b << '\n';
        first = false;
        b << x[0] << ' ' << x[1] << ' ' << x[2];
    }
    end_array(b);
    b << "      </Points>\n";
}

void put_cells(io::TextBuffer& b, const Cluster& c, const DisplayMesh& m) {
    b << "      <Cells>\n";
    begin_array(b, "Int64", "connectivity");
    bool first = true;
    for (const auto& tris : m.triangles)
        for (const Tri& t : tris) {
            if (!first) b << '\n';
            first = false;
            b << t[0] << ' ' << t[1] << ' ' << t[2];
        }
    end_array(b);
    begin_array(b, "Int64", "offsets");
    for (int f = 0; f < c.n_facets(); ++f)
        b << (f == 0 ? "" : f % kPerLine == 0 ? "\n" : " ") << 3LL * (f + 1);
    end_array(b);
    begin_array(b, "UInt8", "types");
    for (int f = 0; f < c.n_facets(); ++f)
        b << (f == 0 ? "" : f % kPerLine == 0 ? "\n" : " ") << kVtkTriangle;
    end_array(b);
    b << "      </Cells>\n";
}

/// One value per facet, the value of its surface.
template <class T> void put_surface_array(io::TextBuffer& b, const Cluster& c, const char* type,
                                          const char* name, const std::vector<T>& of_surface) {
    begin_array(b, type, name);
    int f = 0;
    for (int s = 0; s < c.n_surfaces(); ++s)
        for (std::size_t k = 0; k < c.surface(s).triangles.size(); ++k, ++f)
            b << (f == 0 ? "" : f % kPerLine == 0 ? "\n" : " ") << of_surface[s];
    end_array(b);
}

/// Per facet: its surface (1-based), its sigma, and the bodies on either side: body_behind is
/// the body its normal points out of, body_front the one it points into (0: none).
void put_cell_data(io::TextBuffer& b, const Cluster& c) {
    std::vector<int> id(c.n_surfaces()), behind(c.n_surfaces(), 0), front(c.n_surfaces(), 0);
    std::vector<double> sigma(c.n_surfaces());
    for (int s = 0; s < c.n_surfaces(); ++s)
        id[s] = s + 1, sigma[s] = c.surface(s).sigma;
    for (int k = 0; k < c.n_bodies(); ++k)
        for (const BodyFace& f : c.bodies()[k].faces)
            (f.sign > 0 ? behind : front)[f.surface] = k + 1;
    b << "      <CellData Scalars=\"surface\">\n";
    put_surface_array(b, c, "Int32", "surface", id);
    put_surface_array(b, c, "Float64", "sigma", sigma);
    put_surface_array(b, c, "Int32", "body_behind", behind);
    put_surface_array(b, c, "Int32", "body_front", front);
    b << "      </CellData>\n";
}

void put_point_data(io::TextBuffer& b, const std::vector<PointField>& fields,
                    const DisplayMesh& m) {
    if (fields.empty()) return;
    b << "      <PointData Scalars=\"";
    b.xml_escaped(fields.front().name) << "\">\n";
    for (const PointField& field : fields) {
        begin_array(b, "Float64", field.name);
        for (std::size_t i = 0; i < m.vertex.size(); ++i)
            b << (i == 0 ? "" : i % kPerLine == 0 ? "\n" : " ") << field.values[m.vertex[i]];
        end_array(b);
    }
    b << "      </PointData>\n";
}

std::string vtu_text(const Cluster& c, const std::vector<PointField>& fields, double time) {
    const DisplayMesh m = display_mesh(c); // periodic cells unwrapped
    io::TextBuffer b;
    b.reserve(static_cast<std::size_t>(c.n_vertices()) * (72 + 24 * fields.size()) +
              static_cast<std::size_t>(c.n_facets()) * 48 + 1024);
    b << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
         "header_type=\"UInt64\">\n"
         "  <UnstructuredGrid>\n"
         "    <FieldData>\n"
         "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
         "format=\"ascii\">"
      << time
      << "</DataArray>\n"
         "    </FieldData>\n"
         "    <Piece NumberOfPoints=\""
      << static_cast<long long>(m.points.size()) << "\" NumberOfCells=\"" << c.n_facets() << "\">\n";
    put_point_data(b, fields, m);
    put_cell_data(b, c);
    put_points(b, m);
    put_cells(b, c, m);
    b << "    </Piece>\n  </UnstructuredGrid>\n</VTKFile>\n";
    return b.str();
}

} // namespace

void write_vtu(const Cluster& c, const std::string& path,
               const std::vector<PointField>& point_data) {
    check_fields(c, point_data, "write");
    io::write_text_file(path, vtu_text(c, point_data, c.time()), "write");
}

PvdSeries::PvdSeries(std::string pvd_path) : path_(std::move(pvd_path)) {
    const std::filesystem::path p(path_);
    if (p.extension() != ".pvd" || p.stem().empty())
        throw InvalidInput("pvd: '" + path_ + "' is not a .pvd file name");
    dir_ = p.parent_path().string();
    stem_ = p.stem().string();
    write_pvd();
}

std::string PvdSeries::snapshot_path(int k) const {
    char num[16];
    std::snprintf(num, sizeof num, "_%06d.vtu", k);
    const std::string file = stem_ + num;
    return dir_.empty() ? file : (std::filesystem::path(dir_) / file).string();
}

void PvdSeries::add(double time, const Cluster& c, const std::vector<PointField>& point_data) {
    if (!std::isfinite(time))
        throw InvalidInput("pvd: snapshot time " + std::to_string(time) + " is not finite");
    check_fields(c, point_data, "pvd");
    const std::string snap = snapshot_path(count());
    io::write_text_file(snap, vtu_text(c, point_data, time), "pvd");
    entries_.push_back({time, std::filesystem::path(snap).filename().string()});
    try {
        write_pvd();
    } catch (const std::exception&) { // only std exceptions: no Lua runs in here
        entries_.pop_back();
        throw;
    }
}

void PvdSeries::write_pvd() const {
    io::TextBuffer b;
    b << "<?xml version=\"1.0\"?>\n"
         "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
         "  <Collection>\n";
    for (const Entry& e : entries_) {
        b << "    <DataSet timestep=\"" << e.time << "\" group=\"\" part=\"0\" file=\"";
        b.xml_escaped(e.file) << "\"/>\n";
    }
    b << "  </Collection>\n</VTKFile>\n";
    io::write_text_file(path_, b.str(), "pvd");
}

} // namespace froth
