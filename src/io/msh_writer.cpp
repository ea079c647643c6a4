#include "io/msh_writer.h"

#include "core/errors.h"

#include "io/text_file.h"
#include "mesh/cluster.h"

#include <algorithm>
#include <limits>
#include <vector>

namespace froth {
namespace {

constexpr int kTriangle = 2; // gmsh element type: 3-node triangle

struct Box {
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity());
    Vec3 hi = -lo;
    void add(const Box& b) { lo = lo.cwiseMin(b.lo), hi = hi.cwiseMax(b.hi); }
};

void put_box(io::TextBuffer& b, const Box& box) {
    b << box.lo[0] << ' ' << box.lo[1] << ' ' << box.lo[2] << ' ';
    b << box.hi[0] << ' ' << box.hi[1] << ' ' << box.hi[2];
}

std::vector<Box> surface_boxes(const Cluster& c) {
    std::vector<Box> boxes(c.n_surfaces());
    for (int s = 0; s < c.n_surfaces(); ++s)
        for (int v : c.surface(s).vertices)
            boxes[s].lo = boxes[s].lo.cwiseMin(c.position(v)),
            boxes[s].hi = boxes[s].hi.cwiseMax(c.position(v));
    return boxes;
}

void put_physical_names(io::TextBuffer& b, const Cluster& c) {
    b << "$PhysicalNames\n" << c.n_surfaces() + c.n_bodies() << '\n';
    for (int s = 1; s <= c.n_surfaces(); ++s)
        b << "2 " << s << " \"surface_" << s << "\"\n";
    for (int j = 1; j <= c.n_bodies(); ++j)
        b << "3 " << j << " \"body_" << j << "\"\n";
    b << "$EndPhysicalNames\n";
}

// No points or curves: gmsh accepts surfaces without bounding curves, and read_msh derives the
// triple lines from the triangles anyway. Volumes carry the signed surface lists, which is
// what gives read_msh (via getAdjacencies) the bodies back.
void put_entities(io::TextBuffer& b, const Cluster& c) {
    const std::vector<Box> boxes = surface_boxes(c);
    b << "$Entities\n0 0 " << c.n_surfaces() << ' ' << c.n_bodies() << '\n';
    for (int s = 0; s < c.n_surfaces(); ++s) {
        b << s + 1 << ' ';
        put_box(b, boxes[s]);
        b << " 1 " << s + 1 << " 0\n";
    }
    for (int j = 0; j < c.n_bodies(); ++j) {
        const Body& body = c.bodies()[j];
        Box box;
        for (const BodyFace& f : body.faces)
            box.add(boxes[f.surface]);
        b << j + 1 << ' ';
        put_box(b, box);
        b << " 1 " << j + 1 << ' ' << static_cast<int>(body.faces.size());
        for (const BodyFace& f : body.faces)
            b << ' ' << f.sign * (f.surface + 1);
        b << '\n';
    }
    b << "$EndEntities\n";
}

void put_nodes(io::TextBuffer& b, const Cluster& c) {
    // Each node in the block of the first surface that uses it; every node is in some facet.
    std::vector<int> owner(c.n_vertices(), -1);
    std::vector<std::vector<int>> block(c.n_surfaces());
    for (int s = 0; s < c.n_surfaces(); ++s)
        for (int v : c.surface(s).vertices)
            if (owner[v] < 0) owner[v] = s, block[s].push_back(v);
    const long long n = c.n_vertices();
    b << "$Nodes\n" << c.n_surfaces() << ' ' << n << " 1 " << n << '\n';
    for (int s = 0; s < c.n_surfaces(); ++s) {
        b << "2 " << s + 1 << " 0 " << static_cast<int>(block[s].size()) << '\n';
        for (int v : block[s])
            b << v + 1 << '\n';
        for (int v : block[s]) {
            const Vec3& x = c.position(v);
            b << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
        }
    }
    b << "$EndNodes\n";
}

void put_elements(io::TextBuffer& b, const Cluster& c) {
    b << "$Elements\n" << c.n_surfaces() << ' ' << c.n_facets() << " 1 " << c.n_facets() << '\n';
    long long tag = 0;
    for (int s = 0; s < c.n_surfaces(); ++s) {
        const std::vector<Tri>& tris = c.surface(s).triangles;
        b << "2 " << s + 1 << ' ' << kTriangle << ' ' << static_cast<int>(tris.size()) << '\n';
        for (const Tri& t : tris)
            b << ++tag << ' ' << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    }
    b << "$EndElements\n";
}

} // namespace

void write_msh(const Cluster& c, const std::string& path) {
    if (c.periodic())
        throw InvalidInput("write: a periodic cluster cannot be written as .msh (its offsets "
                           "would be lost); write .vtu, .off or .ply (unwrapped) or c:save");
    io::TextBuffer b;
    b.reserve(static_cast<std::size_t>(c.n_vertices()) * 64 + c.n_facets() * 32 + 1024);
    b << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
    put_physical_names(b, c);
    put_entities(b, c);
    put_nodes(b, c);
    put_elements(b, c);
    io::write_text_file(path, b.str(), "write");
}

} // namespace froth
