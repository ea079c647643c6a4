#pragma once
/// The T1s and inverse T1s that runs make on their own (evolve with transitions, minimize with
/// transitions): which junctions are due, and the transition of one. A junction is due when it
/// is small (a triple line between quadruple points shorter than min_line_fraction of the mean
/// edge, a triangular film of perimeter below three times that) and has shrunk since the last
/// look, or is a film squeezed flat (mean width below a tenth of the line limit, shrinking
/// or not). What a transition makes is not due in the same look, and later only once it has
/// shrunk below half its size right after it: a product is made larger than the limit where
/// the mesh lets it be, and relaxes back by shrinking a little, which is not the shrinking of
/// a junction on its way out (without this rule T1s and inverse T1s alternated at
/// the same junction step after step in grain networks); when forced (an edge or facet
/// collapsing that nothing else mends) products are due as well, since a product made below
/// the mesh's scale is what collapses. Nor may a transition undo what one
/// did to the same two cells (a film between them made or removed) in the same look or the few
/// after, unless forced (an edge collapsing): at a tangle of small junctions a T1 next to an
/// inverse T1 otherwise restored the film it removed, look after look.

#include "core/types.h"
#include "mesh/cluster.h"
#include "run/topology_watch.h"

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace froth {

struct TransitionRecord; // mesh/transitions.h
struct FilmWaist;        // mesh/transitions.h

/// A topological transition a run made.
struct TransitionEvent {
    std::string kind;  ///< "pop body", "absorb body", "T1", "inverse T1", "two-sided film",
                       ///< "disc film", "film pinch"
    std::string where; ///< what and where, for people (TransitionRecord::where)
    double t = 0;      ///< the model time of the transition
    int step = 0;      ///< it followed this step (evolve) or round (minimize) of the run (1-based)
    /// pop, absorb: the body that went, as numbered at the start of the run (0-based)
    int body = -1;
    int neighbours = 0; ///< pop, absorb: the cells around it (the outside counts as one)
    double energy_before = 0, energy_after = 0;
    int line = -1;     ///< T1: the triple line that became a film (0-based, its id before)
    int film = -1;     ///< inverse T1, lens, disc: the film that went (0-based, its id before);
                       ///< film pinch: the film pinched
    /// T1, film pinch: the bodies the new film lies between; inverse T1: those the film lay
    /// between;
    /// absorb: the body and the one it joined; as numbered at the start of the run (-1: the
    /// outside)
    std::array<int, 2> cells{-1, -1};
};

class JunctionTransitions {
  public:
    /// min_line_fraction: WatchOptions::min_line_fraction. original_body: the bodies' ids at the
    /// start of the run, by their ids now (pops remove entries); the memory's keys use them.
    /// fit_corners: transitions may move their new corners off slivers (surgery::fit_corners),
    /// as evolve's do; minimize's do not, since its rounds stop on the slivers that can leave
    explicit JunctionTransitions(double min_line_fraction, bool fit_corners = true)
        : fraction_(min_line_fraction), fit_corners_(fit_corners) {}

    /// The sizes of c's junctions, for the next look.
    void remember(const Cluster& c, const std::vector<int>& original_body);
    /// A new look (after a step): the products of the last look's transitions may be due
    /// again, and what they did to two cells is one look older.
    void new_look();
    /// Keeps the memory for the next run on the same cluster (evolve's calls one after the
    /// other behave as one long call): its keys go from the run's original body ids to the ids
    /// now (original_body: the original id of each body now), the junctions of popped bodies
    /// are forgotten.
    void carry_over(const std::vector<int>& original_body);
    /// The memory, carried over (keys in the bodies' ids now), as named arrays "junctions.*"
    /// for a state file (c:save), so that a loaded run makes the transitions the saving run
    /// would have made; refusals and this look's products are not kept (carry_over drops
    /// them too).
    void save(std::vector<NamedValues>& out) const;
    /// The memory save() wrote, for a cluster of n_bodies bodies; none if `in` holds no
    /// "junctions.*" arrays. \throw InvalidInput if they are not what save() writes (a body id
    /// out of range, a size that is not finite, a length that does not add up)
    static std::optional<JunctionTransitions> restore(const std::vector<NamedValues>& in,
                                                      int n_bodies);
    /// True if this memory, carried over, fits a run on a cluster of n_bodies bodies with this
    /// min_line_fraction.
    bool fits(int n_bodies, double min_line_fraction) const {
        return n_bodies == bodies_ && min_line_fraction == fraction_;
    }

    /// The first due junction of c (triangular films with `films`, else lines) whose
    /// transition can be made, smallest first; with `force` every small one is due, shrinking
    /// or not. The new cluster and its event (step, t left to the caller), or none (then
    /// refused() says why the due ones could not be made).
    std::optional<Cluster> make(const Cluster& c, bool films, bool force,
                                const std::vector<int>& original_body, TransitionEvent& event);
    /// The T1 length of c: min_line_fraction of its mean edge, below which a line is due for
    /// a T1 and a film's waist for a pinch.
    double t1_length(const Cluster& c) const;
    /// The pinch (pinch_film) at the shortest edge below max_length across a film between two
    /// of its lines (pinched_film_edges) that the mesh lets be made without crossings: the
    /// film's waist closing, as a short line is a T1's. Unless forced, not where it would give
    /// back the contact a lens's collapse took in the last few looks. The lens it makes is a
    /// product (not due in this look, and later only once below half its size). The new
    /// cluster and its event (step left to the caller), or none (then refused() says why the
    /// last one could not be made).
    std::optional<Cluster> pinch(const Cluster& c, double max_length, bool force,
                                 const std::vector<int>& original_body, TransitionEvent& event);
    /// Why the last forced attempt of this look was refused, or without one the last attempt:
    /// a forced one ignores the contact lock, so its reason is the mesh's (a stop's message
    /// named the lock of a later unforced attempt before).
    const std::string& refused() const {
        return forced_refused_.empty() ? refused_ : forced_refused_;
    }

  private:
    std::vector<Junction> junctions(const Cluster& c, bool films,
                                    const std::vector<int>& original_body) const;
    std::vector<Junction> due(const Cluster& c, bool films, double limit, bool force,
                              const std::vector<int>& original_body) const;
    /// The transition of `acted` (a film's with `film`, else a line's T1) on c, tested for
    /// crossings where it moved corners off slivers or capped a disc. \throw TopologyError
    Cluster transition_of(const Cluster& c, const Junction& acted, bool film, bool force,
                          double limit, TransitionRecord& record) const;
    /// The transition of `acted` (a film's with `film`, else a line's T1), or none (then
    /// refused_ says why).
    std::optional<Cluster> try_make(const Cluster& c, const Junction& acted, bool film,
                                    bool force, double limit,
                                    const std::vector<int>& original_body,
                                    TransitionEvent& event);
    /// Why the transition of `acted` would undo one of the last kContactLooks looks (the same
    /// two cells gain or lose a film), or empty; with `force` always empty.
    std::string undoes_recent(const std::vector<int>& pair, bool force) const;
    /// Forgets the refusals of the junctions that share two cells with `cells` (a
    /// transition was made there).
    void forget_refusals_near(const std::vector<int>& cells);

    double fraction_;
    bool fit_corners_;
    // the sizes of the junctions at the last look, by their cells
    std::map<std::vector<int>, double> line_sizes_, film_sizes_;
    // the lengths of the films' waists (film_waists) below kWaistMemory T1 lengths at the
    // last look, by their cells (FilmWaist::cells)
    std::map<std::vector<int>, double> waist_sizes_;
    /// The waists of c shorter than `below`, their cells in the bodies' original ids.
    std::vector<FilmWaist> waists(const Cluster& c, double below,
                                  const std::vector<int>& original_body) const;
    /// True if j (a film with `film`) is the product of an earlier transition that has not
    /// yet shrunk below kProductShrink of its first size.
    bool protected_product(const Junction& j, bool film) const;

    // [0] lines, [1] films (a line's cells and a film's can be the same list):
    // the cells of the junctions this look's transitions made
    std::array<std::set<std::vector<int>>, 2> made_;
    // the cells of earlier transitions' products, with their sizes right after the transition
    // (-1 until remember() sees it); dropped once gone or grown past that size
    std::array<std::map<std::vector<int>, double>, 2> products_;
    // the pairs of cells (sorted) a film between which a transition made or removed, with
    // the look it did so in
    std::map<std::vector<int>, int> contacts_;
    // the transitions the mesh refused in this look, by (film, forced, the junction's
    // cells; a pinch's: false, forced, the waist's four cells, which no line has), with the
    // junction's size then and why: one is not tried again in the look
    // while its size is the same and no transition was made next to it (at two of its
    // cells: a junction that shares a film with it). Each attempt rebuilds the whole
    // cluster, and without this every call of make tried every refused one again (the
    // 1000-cell minimize spent an hour so); a transition beside one may change what the mesh
    // allows there, so it is tried again then. They hold for the mesh they were met on
    // (mesh_, a hash) or one a transition of this memory made from it: any other change
    // (mesh upkeep, a step) forgets them all.
    struct Refusal {
        double size;
        std::string why;
    };
    std::map<std::tuple<bool, bool, std::vector<int>>, Refusal> refusals_;
    std::uint64_t mesh_ = 0;
    int look_ = 0;
    int bodies_ = -1; // carry_over: the number of bodies the memory is for
    std::string refused_;             // why a due transition could not be made in this look
    std::string forced_refused_;      // why the last forced one could not
};

} // namespace froth
