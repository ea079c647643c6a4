#pragma once
/// The space W^h of (3.4b) as a change of basis (numerics.md §3). kappa has one value per
/// (surface, vertex) pair; at a junction vertex the values must satisfy sum_j o_j kappa_{s_j} = 0
/// for every triple line through it. Rather than the paper's projection K (4.3a,b), we take an
/// orthonormal basis Z_v of the null space of those few rows at each vertex and write
/// kappa_v = Z_v k_v. Then kappa = Z k for a block-diagonal Z with k unconstrained, the reduced
/// systems are nonsingular, and quadruple points need no special case (6 pairs, 4 rows of rank 3).

#include "mesh/cluster.h"

#include <vector>

namespace froth {

struct KappaBasis {
    /// Row k of Z (pair k) has entries col[start[k] .. start[k+1]) with values val[...].
    std::vector<int> start, col;
    std::vector<double> val;
    int n_reduced = 0;
};

/// Z for the cluster's junction topology; constant while the topology is (o^k is combinatorial).
KappaBasis kappa_basis(const Cluster& c);

} // namespace froth
