#pragma once
/// Watching an evolution for the approach of a topology change (pinch-off, a tearing ring, a
/// vanishing bubble), which the parametric method cannot pass (seed §5.1: t ~ 26.61, 0.91,
/// 0.178). The watch looks for the signs that precede one and names what, where and when.

#include "mesh/cluster.h"

#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace froth {

struct WatchOptions {
    bool enabled = true;
    /// A body whose volume falls below this fraction of its initial volume is vanishing.
    double min_volume_fraction = 1e-3;
    /// An edge shorter than this fraction of the mean edge length is collapsing (a neck or a
    /// shrinking film concentrates short edges; a uniformly shrinking cluster does not).
    double min_edge_fraction = 0.02;
    /// Set by evolve with transitions: an edge that is a whole triple line between two
    /// quadruple points collapses only below a tenth of that (a T1 is due long before; a line
    /// an inverse T1 made in a finely meshed corner may start that short), and a facet angle
    /// facing such an edge counts ten times its size against min_facet_angle (the needles
    /// beside a short line are the line's T1's to remove, not a facet collapsing).
    bool lines_to_transitions = false;
    /// A facet corner angle below this (degrees) means a facet is collapsing; on a surface
    /// with a nearly crystalline anisotropy (Anisotropy::nearly_crystalline) a tenth of it:
    /// there the schemes keep thin facets along the Wulff shape's edges (0.2-0.9 degrees in
    /// the seed's Figs. 17-19) that do not collapse.
    double min_facet_angle = 0.5;
    /// Test for crossing facets (CGAL) every this many steps; 0 never.
    int self_intersection_every = 10;
    /// A triple line between two quadruple points shorter than this fraction of the mean edge
    /// length, or a triangular (two-sided) film of perimeter below three (two) times that, is
    /// vanishing (evolve makes a T1, an inverse T1 or a lens's collapse there once it shrinks).
    double min_line_fraction = 0.2;
};

struct TopologyEvent {
    std::string kind;    ///< "vanishing body", "collapsing edge", "collapsing facet", "self-intersection"
    std::string message; ///< what, where and when, for people
    double t = 0;        ///< model time of the state that is kept
    int body = -1;       ///< "vanishing body": which (0-based)
    /// "collapsing edge", "collapsing facet": the facet the watch names (0-based)
    int surface = -1, facet = -1;
};

/// The mean and the longest length of the facets' edges (each counted once per facet).
struct EdgeLengths {
    double mean = 0, longest = 0;
};
EdgeLengths edge_lengths(const Cluster& c);
double mean_edge_length(const Cluster& c); ///< edge_lengths(c).mean

/// The smallest cell within two mean edges of facet `facet` of surface `surface` (facet
/// centres, across a periodic box the nearest image) whose volume is below both a ball of the
/// mean edge's radius and a tenth of the mean cell: a cell the mesh no longer resolves. -1 if
/// there is none.
int unresolved_cell_near(const Cluster& c, int surface, int facet);

struct FacetCrossing; // checks/self_intersection.h
/// "facet 3 of surface 2 crosses facet 7 of surface 5" (geometry.h's facet_name of each).
std::string crossing_text(const FacetCrossing& x);

/// Where a T1, an inverse T1 or a lens's or disc's collapse can act: a triple line between two
/// distinct quadruple points, a triangular film (bounded by three such lines, between two
/// cells, with three other cells along its sides), a two-sided film (a lens: two such lines
/// between the same two quadruple points, two other cells along them) or a disc film (bounded
/// by one closed triple line, one other cell along it). The cells name it through transitions
/// of other junctions, where its id changes.
struct Junction {
    int id = -1;       ///< the triple line's or the surface's (0-based)
    double size = 0;   ///< the line's length, the film's perimeter
    /// line: the three cells around it sorted, then the two at its ends sorted; film: its two
    /// cells sorted, then the three (two) of its sides sorted (body ids, -1 the outside)
    std::vector<int> cells;
    /// a film's mean width, 2 area / perimeter (near 0 for a film squeezed flat)
    double width = INFINITY;
    /// the number of sides of a film
    int sides() const { return static_cast<int>(cells.size()) - 2; }
};
std::vector<Junction> quadruple_lines(const Cluster& c);
/// The triangular, the two-sided and the disc films.
std::vector<Junction> collapsible_films(const Cluster& c);

class TopologyWatch {
  public:
    explicit TopologyWatch(WatchOptions options) : options_(options) {}
    /// Checks the cluster after step number `step` (1-based). Cheap checks every step; the
    /// self-intersection test every options.self_intersection_every steps.
    std::optional<TopologyEvent> check(const Cluster& c, int step) const;
    /// True if this step will run the self-intersection test (the caller keeps a state to
    /// return to, since a crossing state is not a valid one).
    bool tests_crossings(int step) const;

  private:
    WatchOptions options_;
};

} // namespace froth
