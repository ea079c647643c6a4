#pragma once
/// The discrete surface cluster (numerics.md §1): one global vertex array shared by all surfaces
/// at triple lines and quadruple points, surfaces as consistently oriented triangle lists, bodies
/// as signed surface lists. Junction topology (triple-line edges, their orientation
/// coefficients o^k, triple lines, quadruple points) is derived from the triangles, never entered.

#include <Eigen/Core>
#include <Eigen/Geometry> // cross products

#include "anisotropy/mobility.h"
#include "core/types.h"
#include "mesh/curves.h"
#include "mesh/walls.h"

#include <array>
#include <cstdint>
#include <unordered_map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace froth {

/// The largest coordinate magnitude a cluster accepts: a volume is a sum of products of three
/// coordinates, and 1e100 cubed is still finite.
inline constexpr double kMaxCoordinate = 1e100;

/// Integer lattice coordinates: a facet corner of a periodic cluster sits at X[v] + L k.
using Offset = std::array<int, 3>;
/// The largest lattice coordinate a facet corner may have (a facet spans a few periods at most).
inline constexpr int kMaxOffset = 1000;

/// What a builder or a user hands to the engine. All ids are 0-based.
struct ClusterSpec {
    struct Surface {
        std::vector<Tri> triangles; ///< vertex ids; one consistent orientation per surface
        double sigma = 1.0;         ///< isotropic surface tension
        /// Periodic clusters only: per facet, the lattice offsets k of its three corners (the
        /// corner of vertex v is at X[v] + period k). Empty: all zero.
        std::vector<std::array<Offset, 3>> offsets;
    };
    std::vector<Vec3> vertices;
    std::vector<Surface> surfaces;
    /// Each body as the (unsigned) ids of the surfaces that enclose it; the engine finds the
    /// signs so that every body is a closed, outward-oriented polyhedron.
    std::vector<std::vector<int>> bodies;
    /// Evolver's `volconst` per body (empty, or one entry per body; nullopt: none). A body with
    /// one has Evolver's volume: the integral of z dx dy over its facets plus the constant, so
    /// its lids on wires and walls count nothing (mesh/boundary.cpp, lid_volume; Evolver's
    /// content integrals, which froth does not read, would add to it) and an Evolver
    /// datafile's `volume` target means the same number. Without it the volume is the one the
    /// films and lids enclose.
    std::vector<std::optional<double>> volconst;
    /// External boundaries (seed (1.25)): every free boundary edge (an edge of one facet only)
    /// must lie on one of them, or be a wire (below); its vertices are then constrained to the
    /// wall (3.10)/(3.11).
    std::vector<WallPtr> walls;
    /// Vertices held in place (Evolver's `fixed`): every scheme and minimize leave them where
    /// they are (their displacement space is {0}, as the walls' is the tangent plane). A free
    /// boundary edge between two fixed vertices that lies on no wall is a wire: the film ends
    /// there (a minimal surface spanning a frame needs no body).
    std::vector<int> fixed;
    /// (vertex, wall) pairs: which walls the vertices of free boundary edges are attached to,
    /// as a saved cluster had them (io/state_file.h). Empty: found by distance (a vertex is on
    /// a wall within 1e-6 of a typical edge), which a state that drifted off a curved wall by
    /// the seed's linearised constraint (O(tau^2) a step) would fail.
    std::vector<std::array<int, 2>> attachments;
    /// Wire curves and the fixed vertices on them (mesh/curves.h): each vertex at most once,
    /// fixed, and at its curve's point x(p) (within 1e-9 of its size).
    std::vector<CurvePtr> curves;
    std::vector<CurvePoint> curve_points;
    /// A periodic cluster (Evolver's torus model): the three period vectors as the columns of
    /// L. Space is R^3 modulo the lattice L Z^3; facets reach across the box through their
    /// corners' offsets (Surface::offsets), and every body must be a cell (a region bounded by
    /// one closed surface once unwrapped). A surface named twice in a body bounds it on both
    /// sides (a film between a cell and its own periodic image). No walls.
    std::optional<Eigen::Matrix3d> period;
};

/// A surface of the cluster. Its energy density is sigma gamma(nu) (seed (1.15); gamma null:
/// the isotropic |nu|, so sigma alone as in (1.14)), its mobility beta (1.19)/(1.20).
struct Surface {
    std::vector<Tri> triangles;
    double sigma = 1.0;
    std::shared_ptr<const Anisotropy> gamma; ///< null: isotropic
    Mobility beta;                           ///< 1 unless set
    std::vector<int> vertices;               ///< sorted global ids of the vertices of this surface

    /// Periodic clusters only (else empty): per facet its corners' lattice offsets and the
    /// shifts period * offset they stand for.
    std::vector<std::array<Offset, 3>> offsets;
    std::vector<std::array<Vec3, 3>> shifts;

    /// The three corners of facet f at positions X (one per vertex): X[t[a]], moved by the
    /// corner's lattice shift in a periodic cluster, so that the facet is whole. Every
    /// per-facet quantity (areas, normals, stiffness, volumes) is computed on these.
    std::array<Vec3, 3> corners(const std::vector<Vec3>& X, std::size_t f) const {
        const Tri& t = triangles[f];
        if (shifts.empty()) return {X[t[0]], X[t[1]], X[t[2]]};
        const auto& d = shifts[f];
        return {X[t[0]] + d[0], X[t[1]] + d[1], X[t[2]] + d[2]};
    }

    /// True when the surface uses the cotangent (isotropic) stiffness: gamma null or a multiple
    /// of |.|.
    bool isotropic() const { return !gamma || gamma->is_isotropic(); }
    /// sigma gamma(p) (p need not be a unit vector: the density is 1-homogeneous).
    double density(const Vec3& p) const { return sigma * (gamma ? gamma->gamma(p) : p.norm()); }
};

/// One (surface, sign) entry of a body: sign = +1 when the surface normal points out of the body.
/// In a periodic cluster a surface may appear twice in a body, once with each sign (a film
/// between a cell and its own image), and `shift` holds per facet the lattice translation that
/// puts it where the unwrapped cell has it (empty otherwise): the body's volume is the
/// divergence theorem over those translated facets.
struct BodyFace {
    int surface;
    int sign;
    std::vector<Vec3> shift;
};

/// Where a body meets walls or wires: a closed loop of free boundary edges of the body's films,
/// each directed as the body's outward-oriented facets traverse it. On walls the lid is the part
/// of the walls inside the loop (on several walls when the body sits in a corner); volumes close
/// it by a fan from the loop's center projected onto all of those walls. A loop of wire edges
/// (fixed vertices) is closed by the flat fan from its center.
struct Lid {
    std::vector<std::array<int, 2>> edges;
    std::vector<int> walls; ///< the walls its edges lie on; empty for a loop of wires
    /// A lid of a body with volconst: Evolver's convention (no content integrals), under which
    /// the lid adds its flat fan's cone volume less the fan's integral of z dx dy, what turns
    /// the cone sum of the films and the fan into the z dx dy sum over the films alone.
    bool evolver_content = false;
};

struct Body {
    std::vector<BodyFace> faces;
    std::vector<Lid> lids;            ///< empty for a body enclosed by films alone
    std::optional<double> volconst;   ///< ClusterSpec::volconst
};

/// An edge of exactly one facet: it lies on a wall (seed B_k).
struct BoundaryEdge {
    int a, b;
    int surface;
};

/// An edge shared by exactly three surfaces (seed Fig. 1). o[j] = +1 if the triangle of
/// surfaces[j] at this edge traverses a -> b in its own vertex order, -1 if b -> a: then the
/// pairs (o_j nu_j, mu_j) share one orientation about the edge, as (1.4c,d) require.
struct JunctionEdge {
    int a, b;
    std::array<int, 3> surfaces;
    std::array<int, 3> o;
    std::array<int, 3> opposite; ///< the third corner of each surface's triangle at this edge
    int line;                    ///< index into Cluster::triple_lines()
};

/// A chain of junction edges between quadruple points (or a closed loop).
struct TripleLine {
    std::vector<int> vertices; ///< ordered; for a closed line the first vertex is not repeated
    bool closed = false;
    std::array<int, 3> surfaces;
};

class Cluster {
  public:
    /// Validates the spec and derives the junction topology.
    /// \throw InvalidInput, TopologyError or GeometryError naming the offending element; the
    /// spec is consumed either way (no cluster exists after a throw).
    explicit Cluster(ClusterSpec spec);

    int n_vertices() const { return static_cast<int>(X_.size()); }
    int n_surfaces() const { return static_cast<int>(surfaces_.size()); }
    int n_facets() const { return n_facets_; }
    int n_bodies() const { return static_cast<int>(bodies_.size()); }
    /// True when the bodies of a periodic cluster fill its box: every surface bounds two
    /// cells (or one cell on both sides), so the volumes add up to the box's and the last one
    /// is fixed by the others.
    bool fills_box() const { return fills_box_; }
    /// The bodies whose volumes are constraints of their own: all, or all but the last when
    /// the bodies fill the box (its multiplier, the pressure, is the gauge 0).
    int n_volume_constraints() const { return n_bodies() - (fills_box_ ? 1 : 0); }
    /// |det period|, the volume of the periodic box (only for a periodic cluster).
    double box_volume() const;
    /// True for a periodic cluster (ClusterSpec::period).
    bool periodic() const { return period_.has_value(); }
    /// The period vectors as columns (only for a periodic cluster).
    const Eigen::Matrix3d& period() const { return *period_; }
    /// The lattice shift from vertex a to its neighbour b along their edge: X[b] - X[a] +
    /// edge_shift(a, b) is the edge vector (zero but in a periodic cluster; a and b must share
    /// an edge there).
    Vec3 edge_shift(int a, int b) const;

    const std::vector<Vec3>& positions() const { return X_; }
    const Vec3& position(int v) const { return X_[v]; }
    /// Replace all positions (same count); used by the time-stepping schemes.
    void set_positions(std::vector<Vec3> X);

    const std::vector<Surface>& surfaces() const { return surfaces_; }
    const Surface& surface(int i) const { return surfaces_[i]; }
    /// \throw InvalidInput unless sigma is finite and positive.
    void set_sigma(int surface, double sigma);
    /// Sets gamma_i (null: isotropic). \throw InvalidInput for a surface id out of range.
    void set_anisotropy(int surface, std::shared_ptr<const Anisotropy> gamma);
    /// Sets beta_i. \throw InvalidInput for a surface id out of range.
    void set_mobility(int surface, Mobility beta);
    /// True if some surface is anisotropic.
    bool anisotropic() const;
    /// True if some surface has r > 1: its scheme is nonlinear ((3.9), solved by Newton).
    bool nonlinear() const;
    /// True if some mobility is not the constant 1.
    bool has_mobilities() const;
    /// Changes whenever the sparsity of the position block may change (set_anisotropy): the
    /// time stepper rebuilds its patterns when it sees a new value.
    int assembly_revision() const { return assembly_revision_; }
    /// Changes whenever anything of a step's system besides the positions changes (sigma,
    /// gamma, beta, fixed vertices): an order-2 step's history is void then.
    int materials_revision() const { return materials_revision_; }

    const std::vector<Body>& bodies() const { return bodies_; }
    const std::vector<JunctionEdge>& junction_edges() const { return junction_edges_; }
    const std::vector<TripleLine>& triple_lines() const { return triple_lines_; }
    /// Vertices where three or more triple lines meet (4 at a proper quadruple point).
    const std::vector<int>& quadruple_points() const { return quadruple_points_; }

    /// The (surface, vertex) pairs in vertex-major order, surfaces sorted within a vertex: pair k
    /// belongs to vertex v for pair_begin(v) <= k < pair_begin(v + 1). They number the
    /// per-surface unknowns (kappa_iv) of the schemes.
    int n_pairs() const { return static_cast<int>(vs_list_.size()); }
    int pair_begin(int v) const { return vs_start_[v]; }
    int pair_surface(int k) const { return vs_list_[k]; }
    /// The pair of (surface s, vertex v), or -1 if s does not contain v.
    int pair_index(int v, int s) const;
    /// Junction edges at vertex v.
    std::vector<int> vertex_junction_edges(int v) const;

    const std::vector<WallPtr>& walls() const { return walls_; }
    /// Free boundary edges on walls (the vertices attached to the walls).
    const std::vector<BoundaryEdge>& boundary_edges() const { return boundary_edges_; }
    /// Free boundary edges between two fixed vertices on no wall: a wire the film spans
    /// (Evolver's fixed edges; a film need not enclose a body then).
    const std::vector<BoundaryEdge>& wire_edges() const { return wire_edges_; }
    bool is_wire_edge(int a, int b) const;
    /// The walls (ids into walls()) that vertex v is attached to; empty unless v is on a free
    /// boundary edge. Fixed when the cluster is made.
    std::vector<int> vertex_walls(int v) const;
    /// Every (vertex, wall) attachment, vertex-major (ClusterSpec::attachments).
    std::vector<std::array<int, 2>> wall_attachments() const;
    /// How many directions vertex v may move in: 0 if it is fixed, else 3, or 3 - rank of its
    /// walls' normals.
    int vertex_freedom(int v) const { return fixed_[v] ? 0 : freedom_[v]; }
    /// True if some vertex is attached to a wall.
    bool has_walls() const { return !boundary_edges_.empty(); }
    /// Fixed vertices (ClusterSpec::fixed, set_fixed).
    bool is_fixed(int v) const { return fixed_[v] != 0; }
    bool has_fixed() const { return n_fixed_ > 0; }
    /// The fixed vertices in increasing order.
    std::vector<int> fixed_vertices() const;
    /// Fixes (or frees) the given vertices; the assembly revision changes, since the schemes'
    /// unknowns do. \throw InvalidInput for an id out of range or for freeing a vertex of a
    /// wire edge (nothing changes then).
    void set_fixed(const std::vector<int>& vertices, bool fixed);

    /// Wire curves (ClusterSpec::curves) and the vertices on them, in increasing vertex order.
    const std::vector<CurvePtr>& curves() const { return curves_; }
    const std::vector<CurvePoint>& curve_points() const { return curve_points_; }
    /// The curve point of vertex v, or null if v is on no curve.
    const CurvePoint* curve_point(int v) const;

    /// Model time, advanced by the schemes.
    double time() const { return time_; }
    void set_time(double t) { time_ = t; }
    /// Body volumes when the cluster was made: the reference for volume-loss reports.
    const std::vector<double>& initial_volumes() const { return initial_volumes_; }
    /// The volume each body is held at by the volume-exact schemes (surface diffusion with
    /// exact_volumes, minimize): the initial volume unless set_target_volume changed it, or a
    /// step of a scheme that does not hold volumes (MCF, the seed's SD) moved them (the targets
    /// then follow: TimeStepper::step sets them to the volumes after such a step).
    const std::vector<double>& target_volumes() const { return target_volumes_; }
    /// \throw InvalidInput for a body id out of range or a volume that is not positive and
    /// finite (the message names the body and the value).
    void set_target_volume(int body, double volume);
    /// Replaces the reference and target volumes (same count as bodies; used when a cluster is
    /// rebuilt from another one, e.g. by refine, so reports keep measuring from the start).
    void set_volume_references(std::vector<double> initial, std::vector<double> target);
    /// Total facet area when the cluster was made: a length scale for degeneracy checks.
    double initial_area() const { return initial_area_; }
    /// Restores the reference area of a saved cluster (io/state_file.h). \throw InvalidInput
    /// unless it is positive and finite.
    void set_initial_area(double area);

  private:
    void check_spec(const ClusterSpec& spec) const;
    void check_curve_points(const ClusterSpec& spec) const;
    void check_period(const ClusterSpec& spec) const;
    void classify_edges();
    void build_triple_lines();
    /// \throw InvalidInput "<op>: the tensions at triple line k ... break the triangle inequality"
    void check_tension_triangles(const char* op) const;
    void orient_bodies(const std::vector<std::vector<int>>& body_surfaces,
                       const std::vector<std::optional<double>>& volconst);
    /// Periodic clusters: each body's facets found by walking its unwrapped surface
    /// (mesh/periodic.cpp), with their signs and lattice shifts.
    void orient_periodic_bodies(const std::vector<std::vector<int>>& body_surfaces);
    /// Periodic clusters: every edge joins its two vertices with one lattice offset; records
    /// it for edge_shift.
    void index_edge_offsets();
    void attach_walls();
    /// How far from a wall a vertex may be and count as on it.
    double wall_tolerance() const;
    /// True if both vertices lie on one wall (within wall_tolerance).
    bool on_common_wall(int a, int b) const;
    void find_lids(Body& body) const;

    std::vector<Vec3> X_;
    std::optional<Eigen::Matrix3d> period_;
    bool fills_box_ = false;
    std::unordered_map<std::int64_t, Vec3> edge_shift_; // (lo, hi) -> shift from lo to hi
    std::vector<Surface> surfaces_;
    std::vector<Body> bodies_;
    std::vector<JunctionEdge> junction_edges_;
    std::vector<TripleLine> triple_lines_;
    std::vector<int> quadruple_points_;
    // CSR incidence vertex -> surfaces and vertex -> junction edges
    std::vector<int> vs_start_, vs_list_, vj_start_, vj_list_;
    std::vector<WallPtr> walls_;
    std::vector<BoundaryEdge> boundary_edges_;
    std::vector<BoundaryEdge> wire_edges_; // sorted by (a, b), a < b
    std::vector<int> vw_start_, vw_list_, freedom_; // CSR vertex -> walls; free directions
    bool given_attachments_ = false;                // vw_* from ClusterSpec::attachments
    std::vector<CurvePtr> curves_;
    std::vector<CurvePoint> curve_points_; // sorted by vertex
    std::vector<char> fixed_;                       // per vertex
    int n_fixed_ = 0;
    std::vector<double> initial_volumes_, target_volumes_;
    double initial_area_ = 0;
    int n_facets_ = 0;
    double time_ = 0.0;
    int assembly_revision_ = 0;
    int materials_revision_ = 0;
};

/// The spec that rebuilds c: positions, surfaces (triangles, sigma), bodies and their volconst,
/// walls and attachments, fixed vertices, curves and curve points.
ClusterSpec cluster_spec(const Cluster& c);
/// What a cluster rebuilt from c's spec (refine, equiangulate) takes over from c: the surfaces'
/// anisotropies and mobilities, the time, the reference and target volumes.
void carry_over(const Cluster& from, Cluster& to);

/// Evolver's `r`: every facet split into four at its edge midpoints (one midpoint per edge, so
/// triple lines, quadruple points and bodies are kept; midpoints of free boundary edges are
/// projected onto the walls both ends lie on). The midpoint of a wire edge, or of an edge whose
/// facets have only fixed corners, is fixed, so a fixed frame stays fixed (an edge across a
/// film between two fixed vertices gets a free midpoint); on a wire edge between two vertices
/// of one curve it is the curve's point at curve_midpoint, so a ring stays on its circle.
/// Tensions, anisotropies, mobilities, walls, wall attachments, curves, time and the reference
/// and target volumes are carried over; the vertices of c keep their ids.
/// Volumes are unchanged except where a curved wall's lid gains the projected midpoints.
/// \throw what the Cluster constructor throws (it should not for a valid c).
Cluster refine(const Cluster& c);

struct EquiangulateResult {
    std::optional<Cluster> cluster; ///< the flipped cluster; empty when nothing flipped
    int flips = 0;                  ///< edges flipped
    int sweeps = 0;                 ///< passes over the edges that flipped something
};
/// Evolver's `u`: flips interior edges of the films until each is locally Delaunay (the angles
/// opposite an edge add up to at most pi), at most max_sweeps passes. Only edges inside one
/// surface flip (never a triple line, wall or wire edge), never into an edge that exists, a
/// degenerate or folded facet, or among four fixed corners. Vertices do not move; volumes change
/// by what the flipped edges' tetrahedra hold (minimize restores the targets). The vertices
/// and everything refine carries over are kept.
/// \throw InvalidInput for max_sweeps < 1; what the Cluster constructor throws.
EquiangulateResult equiangulate(const Cluster& c, int max_sweeps = 100);

/// Turns a spec whose vertices are unwrapped positions into a periodic one: vertices that are
/// lattice translates of one another (within 1e-9 of the period's size) become one vertex,
/// placed at its first occurrence reduced into the cell L [0, 1)^3, and each facet corner
/// gets the offset that puts it back where it was. Vertices are renumbered by first
/// appearance; returns the new id of every old vertex. Sets spec.period = L.
/// \throw InvalidInput for a singular or non-finite L, or an offset beyond kMaxOffset.
std::vector<int> identify_periodic_images(ClusterSpec& spec, const Eigen::Matrix3d& L);

/// When c's bodies fill its periodic box, their target volumes must add up to the box's
/// volume (to 1e-9 of it), or no state holds them all. \throw InvalidInput naming `op`, the sum
/// and the box volume otherwise.
void check_filled_box_targets(const Cluster& c, const char* op);

/// The cluster as a plain triangle mesh for writers: in a periodic cluster each distinct
/// (vertex, lattice offset) of a facet corner is a point of its own, so every facet is drawn
/// whole where its corners put it (films reach out of the box rather than wrap); otherwise the
/// cluster's own vertices and triangles.
struct DisplayMesh {
    std::vector<Vec3> points;
    std::vector<int> vertex;           ///< the cluster vertex of each point
    std::vector<std::vector<Tri>> triangles; ///< per surface, into points
};
DisplayMesh display_mesh(const Cluster& c);

/// Removes from spec the facets with all three corners on one of spec.walls (within 1e-6 of
/// the mean edge length): the faces of a solid that rest on a wall are its lids, not films.
/// Surfaces left without facets are removed (and from their bodies), unused vertices dropped
/// and the rest renumbered by first use. Returns the old ids of the surfaces kept.
std::vector<int> drop_wall_lids(ClusterSpec& spec);

/// The volume the lid adds to its body: the fan from the loop's center, projected onto all the
/// lid's walls (their common point), to the loop's edges, signed like the divergence-theorem sum
/// of the body's facets. Exact for flat walls, also for a lid on two or three planes (each fan
/// triangle lies in the plane of its edge). On one curved wall each fan triangle counts the
/// flux of the wall patch it spans (Wall::fan_flux: exact for spheres and cylinders up to O(h^2),
/// the flat triangle for user walls, which leaves out the lid's bulge). A wire loop's fan is
/// flat; with Lid::evolver_content every fan is flat and adds its cones less its z dx dy.
double lid_volume(const Cluster& c, const Lid& lid);
/// The same at positions X (one per vertex of c) instead of the cluster's own.
double lid_volume(const Cluster& c, const Lid& lid, const std::vector<Vec3>& X);

/// The signed volume of the cone from the origin over the triangle (a, b, c), a . (b x c) / 6:
/// summed over a closed oriented surface, the volume it encloses (the divergence theorem).
inline double cone_volume(const Vec3& a, const Vec3& b, const Vec3& c) {
    return a.dot(b.cross(c)) / 6.0;
}

/// The volume of one body at positions X: its signed facets' cones plus its lids (plus its
/// volconst, if it has one). A body without lids takes its cones from its first facet's first
/// corner, not the origin: the sum is the same for a closed surface, and its round-off is that
/// of the cell's size, not of its distance from the origin. The one
/// volume kernel: the body orientation at construction, geometry's body_volumes and every
/// report use it.
double body_volume(const Cluster& c, const Body& body, const std::vector<Vec3>& X);

} // namespace froth
