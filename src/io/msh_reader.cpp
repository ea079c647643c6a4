// The MSH reader: a validating tokenizer over the whole file, one parser per section, then the
// same surface/body rules gmsh's reader gave (physical groups first, else entities).
#include "io/msh_reader.h"

#include "core/errors.h"
#include "io/text_file.h"
#include "io/tokens.h"
#include "mesh/orient_parts.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <unordered_map>
#include <utility>
#include <vector>

namespace froth {
namespace {

using io::Tokens;

/// What the sections say, before it becomes a ClusterSpec.
struct MshModel {
    struct Node {
        std::size_t tag;
        Vec3 x;
    };
    std::vector<Node> nodes;
    std::map<int, std::vector<NodeTri>> triangles;     ///< surface entity tag -> its triangles
    std::map<int, std::vector<int>> surface_physicals; ///< surface entity -> physical tags
    std::map<int, std::vector<int>> volume_physicals;  ///< volume entity -> physical tags
    std::map<int, std::vector<int>> volume_boundaries; ///< volume entity -> surface entities
};

/// Nodes per element of the gmsh element types 1..31 (0: not a type); other types are refused.
int nodes_of_type(int type) {
    static const int n[32] = {0, 2,  3,  4,  4, 8,  6,  5,  3,  6,  9, 10, 27, 18, 14, 1,
                              8, 20, 15, 13, 9, 10, 12, 15, 15, 21, 4, 5,  6,  20, 35, 56};
    return type >= 1 && type <= 31 ? n[type] : 0;
}
constexpr int kTriangle = 2;

/// An element type and its number of nodes; unknown types are refused.
std::pair<int, int> read_element_type(Tokens& t) {
    const int type = t.tag("element type");
    const int per = nodes_of_type(type);
    if (per == 0)
        t.fail("element type " + std::to_string(type) + " is not a gmsh element type froth knows");
    return {type, per};
}

void read_tags(Tokens& t, std::vector<int>& into, const char* what) {
    const std::size_t n = t.count(what, 1);
    for (std::size_t i = 0; i < n; ++i)
        into.push_back(t.tag(what));
}

// $Entities (4.1): points, curves, surfaces, volumes with their physical tags; volumes also
// list their bounding surfaces (signed), which is where the bodies come from.
void read_entities(Tokens& t, MshModel& m) {
    const std::size_t np = t.count("number of points", 5), nc = t.count("number of curves", 9),
                      ns = t.count("number of surfaces", 9), nv = t.count("number of volumes", 9);
    std::vector<int> ignored;
    for (std::size_t i = 0; i < np; ++i) {
        t.tag("point tag");
        for (int d = 0; d < 3; ++d)
            t.real("point coordinate");
        read_tags(t, ignored, "number of physical tags");
    }
    const std::size_t counts[3] = {nc, ns, nv};
    for (int dim = 1; dim <= 3; ++dim)
        for (std::size_t i = 0; i < counts[dim - 1]; ++i) {
            const int tag = t.tag("entity tag");
            for (int d = 0; d < 6; ++d)
                t.real("bounding box coordinate");
            std::vector<int> physicals, boundary;
            read_tags(t, physicals, "number of physical tags");
            read_tags(t, boundary, "number of bounding entities");
            if (dim == 2) m.surface_physicals[tag] = std::move(physicals);
            if (dim == 3) {
                m.volume_physicals[tag] = std::move(physicals);
                for (int& b : boundary)
                    b = std::abs(b);
                m.volume_boundaries[tag] = std::move(boundary);
            }
        }
    t.expect("$EndEntities");
}

/// The first line of $Nodes and $Elements in 4.1: numBlocks numItems minTag maxTag.
struct BlockHeader {
    std::size_t blocks, total;
};
BlockHeader read_block_header(Tokens& t, const char* items, int tokens_per_item) {
    const std::string what(items);
    BlockHeader h{t.count(("number of " + what + " blocks").c_str(), 4),
                  t.count(("number of " + what + "s").c_str(), tokens_per_item)};
    t.integer(("minimum " + what + " tag").c_str(), 0, std::numeric_limits<long long>::max());
    t.integer(("maximum " + what + " tag").c_str(), 0, std::numeric_limits<long long>::max());
    return h;
}

void read_nodes_41(Tokens& t, MshModel& m) {
    const auto [blocks, total] = read_block_header(t, "node", 4);
    m.nodes.reserve(total);
    for (std::size_t b = 0; b < blocks; ++b) {
        const int dim = static_cast<int>(t.integer("entity dimension", 0, 3));
        t.tag("entity tag");
        const bool parametric = t.integer("parametric flag", 0, 1) == 1;
        const std::size_t n = t.count("number of nodes in block", 4);
        if (m.nodes.size() + n > total)
            t.fail("the node blocks hold more than the " + std::to_string(total) +
                   " nodes announced");
        const std::size_t first = m.nodes.size();
        for (std::size_t i = 0; i < n; ++i)
            m.nodes.push_back({static_cast<std::size_t>(
                                   t.integer("node tag", 1, std::numeric_limits<long long>::max())),
                               Vec3::Zero()});
        const int params = parametric ? std::min(dim, 2) : 0; // u on curves, u v on surfaces
        for (std::size_t i = 0; i < n; ++i) {
            for (int d = 0; d < 3; ++d)
                m.nodes[first + i].x[d] = t.real("node coordinate");
            for (int k = 0; k < params; ++k)
                t.real("node parameter");
        }
    }
    if (m.nodes.size() != total)
        t.fail("the node blocks hold " + std::to_string(m.nodes.size()) + " nodes, not the " +
               std::to_string(total) + " announced");
    t.expect("$EndNodes");
}

void read_elements_41(Tokens& t, MshModel& m) {
    const auto [blocks, total] = read_block_header(t, "element", 2);
    std::size_t seen = 0;
    for (std::size_t b = 0; b < blocks; ++b) {
        const int dim = static_cast<int>(t.integer("entity dimension", 0, 3));
        const int entity = t.tag("entity tag");
        const auto [type, per] = read_element_type(t);
        const std::size_t n = t.count("number of elements in block", per + 1);
        seen += n;
        if (seen > total)
            t.fail("the element blocks hold more than the " + std::to_string(total) +
                   " elements announced");
        std::vector<NodeTri>* tris = type == kTriangle && dim == 2 ? &m.triangles[entity] : nullptr;
        for (std::size_t i = 0; i < n; ++i) {
            t.integer("element tag", 0, std::numeric_limits<long long>::max());
            NodeTri tri{};
            for (int k = 0; k < per; ++k) {
                const auto node = static_cast<std::size_t>(
                    t.integer("node tag", 1, std::numeric_limits<long long>::max()));
                if (tris) tri[k] = node;
            }
            if (tris) tris->push_back(tri);
        }
    }
    if (seen != total)
        t.fail("the element blocks hold " + std::to_string(seen) + " elements, not the " +
               std::to_string(total) + " announced");
    t.expect("$EndElements");
}

void read_nodes_22(Tokens& t, MshModel& m) {
    const std::size_t n = t.count("number of nodes", 4);
    m.nodes.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        MshModel::Node node{static_cast<std::size_t>(
                                t.integer("node tag", 1, std::numeric_limits<long long>::max())),
                            Vec3::Zero()};
        for (int d = 0; d < 3; ++d)
            node.x[d] = t.real("node coordinate");
        m.nodes.push_back(node);
    }
    t.expect("$EndNodes");
}

// MSH 2.2 elements: tag type ntags tags... nodes...; tags[0] is the physical, tags[1] the
// elementary (entity) tag.
void read_elements_22(Tokens& t, MshModel& m) {
    const std::size_t n = t.count("number of elements", 4);
    for (std::size_t i = 0; i < n; ++i) {
        t.integer("element tag", 0, std::numeric_limits<long long>::max());
        const auto [type, per] = read_element_type(t);
        const int ntags = static_cast<int>(t.integer("number of element tags", 0, 64));
        int physical = 0, entity = 0;
        for (int k = 0; k < ntags; ++k) {
            const int tag = t.tag("element tag value");
            if (k == 0) physical = tag;
            if (k == 1) entity = tag;
        }
        NodeTri tri{};
        for (int k = 0; k < per; ++k) {
            const auto node = static_cast<std::size_t>(
                t.integer("node tag", 1, std::numeric_limits<long long>::max()));
            if (type == kTriangle) tri[k] = node;
        }
        if (type != kTriangle) continue;
        m.triangles[entity].push_back(tri);
        std::vector<int>& ph = m.surface_physicals[entity];
        if (physical != 0 && std::find(ph.begin(), ph.end(), physical) == ph.end())
            ph.push_back(physical);
    }
    t.expect("$EndElements");
}

MshModel read_model(Tokens& t) {
    MshModel m;
    t.expect("$MeshFormat");
    const std::string_view version = t.next("the format version");
    const bool v41 = version == "4.1";
    if (!v41 && version != "2.2" && version != "2.1" && version != "2")
        t.fail("MSH version " + std::string(version) +
               " is not read (froth reads ASCII MSH 4.1 "
               "and 2.2: gmsh -save -format msh41 converts)");
    if (t.integer("the file type", 0, 1) != 0)
        t.fail("binary MSH is not read (save it as ASCII: gmsh -save -format msh41 -bin 0)");
    t.integer("the data size", 0, 64);
    t.expect("$EndMeshFormat");
    bool nodes = false, elements = false;
    while (!t.at_end()) {
        const std::string_view section = t.next("a section");
        if (section.size() < 2 || section[0] != '$')
            t.fail("expected a section ($Nodes, ...), got '" + std::string(section.substr(0, 40)) +
                   "'");
        const std::string_view name = section.substr(1);
        if ((name == "Nodes" && nodes) || (name == "Elements" && elements))
            t.fail("a second $" + std::string(name) + " section");
        if (name == "Entities" && v41) {
            read_entities(t, m);
        } else if (name == "Nodes") {
            v41 ? read_nodes_41(t, m) : read_nodes_22(t, m);
            nodes = true;
        } else if (name == "Elements") {
            v41 ? read_elements_41(t, m) : read_elements_22(t, m);
            elements = true;
        } else if (name == "PartitionedEntities" || name == "Periodic") {
            t.fail("$" + std::string(name) + " (partitioned or periodic meshes) is not read");
        } else {
            t.skip_section(name); // $PhysicalNames, $NodeData, ...: nothing froth uses
        }
    }
    return m;
}

/// Entity groups of one dimension: by physical tag (sorted) if any entity has one, else one
/// group per entity. `physical` says which.
std::vector<std::vector<int>> groups_of(const std::map<int, std::vector<int>>& physicals,
                                        const std::vector<int>& entities, bool& physical) {
    std::map<int, std::vector<int>> by_tag;
    for (int e : entities)
        if (auto it = physicals.find(e); it != physicals.end())
            for (int p : it->second)
                by_tag[p].push_back(e);
    physical = !by_tag.empty();
    std::vector<std::vector<int>> groups;
    if (physical)
        for (auto& [tag, members] : by_tag)
            groups.push_back(std::move(members));
    else
        for (int e : entities)
            groups.push_back({e});
    return groups;
}

ClusterSpec build_spec(MshModel& m, const std::string& where) {
    // Surface entities: every one with triangles or listed in $Entities, in tag order.
    std::set<int> surface_entities;
    for (auto& [e, tris] : m.triangles)
        if (!tris.empty()) surface_entities.insert(e);
    for (auto& [e, ph] : m.surface_physicals)
        surface_entities.insert(e);
    bool physical = false;
    std::vector<std::vector<int>> films;
    for (auto& group : groups_of(m.surface_physicals,
                                 {surface_entities.begin(), surface_entities.end()}, physical)) {
        std::size_t n = 0;
        for (int e : group)
            if (auto it = m.triangles.find(e); it != m.triangles.end()) n += it->second.size();
        if (n == 0 && physical)
            throw IoError(where + "physical surface " + std::to_string(films.size() + 1) +
                          " has no triangles");
        if (n > 0) films.push_back(std::move(group));
    }
    if (films.empty()) return {};

    std::sort(m.nodes.begin(), m.nodes.end(),
              [](const auto& a, const auto& b) { return a.tag < b.tag; });
    for (std::size_t i = 1; i < m.nodes.size(); ++i)
        if (m.nodes[i].tag == m.nodes[i - 1].tag)
            throw IoError(where + "node " + std::to_string(m.nodes[i].tag) + " is defined twice");
    auto row = [&](std::size_t tag) -> std::size_t {
        auto it = std::lower_bound(m.nodes.begin(), m.nodes.end(), tag,
                                   [](const auto& n, std::size_t t) { return n.tag < t; });
        if (it == m.nodes.end() || it->tag != tag)
            throw IoError(where + "triangle node " + std::to_string(tag) + " has no coordinates");
        return static_cast<std::size_t>(it - m.nodes.begin());
    };

    ClusterSpec spec;
    std::vector<std::vector<NodeTri>> tris(films.size());
    std::vector<std::size_t> used;
    for (std::size_t f = 0; f < films.size(); ++f) {
        std::vector<std::vector<NodeTri>> parts;
        for (int e : films[f])
            if (auto it = m.triangles.find(e); it != m.triangles.end())
                parts.push_back(std::move(it->second));
        orient_parts(parts, where + "surface " + std::to_string(f + 1));
        for (auto& part : parts)
            tris[f].insert(tris[f].end(), part.begin(), part.end());
        for (const NodeTri& t : tris[f])
            for (std::size_t node : t)
                used.push_back(row(node));
    }
    std::sort(used.begin(), used.end());
    used.erase(std::unique(used.begin(), used.end()), used.end());
    if (used.size() > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw IoError(where + "too many vertices");
    for (std::size_t r : used)
        spec.vertices.push_back(m.nodes[r].x);
    auto id = [&](std::size_t tag) {
        return static_cast<int>(std::lower_bound(used.begin(), used.end(), row(tag)) -
                                used.begin());
    };
    for (std::size_t f = 0; f < films.size(); ++f) {
        ClusterSpec::Surface s;
        s.triangles.reserve(tris[f].size());
        for (const NodeTri& t : tris[f])
            s.triangles.push_back({id(t[0]), id(t[1]), id(t[2])});
        spec.surfaces.push_back(std::move(s));
    }

    std::unordered_map<int, int> film_of; // surface entity -> froth surface
    for (std::size_t f = 0; f < films.size(); ++f)
        for (int e : films[f])
            film_of.emplace(e, static_cast<int>(f));
    std::vector<int> volumes;
    for (auto& [v, b] : m.volume_boundaries)
        volumes.push_back(v);
    for (const std::vector<int>& group : groups_of(m.volume_physicals, volumes, physical)) {
        std::vector<int> body;
        for (int v : group)
            for (int s : m.volume_boundaries[v])
                if (auto it = film_of.find(s); it != film_of.end()) body.push_back(it->second);
        std::sort(body.begin(), body.end());
        body.erase(std::unique(body.begin(), body.end()), body.end());
        if (body.empty() && physical)
            throw IoError(where + "physical volume " + std::to_string(spec.bodies.size() + 1) +
                          " has no triangulated boundary surfaces");
        if (!body.empty()) spec.bodies.push_back(std::move(body));
    }
    return spec;
}

} // namespace

ClusterSpec parse_msh(std::string_view text, const std::string& name) {
    const std::string where = "read: '" + name + "' is not a readable mesh: ";
    Tokens tokens(text, where);
    if (tokens.at_end()) throw IoError("read: '" + name + "' has no triangles");
    MshModel model = read_model(tokens);
    ClusterSpec spec = build_spec(model, "read: '" + name + "': ");
    if (spec.surfaces.empty()) throw IoError("read: '" + name + "' has no triangles");
    return spec;
}

ClusterSpec read_msh(const std::string& path, const MshReadLimits& limits) {
    return parse_msh(io::read_text_file(path, limits.max_bytes, "read"), path);
}

} // namespace froth
