#pragma once
/// The second variation of E - sum_b p_b (V_b - V*_b) for minimize's Newton steps
/// (flows/minimize.h, Evolver's `hessian`): the exact Hessian of the polyhedral area and
/// volumes in the positions, 3 x 3 blocks per pair of vertices of a facet.
///
/// A facet of corners x_0, x_1, x_2 has n = (x_1 - x_0) x (x_2 - x_0), area |n| / 2, unit
/// normal nu = n / |n| and opposite edges e_i = x_{i+2} - x_{i+1} (indices mod 3). Then
///   d area / d x_i = nu x e_i / 2,        d n / d x_j = [e_j]_x,
///   d^2 area / d x_i d x_j = ( -[e_i]_x (I - nu nu^T) [e_j]_x / |n| + (d_{j,i+2} - d_{j,i+1})
///   [nu]_x ) / 2,
/// [a]_x the cross-product matrix (a x b = [a]_x b). A body's volume gradient at a vertex is
/// sum_f s_f n_f / 6 over its facets there (s_f = +-1 the facet's side; exact for every vertex
/// of a closed boundary), so d^2 V / d x_i d x_j = sum_f s_f [e_j]_x / 6 over the facets with
/// both corners, symmetric once summed over them (the block is symmetrised after assembly).
/// Edge vectors are taken from a facet's unwrapped corners, so periodic clusters need nothing
/// more.

#include "mesh/cluster.h"
#include "solvers/sparse_solvers.h"

#include <vector>

namespace froth {

/// sum_f sigma_f d^2 area_f - sum_b p_b d^2 V_b in the full coordinates (3 rows per vertex),
/// symmetric. `pressures` has one entry per volume constraint (Cluster::n_volume_constraints;
/// more are ignored). Isotropic films and bodies without lids only (the caller checks:
/// Cluster::anisotropic, Cluster::has_walls).
SparseMatrix lagrangian_hessian(const Cluster& c, const std::vector<double>& pressures);

} // namespace froth
