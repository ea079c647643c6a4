#pragma once
/// What the topological transitions (transitions.h) share: the steps of rebuilding a cluster
/// after mesh surgery. Internal to src/mesh.

#include "mesh/cluster.h"
#include "mesh/transitions.h"

#include <array>
#include <functional>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace froth::surgery {

/// "body k+1", or "the outside" for k < 0: a cell in transitions' messages and records.
std::string cell_name(int k);

/// Drops the vertices of V that no facet of spec uses: spec.vertices becomes the used ones in
/// order and the triangles are renumbered. Returns the map from V's ids to the new ones (-1:
/// dropped).
std::vector<int> keep_used_vertices(ClusterSpec& spec, const std::vector<Vec3>& V);

/// c's walls, wall attachments, fixed vertices, curves and curve points into spec, the vertex
/// ids through `map` (from c's ids; -1 for a vertex that is gone, which the callers refuse
/// before: such an entry makes the cluster invalid).
void copy_vertex_lists(const Cluster& c, const std::function<int(int)>& map, ClusterSpec& spec);

/// The cluster of spec; what its constructor throws becomes a TopologyError "<what>: the
/// cluster after <surgery> is not valid: ...".
Cluster rebuild(ClusterSpec spec, const std::string& what, const std::string& surgery);

/// r, made from c without body `gone` (its surface i from c's kept_surfaces[i]): those
/// surfaces' anisotropies and mobilities, c's time, the other bodies' reference volumes, and
/// targets that are the volumes now.
void carry_over_without_body(const Cluster& c, int gone, const std::vector<int>& kept_surfaces,
                             Cluster& r);

/// In one surface, the facets at a point P given by their link edges x -> y (the corners after
/// P in the facet's order) must form one fan: a path or a cycle. Two fans would pinch the film
/// at P. \throw TopologyError "<what>: ... surface N ..."
void check_one_fan(const std::vector<std::pair<int, int>>& link, int surface,
                   const std::string& what);

/// Per vertex, what the upkeep may do with it: 0 inside one film, 1 on a triple line, 2 a
/// quadruple point, -1 held (a wall, a wire, a fixed or curve vertex, or another junction).
std::vector<int> vertex_ranks(const Cluster& c);

/// True if the facet with corners y still faces the way of its old area vector and has not
/// (nearly) lost its area: surgery that moves corners must not turn or flatten a facet.
bool keeps_its_side(const Vec3& old_area, const std::array<Vec3, 3>& y);

/// Integer lattice offsets d with u = X + L d (all zero without a period).
Offset lattice_offset(const Cluster& c, const Vec3& unwrapped, const Vec3& stored);

/// The surfaces with a facet at vertex v.
std::set<int> surfaces_at(const Cluster& c, int v);

/// The mean length of the edges at v in its surfaces' facets (0 if it has none).
double mean_edge_at(const Cluster& c, int v);

/// The area vector of facet f of surface s of c (its corners in the facet's frame).
Vec3 facet_area(const Cluster& c, int surface, std::size_t facet);

/// A facet that took a new corner: where it is in the new spec and its area vector in c.
struct MovedFacet {
    int surface, facet;
    Vec3 area;
};

/// Surface si of spec (still c's facets): the vertices that are keys of `d` become the new
/// vertex p, their corner offsets less d (each vertex's lattice offset in p's frame); facets
/// with two or more such corners go, the others that take p are added to `moved`.
/// \throw TopologyError "<what>: ..." if p's facets would not form one fan.
void collapse_onto(const Cluster& c, ClusterSpec& spec, int si, const std::map<int, Offset>& d,
                   int p, std::vector<MovedFacet>& moved, const std::string& what);

/// The fan of `triangles` (one surface's) at v, a vertex on its border: the link vertices
/// u_0 .. u_n in order and the facet (v, u_j, u_{j+1}) of each link edge j.
struct BorderFan {
    std::vector<int> link;
    std::vector<int> facets;
};
/// \throw TopologyError "<what>: surface N is folded at / surrounds / is pinched at vertex M"
BorderFan border_fan(const std::vector<Tri>& triangles, int v, const std::string& what,
                     int surface);

/// Surface si of spec (c's facets, or with facets appended): its fan at vertex v, facets
/// (v, u_j, u_{j+1}) from u_0 to u_n along its link, splits between the new corners
/// p = corner_towards(u_0) and q = corner_towards(u_n): facets j < m take p, the others q
/// (m = ceil(n / 2), so the facets at both ends of the fan take their own corner), their
/// offsets at v less dv (v's lattice offset in the corners' frame), and the new facet
/// (p, u_m, q) fills the gap; its edge q -> p is a new junction edge.
/// \throw TopologyError "<what>: ..." if the fan is folded, closed or pinched at v.
void split_fan(const Cluster& c, ClusterSpec& spec, int si, int v, const Offset& dv,
               const std::function<int(int)>& corner_towards, std::vector<MovedFacet>& moved,
               const std::string& what);

/// True if a moved facet turns over or flattens at positions V (keeps_its_side); the first
/// such facet's surface into *surface. Moving corners must not: the cell walk that orients
/// the bodies would go astray.
bool turns_a_facet(const ClusterSpec& spec, const std::vector<Vec3>& V,
                   const std::vector<MovedFacet>& moved, int* surface = nullptr);

/// Moves the vertices `movable` of V (the new corners of a transition) by cyclic projection
/// onto half-spaces until every moved facet keeps its side with a margin: each corner of a
/// moved facet that is movable must lie, in the plane of the facet's old area vector, at least
/// a hundredth of the opposite edge's length beyond that edge (a corner angle of about half a
/// degree). Each projection is the least move that meets one facet's condition with the
/// facet's other corners held, so a corner that meets them all from the start stays where it
/// is. A corner moves at most `max_shift` in all. True if then no moved facet turns
/// (turns_a_facet); V keeps the moves either way.
bool fit_corners(const ClusterSpec& spec, std::vector<Vec3>& V, const std::vector<MovedFacet>& moved,
                 const std::vector<int>& movable, double max_shift);

/// Surface `gone`'s facets join surface `keep` in spec (c's surface ids); both lie between
/// body k and another cell, and where k gives them opposite signs gone's facets are turned to
/// face keep's way. `gone` keeps its (now doubled) facets until remove_surfaces.
void join_films(const Cluster& c, ClusterSpec& spec, int keep, int gone, int k);

/// The surfaces `removed` (sorted) go from spec and its bodies; those after them move down.
void remove_surfaces(ClusterSpec& spec, const std::vector<int>& removed);

/// c's materials of the surfaces r keeps (all but `removed`, sorted, in order; surfaces r
/// has after them are new and keep theirs), its time and the bodies' reference and target
/// volumes, to r.
void carry_over_without_surfaces(const Cluster& c, const std::vector<int>& removed, Cluster& r);

/// c with its edge (a, b) split at a + t (b - a) (b unwrapped in a's frame), each facet at it
/// into two in the same orientation (as split_long_edges); the new vertex is the last.
/// \throw TopologyError if a and b share no edge, or it lies on a wall or wire.
Cluster split_edge(const Cluster& c, int a, int b, double t);

/// The disc film `surface` of c closed by caps (disc_caps.cpp): collapse_disc_film with
/// by_caps. \throw TopologyError as collapse_disc_film.
Cluster cap_disc_film(const Cluster& c, int surface, TransitionRecord* record);

} // namespace froth::surgery
