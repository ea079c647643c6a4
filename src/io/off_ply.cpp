#include "io/off_ply.h"

#include "io/text_file.h"
#include "mesh/cluster.h"

namespace froth {
namespace {

void put_vertices(io::TextBuffer& b, const DisplayMesh& m) {
    for (const Vec3& x : m.points) b << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
}

io::TextBuffer sized_buffer(const Cluster& c) {
    io::TextBuffer b;
    b.reserve(static_cast<std::size_t>(c.n_vertices()) * 72 +
              static_cast<std::size_t>(c.n_facets()) * 32 + 512);
    return b;
}

} // namespace

// Periodic clusters are written unwrapped (display_mesh): a facet's corners where it has them.
void write_off(const Cluster& c, const std::string& path) {
    const DisplayMesh m = display_mesh(c);
    io::TextBuffer b = sized_buffer(c);
    b << "OFF\n" << static_cast<long long>(m.points.size()) << ' ' << c.n_facets() << " 0\n";
    put_vertices(b, m);
    for (const auto& tris : m.triangles)
        for (const Tri& t : tris) b << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << '\n';
    io::write_text_file(path, b.str(), "write");
}

void write_ply(const Cluster& c, const std::string& path) {
    const DisplayMesh m = display_mesh(c);
    io::TextBuffer b = sized_buffer(c);
    b << "ply\nformat ascii 1.0\ncomment froth cluster, time " << c.time() << '\n'
      << "element vertex " << static_cast<long long>(m.points.size()) << '\n'
      << "property double x\nproperty double y\nproperty double z\n"
      << "element face " << c.n_facets() << '\n'
      << "property list uchar int vertex_indices\nproperty int surface\nend_header\n";
    put_vertices(b, m);
    for (int s = 0; s < c.n_surfaces(); ++s)
        for (const Tri& t : m.triangles[s])
            b << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << ' ' << s + 1 << '\n';
    io::write_text_file(path, b.str(), "write");
}

} // namespace froth
