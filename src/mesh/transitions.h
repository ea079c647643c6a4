#pragma once
/// Topological transitions of a cluster: the mesh surgery that lets a run of many cells go on
/// where the parametric method must stop (issue 15 item 4). Each operation builds a new
/// cluster from the old one's spec and never changes the old one; run/evolve.h calls them when
/// the topology watch sees a transition coming.

#include "mesh/cluster.h"

#include <string>

namespace froth {

/// What a transition did, for event lists and messages.
struct TransitionRecord {
    std::string kind;    ///< "pop body"
    std::string where;   ///< for people: "body 3 (volume 1e-05, 4 neighbouring cells) at (x, y, z)"
    int body = -1;       ///< the body that vanished (0-based, its id before the pop)
    Vec3 point = Vec3::Zero(); ///< where it collapsed
    int neighbours = 0;  ///< the cells around it (the outside counts as one)
    int removed_vertices = 0, removed_facets = 0;
};

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

} // namespace froth
