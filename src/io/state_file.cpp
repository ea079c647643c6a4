// State files: capture/restore between Cluster and ClusterState, then the text format.
#include "io/state_file.h"

#include "core/errors.h"
#include "io/text_file.h"
#include "io/tokens.h"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <limits>

namespace froth {
namespace {

constexpr const char* kMagic = "froth-state";
constexpr int kMaxId = std::numeric_limits<int>::max();

/// FNV-1a, 64 bits: enough to tell a damaged file from an intact one (not an adversary).
std::uint64_t fnv1a(std::string_view bytes) {
    std::uint64_t h = 14695981039346656037ull;
    for (unsigned char b : bytes)
        h = (h ^ b) * 1099511628211ull;
    return h;
}

std::string hex64(std::uint64_t h) {
    char s[17];
    std::snprintf(s, sizeof s, "%016" PRIx64, h);
    return s;
}

ClusterState::Material material_of(const Surface& s) {
    ClusterState::Material m;
    if (s.gamma) {
        for (int l = 0; l < s.gamma->n_terms(); ++l)
            m.G.push_back(s.gamma->G(l));
        m.r = s.gamma->r();
    }
    m.mobility = s.beta.kind();
    m.mobility_value = s.beta.constant_value();
    return m;
}

const char* mobility_word(Mobility::Kind k) {
    switch (k) {
    case Mobility::Kind::Constant:
        return "constant";
    case Mobility::Kind::EnergyDensity:
        return "gamma";
    case Mobility::Kind::Function:
        return "function";
    }
    return "?";
}

// --- writing ---

void write_surface(io::TextBuffer& out, const Surface& s, const ClusterState::Material& m) {
    out << "surface " << s.sigma << ' ' << static_cast<int>(s.triangles.size()) << '\n';
    for (const Tri& t : s.triangles)
        out << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << '\n';
    if (m.G.empty()) {
        out << "gamma isotropic\n";
    } else {
        out << "gamma " << m.r << ' ' << static_cast<int>(m.G.size()) << '\n';
        for (const Eigen::Matrix3d& G : m.G)
            for (int i = 0; i < 9; ++i)
                out << G(i / 3, i % 3) << (i == 8 ? '\n' : ' ');
    }
    out << "mobility " << mobility_word(m.mobility);
    if (m.mobility == Mobility::Kind::Constant) out << ' ' << m.mobility_value;
    out << '\n';
}

/// A section of named arrays (read_arrays reads it back).
void write_arrays(io::TextBuffer& out, const char* section, const std::vector<NamedValues>& arrays) {
    out << section << ' ' << static_cast<int>(arrays.size()) << '\n';
    for (const NamedValues& a : arrays) {
        out << "array " << a.name << ' ' << static_cast<int>(a.values.size()) << '\n';
        for (double v : a.values)
            out << v << '\n';
    }
}

std::string state_text(const ClusterState& s) {
    io::TextBuffer out;
    out.reserve(80 * (s.spec.vertices.size() + 1));
    out << kMagic << ' ' << kStateFormatVersion << '\n';
    out << "vertices " << static_cast<int>(s.spec.vertices.size()) << '\n';
    for (const Vec3& x : s.spec.vertices)
        out << x[0] << ' ' << x[1] << ' ' << x[2] << '\n';
    out << "surfaces " << static_cast<int>(s.spec.surfaces.size()) << '\n';
    for (std::size_t i = 0; i < s.spec.surfaces.size(); ++i) {
        Surface surface;
        surface.triangles = s.spec.surfaces[i].triangles;
        surface.sigma = s.spec.surfaces[i].sigma;
        write_surface(out, surface, s.materials[i]);
    }
    out << "bodies " << static_cast<int>(s.spec.bodies.size()) << '\n';
    for (const std::vector<int>& b : s.spec.bodies) {
        out << "body " << static_cast<int>(b.size());
        for (int f : b)
            out << ' ' << f + 1;
        out << '\n';
    }
    out << "walls " << static_cast<int>(s.walls.size()) << '\n';
    for (const WallParameters& w : s.walls) {
        out << "wall " << w.kind << ' ' << static_cast<int>(w.values.size());
        for (double v : w.values)
            out << ' ' << v;
        if (w.kind == "function") out << ' ' << w.name;
        out << '\n';
    }
    out << "attachments " << static_cast<int>(s.spec.attachments.size()) << '\n';
    for (const auto& [v, w] : s.spec.attachments)
        out << v + 1 << ' ' << w + 1 << '\n';
    out << "fixed " << static_cast<int>(s.spec.fixed.size()) << '\n';
    for (int v : s.spec.fixed)
        out << v + 1 << '\n';
    out << "curves " << static_cast<int>(s.curve_names.size()) << '\n';
    for (const std::string& name : s.curve_names)
        out << "curve " << name << '\n';
    out << "curve_points " << static_cast<int>(s.spec.curve_points.size()) << '\n';
    for (const CurvePoint& c : s.spec.curve_points)
        out << c.vertex + 1 << ' ' << c.curve + 1 << ' ' << c.p << '\n';
    out << "time " << s.time << "\ninitial_area " << s.initial_area << '\n';
    out << "volumes " << static_cast<int>(s.initial_volumes.size()) << '\n';
    for (std::size_t b = 0; b < s.initial_volumes.size(); ++b)
        out << s.initial_volumes[b] << ' ' << s.target_volumes[b] << '\n';
    // Format 2: the bodies with Evolver's volconst, as (body id, constant) pairs.
    const auto has_volconst = [](const std::optional<double>& v) { return v.has_value(); };
    out << "volconst "
        << static_cast<int>(
               std::count_if(s.spec.volconst.begin(), s.spec.volconst.end(), has_volconst))
        << '\n';
    for (std::size_t b = 0; b < s.spec.volconst.size(); ++b)
        if (s.spec.volconst[b])
            out << static_cast<int>(b + 1) << ' ' << *s.spec.volconst[b] << '\n';
    // Format 3: the period of a periodic cluster and its facet corners' lattice offsets.
    out << "period " << (s.spec.period ? 1 : 0) << '\n';
    if (s.spec.period) {
        for (int k = 0; k < 3; ++k)
            out << (*s.spec.period)(0, k) << ' ' << (*s.spec.period)(1, k) << ' '
                << (*s.spec.period)(2, k) << '\n';
        for (const ClusterSpec::Surface& surface : s.spec.surfaces) {
            out << "offsets " << static_cast<int>(surface.offsets.size()) << '\n';
            for (const auto& corners : surface.offsets)
                for (int a = 0; a < 3; ++a)
                    for (int d = 0; d < 3; ++d)
                        out << corners[a][d] << (a == 2 && d == 2 ? '\n' : ' ');
        }
    }
    write_arrays(out, "history", s.history);
    write_arrays(out, "transitions", s.transitions);
    out << "end\n";
    return out.str() + "checksum " + state_checksum(out.str()) + "\n";
}

// --- reading ---

int read_id(io::Tokens& t, const char* what, std::size_t n) {
    return static_cast<int>(t.integer(what, 1, static_cast<long long>(n))) - 1;
}

void read_surface(io::Tokens& t, std::size_t n_vertices, ClusterState& s) {
    t.expect("surface");
    ClusterSpec::Surface surface;
    surface.sigma = t.real("sigma");
    surface.triangles.resize(t.count("triangles", 3));
    for (Tri& tri : surface.triangles)
        for (int& v : tri)
            v = read_id(t, "vertex id", n_vertices);
    ClusterState::Material m;
    t.expect("gamma");
    const std::string_view g = t.next("gamma");
    if (g != "isotropic") {
        m.r = t.real(g, "r");
        m.G.resize(t.count("anisotropy terms", 9));
        for (Eigen::Matrix3d& G : m.G)
            for (int i = 0; i < 9; ++i)
                G(i / 3, i % 3) = t.real("G entry");
    }
    t.expect("mobility");
    const std::string_view kind = t.next("mobility kind");
    if (kind == "constant") {
        m.mobility_value = t.real("mobility");
    } else if (kind == "gamma") {
        m.mobility = Mobility::Kind::EnergyDensity;
    } else if (kind == "function") {
        m.mobility = Mobility::Kind::Function;
    } else {
        t.fail("mobility must be constant, gamma or function, got '" + std::string(kind) + "'");
    }
    s.spec.surfaces.push_back(std::move(surface));
    s.materials.push_back(std::move(m));
}

void read_walls(io::Tokens& t, ClusterState& s) {
    t.expect("walls");
    s.walls.resize(t.count("walls", 3));
    for (WallParameters& w : s.walls) {
        t.expect("wall");
        w.kind = std::string(t.next("wall kind"));
        w.values.resize(t.count("wall numbers", 1));
        for (double& v : w.values)
            v = t.real("wall number");
        if (w.kind == "function") w.name = std::string(t.rest_of_line("the wall's name"));
    }
}

void read_curves(io::Tokens& t, ClusterState& s) {
    t.expect("curves");
    s.curve_names.resize(t.count("curves", 2));
    for (std::string& name : s.curve_names) {
        t.expect("curve");
        name = std::string(t.rest_of_line("the curve's name"));
    }
    t.expect("curve_points");
    s.spec.curve_points.resize(t.count("curve points", 3));
    for (CurvePoint& c : s.spec.curve_points) {
        c.vertex = read_id(t, "curve point vertex id", s.spec.vertices.size());
        c.curve = read_id(t, "curve id", s.curve_names.size());
        c.p = t.real("curve parameter");
    }
}

/// A section of named arrays (`history`, `transitions`): its name and count, then per array
/// "array <name> <length>" and the values.
std::vector<NamedValues> read_arrays(io::Tokens& t, const std::string& section) {
    t.expect(section.c_str());
    std::vector<NamedValues> arrays(t.count((section + " arrays").c_str(), 3));
    const std::string value = section + " value";
    for (NamedValues& a : arrays) {
        t.expect("array");
        a.name = std::string(t.next("array name"));
        a.values.resize(t.count("array length", 1));
        for (double& v : a.values)
            v = t.real(value.c_str());
    }
    return arrays;
}

void read_period(io::Tokens& t, ClusterState& s) {
    t.expect("period");
    if (t.integer("period flag", 0, 1) == 0) return;
    Eigen::Matrix3d L;
    for (int k = 0; k < 3; ++k)
        for (int d = 0; d < 3; ++d) L(d, k) = t.real("period coordinate");
    s.spec.period = L;
    for (ClusterSpec::Surface& surface : s.spec.surfaces) {
        t.expect("offsets");
        surface.offsets.resize(t.count("facet offsets", 9));
        if (surface.offsets.size() != surface.triangles.size())
            t.fail("a surface has " + std::to_string(surface.offsets.size()) + " offset triples for " +
                   std::to_string(surface.triangles.size()) + " facets");
        for (auto& corners : surface.offsets)
            for (Offset& k : corners)
                for (int& d : k) d = static_cast<int>(t.integer("lattice offset", -kMaxOffset, kMaxOffset));
    }
}

void read_body(io::Tokens& t, ClusterState& s) {
    const std::size_t n_surfaces = s.spec.surfaces.size();
    std::vector<int> faces(t.count("surfaces of a body", 1));
    for (int& f : faces)
        f = read_id(t, "surface id", n_surfaces);
    s.spec.bodies.push_back(std::move(faces));
}

ClusterState parse_body(io::Tokens& t, long long version) {
    ClusterState s;
    t.expect("vertices");
    s.spec.vertices.resize(t.count("vertices", 3));
    for (Vec3& x : s.spec.vertices)
        for (int d = 0; d < 3; ++d)
            x[d] = t.real("coordinate");
    t.expect("surfaces");
    const std::size_t n_surfaces = t.count("surfaces", 6);
    for (std::size_t i = 0; i < n_surfaces; ++i)
        read_surface(t, s.spec.vertices.size(), s);
    t.expect("bodies");
    const std::size_t n_bodies = t.count("bodies", 2);
    for (std::size_t b = 0; b < n_bodies; ++b) {
        t.expect("body");
        read_body(t, s);
    }
    read_walls(t, s);
    t.expect("attachments");
    s.spec.attachments.resize(t.count("attachments", 2));
    for (auto& [v, w] : s.spec.attachments) {
        v = read_id(t, "attached vertex id", s.spec.vertices.size());
        w = read_id(t, "wall id", s.walls.size());
    }
    t.expect("fixed");
    s.spec.fixed.resize(t.count("fixed vertices", 1));
    for (int& v : s.spec.fixed)
        v = read_id(t, "fixed vertex id", s.spec.vertices.size());
    read_curves(t, s);
    t.expect("time");
    s.time = t.real("time");
    t.expect("initial_area");
    s.initial_area = t.real("initial area");
    t.expect("volumes");
    const std::size_t n_volumes = t.count("volumes", 2);
    if (n_volumes != n_bodies)
        t.fail("volumes " + std::to_string(n_volumes) + " for " + std::to_string(n_bodies) +
               " bodies");
    for (std::size_t b = 0; b < n_volumes; ++b) {
        s.initial_volumes.push_back(t.real("initial volume"));
        s.target_volumes.push_back(t.real("target volume"));
    }
    if (version >= 2) {
        t.expect("volconst");
        const std::size_t n = t.count("volconst entries", 2);
        s.spec.volconst.resize(n_bodies);
        for (std::size_t k = 0; k < n; ++k) {
            std::optional<double>& v = s.spec.volconst[read_id(t, "volconst body id", n_bodies)];
            if (v) t.fail("a body has two volconst entries");
            v = t.real("volconst");
        }
    }
    if (version >= 3) read_period(t, s);
    s.history = read_arrays(t, "history");
    if (version >= 4) s.transitions = read_arrays(t, "transitions");
    t.expect("end");
    if (!t.at_end()) t.fail("text after 'end'");
    return s;
}

} // namespace

ClusterState capture_state(const Cluster& c, std::vector<NamedValues> history) {
    ClusterState s;
    s.spec = cluster_spec(c);
    s.spec.walls.clear(); // saved by their parameters, user walls and curves by name
    s.spec.curves.clear();
    for (const Surface& surface : c.surfaces())
        s.materials.push_back(material_of(surface));
    for (const WallPtr& w : c.walls()) {
        s.walls.push_back(w->parameters());
        if (s.walls.back().name.find_first_of("\r\n") != std::string::npos)
            throw InvalidInput("save: the wall '" + s.walls.back().name +
                               "' has a line break in its name; give it a one-line name");
    }
    for (const CurvePtr& curve : c.curves()) {
        s.curve_names.push_back(curve->name());
        if (curve->name().find_first_of("\r\n") != std::string::npos)
            throw InvalidInput("save: the curve '" + curve->name() +
                               "' has a line break in its name; give it a one-line name");
    }
    s.time = c.time();
    s.initial_area = c.initial_area();
    s.initial_volumes = c.initial_volumes();
    s.target_volumes = c.target_volumes();
    s.history = std::move(history);
    return s;
}

Cluster restore_cluster(const ClusterState& state, const StateResolvers& resolvers) {
    ClusterSpec spec = state.spec;
    for (std::size_t k = 0; k < state.walls.size(); ++k) {
        const WallParameters& w = state.walls[k];
        spec.walls.push_back(w.kind == "function" ? resolvers.wall(static_cast<int>(k), w.name)
                                                  : wall_from_parameters(w));
    }
    for (std::size_t k = 0; k < state.curve_names.size(); ++k)
        spec.curves.push_back(resolvers.curve(static_cast<int>(k), state.curve_names[k]));
    Cluster c(std::move(spec));
    for (int i = 0; i < c.n_surfaces(); ++i) {
        const ClusterState::Material& m = state.materials[i];
        if (!m.G.empty()) c.set_anisotropy(i, std::make_shared<const Anisotropy>(m.G, m.r));
        switch (m.mobility) {
        case Mobility::Kind::Constant:
            if (m.mobility_value != 1.0) c.set_mobility(i, Mobility::constant(m.mobility_value));
            break;
        case Mobility::Kind::EnergyDensity:
            c.set_mobility(i, Mobility::energy_density());
            break;
        case Mobility::Kind::Function:
            c.set_mobility(i, resolvers.mobility(i));
            break;
        }
    }
    if (!std::isfinite(state.time)) throw InvalidInput("load: the time is not finite");
    c.set_time(state.time);
    c.set_initial_area(state.initial_area);
    c.set_volume_references(state.initial_volumes, state.target_volumes);
    for (int b = 0; b < c.n_bodies(); ++b)
        c.set_target_volume(b, state.target_volumes[b]); // validates each
    return c;
}

std::string state_checksum(std::string_view body) {
    return hex64(fnv1a(body));
}

void write_state_file(const std::string& path, const ClusterState& state) {
    io::write_text_file(path, state_text(state), "save");
}

ClusterState read_state_file(const std::string& path, std::uintmax_t max_bytes) {
    return parse_state_file(io::read_text_file(path, max_bytes, "load"), path);
}

ClusterState parse_state_file(std::string_view text, const std::string& name) {
    const std::string who = "load: '" + name + "'";
    io::Tokens head(text.substr(0, 64), who + ": ");
    if (head.at_end() || head.next("the format line") != kMagic)
        throw IoError(who + " is not a froth state file (it does not start with '" + kMagic + "')");
    const long long version = head.integer("the format version", 1, kMaxId);
    if (version > kStateFormatVersion)
        throw IoError(who + " was written by a newer froth (format " + std::to_string(version) +
                      "; this one reads " + std::to_string(kStateFormatVersion) + ")");
    const std::size_t mark = text.rfind("\nchecksum ");
    const std::string_view tail = mark == std::string_view::npos ? "" : text.substr(mark + 10);
    if (tail.size() != 17 || tail.back() != '\n' ||
        tail.substr(0, 16) != state_checksum(text.substr(0, mark + 1)))
        throw IoError(who + " is truncated or corrupted (its checksum line is missing or does "
                            "not match its contents)");
    io::Tokens t(text.substr(0, mark + 1), who + ": ");
    t.expect(kMagic);
    return parse_body(t, t.integer("the format version", 1, kStateFormatVersion));
}

} // namespace froth
