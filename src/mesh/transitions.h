#pragma once
/// Topological transitions of a cluster: the mesh surgery that lets a run of many cells go on
/// where the parametric method must stop (issue 15 item 4). Each operation builds a new
/// cluster from the old one's spec and never changes the old one; run/evolve.h calls them when
/// the topology watch sees a transition coming.

#include "mesh/cluster.h"

#include <functional>
#include <optional>
#include <set>
#include <string>

namespace froth {

/// What a transition did, for event lists and messages.
struct TransitionRecord {
    std::string kind;    ///< "pop body", "absorb body", "T1", "inverse T1", "two-sided film",
                         ///< "disc film", "film pinch"
    std::string where;   ///< for people: "body 3 (volume 1e-05, 4 neighbouring cells) at (x, y, z)"
    int body = -1;       ///< pop, absorb: the body that vanished (0-based, its id before)
    int line = -1;       ///< T1: the triple line that became a film (0-based, before)
    int film = -1;       ///< inverse T1, two-sided or disc film: the film that went (0-based);
                         ///< film pinch: the film pinched
    /// T1, film pinch: the bodies the new film lies between; inverse T1: those the film lay between
    /// (-1: outside); absorb: the body and the one that absorbed it
    std::array<int, 2> cells{-1, -1};
    Vec3 point = Vec3::Zero(); ///< where it collapsed
    double size = 0;     ///< T1, film pinch: the new film's side; inverse T1, two-sided film: the new line's length
    int neighbours = 0;  ///< pop, absorb: the cells around it (the outside counts as one)
    int removed_vertices = 0, removed_facets = 0;
    /// T1, inverse T1, two-sided film: the new corners were moved off slivers
    /// (surgery::fit_corners), so the new junction may cross a film that no moved facet is
    /// part of; the caller decides whether to test for crossings
    bool fitted = false;
    /// disc film: closed by caps (collapse_disc_film with by_caps), which may cross a film
    bool capped = false;
};

/// The bodies on the two sides of each surface (-1: the outside or nothing; a film between a
/// cell and its own periodic image has it on both sides).
std::vector<std::array<int, 2>> surface_cells(const Cluster& c);

/// The cells on the other side of body `body`'s films (-1: the outside).
/// \throw TopologyError for a body that bounds a surface on both sides (it wraps around the
/// periodic box).
std::set<int> neighbour_cells(const Cluster& c, int body);

/// Evolver's `pop` of a vanishing cell: body `body` collapses to one point, its films go, and
/// the films around it close over the point. That point is a Plateau point exactly when the
/// body has at most four neighbouring cells (the outside counts as one): four give a quadruple
/// point (a tetrahedral cell), three a point of their triple line (a lens on a triple line),
/// two a point of their film (a lens on a film), one nothing (a bubble inside a cell). The
/// point is the mean of the body's vertices (unwrapped in a periodic cluster).
/// Bodies after `body` move down one id; surfaces of the body go, the others keep their order,
/// tensions, anisotropies and mobilities; vertices are renumbered in order. The reference
/// volumes of the other bodies are kept, their targets become their volumes after the pop
/// (the vanished volume goes to the neighbours as the collapse gives it, which keeps a filled
/// periodic box filled).
/// \throw InvalidInput for a body id out of range; TopologyError (naming the body and why,
/// nothing changed) for a body with more than four neighbours (its faces must shrink first),
/// one that meets walls, wires, fixed or curve vertices, wraps around a periodic box, is all
/// the cluster has, or whose collapse would pinch a neighbouring film at the point (a mesh too
/// coarse around it).
Cluster pop_body(const Cluster& c, int body, TransitionRecord* record = nullptr);

/// A vanishing body that cannot pop joins a neighbour: body `body`'s films with `into` (-1:
/// the body it shares the most film area with, or the next where joining that one would make
/// no valid cluster, e.g. a cell that meets `body` twice, once through a periodic box) go,
/// its other films become `into`'s, and where one of them meets a film of `into` along a line
/// of the films that went, the two join into one film (the one of lower id, with its tension, anisotropy and mobility; the other's
/// facets turned to face its way). No vertex moves: the energy falls by the tension of the
/// films that went (equal tensions) and `into`'s volume grows by exactly `body`'s. The lines
/// of the films that went stop being triple lines and their quadruple points become points of
/// `into`'s lines. Bodies after `body` move down one id, surfaces after the ones that went or
/// joined keep their order; reference volumes are kept, targets become the volumes after.
/// The event kind is "absorb body".
/// \throw InvalidInput for a body id out of range or an `into` that is not another body;
/// TopologyError (naming the body and why, nothing changed) for a body that meets walls or
/// wires, wraps around a periodic box, does not meet `into` (or, with -1, any other body), or
/// whose joined films would not make a valid cluster.
Cluster absorb_body(const Cluster& c, int body, int into = -1, TransitionRecord* record = nullptr);

/// The T1 of foams in 3D (the I -> H transition): triple line `line`, a chain of junction
/// edges between two distinct quadruple points a and b, with cells A, B, C around it and a
/// fourth cell D at a, E at b (D != E), becomes a small triangular film between D and E. Its
/// three corners are new quadruple points, one on each of the line's films (A|B, B|C, C|A),
/// in the plane through the line's midpoint normal to it, at distance side / sqrt(3) from
/// it, side = the largest of the line's length, half the mean length of the edges at a and
/// b, and min_side, or where that would turn a facet beside the line over (the mesh there
/// finer than the film), that side halved until none turns, but not below an eighth of the
/// line's length or smallest_side; its edges are new triple lines (D, E, A), (D, E, B), (D, E, C). The line's
/// films lose it (their facets along it go); each film of D at a and of E at b is split at a
/// and b between two of the new corners. The new film takes the tension, anisotropy and
/// mobility of the first film of D at a, and is the last surface; bodies, their reference and
/// target volumes are kept (the surgery moves a volume of order side^3).
/// Where both ends touch the same fourth cell (D = E, a cell that wraps around the line), no
/// film forms: the triangle is a gap through which D meets itself, D's film with X at b
/// joins its film with X at a (X = A, B, C; the one at b goes unless they are one film, later
/// surfaces move down), and each new corner is a point of the line (X, Y, D), which joins
/// the lines from a and b (a loop where they were one): two quadruple points go.
/// \throw InvalidInput for a line id out of range; TopologyError (naming the line and why,
/// nothing changed) for a closed line, one whose ends are not two distinct quadruple points,
/// where D = E and D's films at the ends do not pair up (D meets a cell twice at one end),
/// which meets walls, fixed or curve vertices,
/// whose films would be pinched or folded by the surgery (a mesh too coarse there), or where
/// every side allowed turns a facet over.
/// With `meets_itself` false, a line whose ends touch the same cell is refused too ("the same
/// cell ... meets both its ends"): runs make that T1 only when forced (see
/// run/junction_transitions.h).
Cluster t1_line_to_film(const Cluster& c, int line, TransitionRecord* record = nullptr,
                        double min_side = 0, double smallest_side = 0, bool fit_corners = true,
                        bool meets_itself = true);

/// The inverse T1 (the H -> I transition, Evolver's pop_tri_to_edge): surface `surface`, a
/// film between cells D and E (D != E) bounded by three open triple lines between three
/// quadruple points, the lines' third cells A, B, C distinct, becomes a triple line between
/// A, B and C, from a new quadruple point a (cells A, B, C, D) to b (A, B, C, E). a and b lie
/// on the film's normal through its (area-weighted) centre, a towards D, length apart:
/// length = the larger of the sides' mean length and min_length, or where that would turn a
/// facet over, that halved until none turns (at most ten times, not below smallest_length).
/// The film goes; in each film D|X its side's vertices become a (its facets along the side
/// go), in E|X they become b; the fan of each film X|Y at its corner splits between a and b
/// with a new facet, whose edge is the new line's. Surfaces after `surface` move down one id
/// and keep their tensions, anisotropies and mobilities; bodies, their reference and target
/// volumes are kept (the surgery moves a volume of order side^3). This is t1_line_to_film
/// backwards.
/// \throw InvalidInput for a surface id out of range; TopologyError (naming the surface and
/// why, nothing changed) for a film between a cell and itself, one that is not a disk
/// bounded by three triple lines between three quadruple points, with the same third cell
/// on two sides, with fixed or wall vertices, whose collapse would pinch or fold a film, or
/// where every length allowed turns a facet over.
Cluster t1_film_to_line(const Cluster& c, int surface, TransitionRecord* record = nullptr,
                        double min_length = 0, double smallest_length = 0,
                        bool fit_corners = true);

/// The collapse of a two-sided film (a lens between two quadruple points q_1 and q_2, left where
/// a T1 takes a side of a triangular film): surface `surface`, between cells D and E, bounded
/// by two triple lines (D, E, X) and (D, E, Y) from q_1 to q_2, X != Y, goes. Its sides become
/// two points a (towards D) and b (towards E) on its normal through its centre, the larger of
/// the sides' mean length and min_length apart (halved while a facet would turn over, at most
/// ten times); the films D|X, D|Y close at a and E|X, E|Y at b, and the films X|Y at q_1 and
/// q_2 join across the edge (a, b) into one (the one at q_1, with its tension, anisotropy and
/// mobility; the other's facets are turned to face its way). a and b are points of the lines
/// (D, X, Y) and (E, X, Y): two quadruple points go, D and E no longer touch there. Surfaces
/// after the removed ones move down; bodies, their reference and target volumes are kept.
/// \throw InvalidInput for a surface id out of range; TopologyError (naming the surface and
/// why, nothing changed) as t1_film_to_line, for a film that is not a disk bounded by two
/// triple lines between two quadruple points with distinct third cells.
Cluster collapse_two_sided_film(const Cluster& c, int surface, TransitionRecord* record = nullptr,
                                double min_length = 0, bool fit_corners = true);

/// The pinch of a film between two of its triple lines (collapse_two_sided_film backwards):
/// the edge (u, w) lies inside film F between cells A and B and joins u, a free point of its
/// border line (A, B, C), to w, a free point of its line (A, B, D), C != D. Where the lines
/// approach across F, C and D meet: u and w become two quadruple points p and q, side apart
/// along the lines about the edge's midpoint (side: the larger of min_side and the mean edge
/// at u and w; halved while a facet would turn over, at most ten times), F's two facets at
/// the edge go and F parts in two where the edge was its only link (the part at q becomes a
/// new surface with F's tension, anisotropy and mobility), the films A|C, B|C at u and A|D,
/// B|D at w split their fans between p and q, and a two-sided film C|D of one facet (p, q, r)
/// forms, bounded by the lines (A, C, D) along p q and (B, C, D) through its third corner r,
/// with the tension, anisotropy and mobility of A|C. New surfaces come last; bodies, their
/// reference and target volumes are kept (the surgery moves a volume of order side^3).
/// \throw InvalidInput for a vertex id out of range or u = w; TopologyError (naming the edge and
/// why, nothing changed) where u or w is not a free point of one triple line, where they do
/// not share exactly one film with the edge inside it, where the same cell lies beyond both
/// lines (C = D), where F would keep no facet at p or q, or where every side allowed turns a
/// facet over.
Cluster pinch_film(const Cluster& c, int u, int w, TransitionRecord* record = nullptr,
                   double min_side = 0, bool fit_corners = true);

/// A film's waist: an edge across it between two of its lines, where pinch_film can cut it.
struct FilmWaist {
    int u = -1, w = -1; ///< the edge's ends, u < w
    int film = -1;      ///< the film it lies in
    /// the film's two cells sorted, then the cells beyond the two lines sorted (-1: outside)
    std::array<int, 4> cells{};
    double length = 0;
};

/// The edges shorter than `shorter_than` that join free points of two different triple lines
/// across a film (pinch_film's edges), shortest first; not those whose ends are within three
/// edges of each other along the lines (a film's corner closed to a slit, which the upkeep
/// zips: zip_slit).
std::vector<FilmWaist> film_waists(const Cluster& c, double shorter_than);

/// The collapse of a disc film (a contact of two cells through a hole in a third's films, as a
/// T1 of a cell that meets itself leaves one): surface `surface`, between cells D and E,
/// bounded by one closed triple line (D, E, X), goes. The line becomes two points a (towards D)
/// and b (towards E) on its normal through its centre, the loop's length over pi apart (or
/// min_length; halved while a facet would turn over, at most ten times); the film D|X closes
/// over the hole at a, E|X at b, and X fills the gap between them. a and b are points inside
/// those films. Surfaces after `surface` move down; bodies, their reference and target volumes
/// are kept.
/// With `by_caps` the loop does not move: D|X closes over it with a fan of new facets to a, and
/// E|X, its loop vertices replaced by copies moved towards E by a quarter of the loop's radius
/// (halved while a facet would turn), with a fan to b; a and b half the radius from the centre.
/// The record then has `capped`: the caps may cross another film, which the caller tests.
/// \throw InvalidInput for a surface id out of range; TopologyError (naming the surface and
/// why, nothing changed) for a film between a cell and itself, one that is not a disk bounded
/// by one closed triple line along a third cell, whose collapse would pinch or fold a film, or
/// where every length allowed turns a facet over.
Cluster collapse_disc_film(const Cluster& c, int surface, TransitionRecord* record = nullptr,
                           double min_length = 0, bool fit_corners = true, bool by_caps = false);

/// A test of a closed disc (the new cluster and its record) that throws TopologyError to refuse
/// it (evolve's crossing test).
using DiscCheck = std::function<void(const Cluster&, const TransitionRecord&)>;

/// A disc film closed as collapse_disc_film does, or where that is refused (or `check` refuses
/// it) by caps, tested by `check` too. \throw InvalidInput for a surface out of range;
/// TopologyError with both reasons ("...; nor can caps close it: ...").
Cluster close_disc_film(const Cluster& c, int surface, TransitionRecord* record = nullptr,
                        bool fit_corners = true, const DiscCheck& check = {});

/// Mesh upkeep: what collapse_short_edges made.
struct EdgeCollapseResult {
    std::optional<Cluster> cluster; ///< none when nothing collapsed
    int collapsed = 0;
};

/// Evolver's `t`: collapses edges shorter than min_length, in one pass of collapses with
/// disjoint neighbourhoods (shortest first), without changing the topology: an edge inside a
/// film whose ends both lie on junctions, one between two quadruple points, one of a closed
/// triple line of three edges, edges at walls, wires, fixed or curve vertices, and collapses
/// that break the link condition or would turn a facet over are left. An edge across a film
/// between two triple lines that leave one quadruple point q (a film's corner squeezed at q)
/// has the lines' first edges collapse onto q instead. The end of higher rank
/// (film < triple line < quadruple point) keeps its place, equal ranks meet halfway.
/// Materials, time and the bodies' reference and target volumes are kept.
EdgeCollapseResult collapse_short_edges(const Cluster& c, double min_length);

/// Which edges collapse_edges tries, in one pass, under the rules of collapse_short_edges.
struct EdgeCollapseCriteria {
    double min_length = 0; ///< edges shorter than this (Evolver's `t`)
    /// With needle_angle > 0, the shortest side of every facet with a corner below
    /// needle_angle degrees: a needle's short side (a film's corner squeezed against a
    /// quadruple point), or a flat cap's side from its flat corner to the nearer end of its
    /// long side (which the flips would mend, but not where that side is a triple line).
    /// A needle whose tip is a triple line's vertex with the line's two edges as its sides (a
    /// hairpin of the line) offers those sides too, as its short side joins two junctions.
    double needle_angle = 0;
    /// Film vertices with three neighbours collapse onto the neighbour of highest rank (their
    /// three facets become the triangle of the neighbours). Such a vertex beside a triple line,
    /// joined to both its ends, breaks the link condition there, so the line could neither
    /// collapse nor make a T1 ("it would fold surface 689 over the point").
    bool valence_three = false;
    /// Where nothing collapses, slits narrower than min_length are zipped (zip_slit).
    /// minimize's upkeep leaves them: with them the 64-cell foam's minimize cycled through
    /// 835 transitions in 128 iterations and stopped, against 411 in 300 without.
    bool slits = true;
};
EdgeCollapseResult collapse_edges(const Cluster& c, const EdgeCollapseCriteria& criteria);

/// Mesh upkeep for a quadruple point whose lines run together (mesh/corner_zip.cpp), which
/// collapse_edges makes when its pass collapses nothing: where edges across films at the
/// quadruple point q, shorter than min_length, join the first vertices of two (a film's
/// corner squeezed shut) or three of q's lines, and those cannot collapse one at a time (a
/// facet beyond would turn over), they all go onto q at once: q keeps its place for two,
/// and for three moves to their centre, where the lines part. Tried on the films flipped
/// to Delaunay (equiangulate) when it fails on them as they are (a squeezed corner's
/// neighbours are often flat caps). The squeeze with the shortest edge whose zip keeps every
/// junction and turns no facet over; `collapsed` counts the vertices that went.
/// Materials, time and the bodies' reference and target volumes are kept.
EdgeCollapseResult zip_squeezed_corner(const Cluster& c, double min_length);

/// Mesh upkeep for a film's corner closed to a slit (mesh/corner_zip.cpp): where the first
/// vertex a of a triple line at quadruple point q lies within min_length of the first edge
/// (q, b) of another of q's lines bounding the same film, inside it (at b - q times 0.1 to
/// 0.9 from q) and the two lines leave q within 15 degrees, the edge (q, b) is split at a's
/// foot m and a and m go onto q, which moves to their midpoint (where that turns a facet
/// over, q keeps its place). The quadruple point moves up the slit by one edge; its two
/// other lines, the sides of the film of the lines' other two cells, reach along to it: a
/// 2D T1 along the slit. The narrowest slit whose zip keeps every junction and turns no
/// facet over; `collapsed` counts the vertices that went (2). Materials, time and the
/// bodies' reference and target volumes are kept.
EdgeCollapseResult zip_slit(const Cluster& c, double min_length);

/// Mesh upkeep for films narrower than their mesh (mesh/thin_film_remesh.cpp): every film
/// whose mean width (2 area / perimeter) is below max_width, whose border is one loop of
/// junction vertices and which has film vertices inside, gets the triangulation of its border
/// alone that maximises the smallest angle among those facing the film's way; its inner
/// vertices go (`collapsed` counts them). Borders, lines and quadruple points stay; the
/// volumes change by about the film's area times its inner vertices' distance from the new
/// facets. None if no film is such or the result is not a valid cluster of the same junctions.
EdgeCollapseResult remesh_thin_films(const Cluster& c, double max_width);

struct VertexRelaxResult {
    std::optional<Cluster> cluster; ///< none when no vertex moved
    int moved = 0;
};

/// Mesh upkeep for flat caps: the film vertex at the largest corner of each facet with a
/// corner below `angle` degrees and one above 90 moves in its tangent plane (the plane normal
/// to the sum of its facets' area vectors) to the mean of its neighbours, or where a facet at
/// it would turn over or flatten half or a quarter of the way, else not at all; in one pass,
/// no two moved vertices neighbours. Inside a film a
/// flip mends a cap too; where the cap's long side is a triple line nothing else does.
/// Topology, materials, time and the reference and target volumes are kept; the volumes
/// change by about the caps' areas times the moves.
VertexRelaxResult relax_flat_corners(const Cluster& c, double angle);

/// Mesh upkeep for a short edge that cannot collapse: its film vertices (not on a junction)
/// move as relax_flat_corners moves a cap's corner. A film vertex next to a line vertex whose
/// collapse breaks the link condition (it is joined to the line's next vertex too) so moves
/// away from it.
VertexRelaxResult relax_short_edge_ends(const Cluster& c, double min_length);

struct EdgeSplitResult {
    std::optional<Cluster> cluster; ///< none when nothing was split
    int split = 0;
};

/// Evolver's `l`: splits edges longer than max_length at their midpoints (each facet at such an
/// edge into two), in one pass of splits with disjoint facets, longest first; edges on walls
/// and wires are left. Topology, volumes (the midpoints lie on the straight edges), materials,
/// time and the reference and target volumes are kept.
EdgeSplitResult split_long_edges(const Cluster& c, double max_length);

/// Before the T1 of triple line `line`: the films at the line whose every facet has two
/// corners on it (a triangular film of one facet with the line as a side), which the T1
/// would leave without a facet, get their other edges split at their midpoints (as
/// split_long_edges; each such facet's two other sides, one edge per facet a pass, in as many
/// passes as that takes), so that the T1 leaves them a lens of two facets. None if no film is
/// such. Vertex ids are kept (the midpoints come after them). With part_common_neighbours, also the edges (a, w) and (b, w) from the
/// line's ends to a vertex w joined to a through a film of the fourth cell at a and to b
/// through one of the fourth cell at b (the T1 may give both films the edge from w to one new
/// corner, an edge of four films; t1_line_to_film with fit_corners splits them where the T1
/// fails without), and in the line's films the edges from the line to a vertex that would
/// fold the film over the collapsed line (joined to two line vertices whose fans it does not
/// join).
std::optional<Cluster> split_films_emptied_by_t1(const Cluster& c, int line,
                                                 bool part_common_neighbours = false);

/// Before the collapse of film `film` (t1_film_to_line, collapse_two_sided_film,
/// collapse_disc_film, which call it): along each triple line bounding it, the other films
/// whose every facet has two corners on that line, which the collapse would leave without a
/// facet (a one-facet film at a corner, as a T1 of a short line can make), get their other
/// edges split as split_films_emptied_by_t1 does. None if no film is such. Vertex and surface
/// ids are kept.
std::optional<Cluster> split_films_emptied_by_collapse(const Cluster& c, int film);

} // namespace froth
