#pragma once
/// Static equilibria at fixed volumes (Evolver's g + hessian; numerics.md "Static equilibria").
///
/// An equilibrium of E_gamma at the target volumes V*_b is a critical point of
/// E - sum_b p_b (V_b - V*_b): grad E(X) = sum_b p_b grad V_b(X) in the directions the walls
/// allow, with p_b the pressure of body b relative to the outside. minimize() reaches it by the
/// seed's mean curvature step (3.7)/(3.10) with the volumes as constraints, whose Lagrange
/// multipliers are the pressures:
///
///   [ T^T (A_gamma + 1/tau sum_i m_iv omega_iv omega_iv^T) T    T^T G ] [ y ]   [ -T^T A_gamma X^m ]
///   [ G^T T                                                      0    ] [ -p] = [ V* - V(X^m)      ]
///
/// X^{m+1} = X^m + T y, G = dV/dX at X^m (geometry.h, stored sparse), and tau growing
/// without bound from step to step (the tau -> infinity limit is the Dirichlet problem on
/// Gamma^m of Pinkall and Polthier). Testing the first row with y gives, for V(X^m) = V*,
/// E(X^{m+1}) <= E(X^m) for every tau (the seed's Theorem 3.2 proof; the constraint adds
/// p . G^T dX = 0), so the iteration is monotone; a step that would collapse a facet or raise
/// the energy by more than its volume correction explains is rejected and tau shrinks. The
/// BGN tangential structure of the step keeps the mesh as good as the flows do.

#include "mesh/cluster.h"
#include "solvers/schur_complement.h"

#include <string>
#include <vector>

namespace froth {

/// The pressures of the bodies and how far the cluster is from an equilibrium.
struct EquilibriumState {
    /// The least-squares multipliers p of grad E ~ sum_b p_b grad V_b, in the norm
    /// sum_v |r_v|^2 / m_v (m_v the lumped vertex mass) over the directions the walls allow; at
    /// an equilibrium the exact multipliers (a sphere of radius R with sigma = 1: 2 / R + O(h^2)).
    std::vector<double> pressures;
    /// The RMS over the films of the unbalanced force density r_v / m_v,
    /// r = grad E - sum_b p_b grad V_b, relative to sigma_mean / R (sigma_mean = E / area,
    /// R = sqrt(area / 4 pi)): sqrt(sum_v |T_v^T r_v|^2 / m_v / area) R / sigma_mean.
    double residual = 0;
};
/// \throw GeometryError for a degenerate facet, or what a user's wall function throws.
EquilibriumState equilibrium_state(const Cluster& c);

struct MinimizeOptions {
    double tol = 1e-6;        ///< stop when residual <= tol and the volumes are exact
    int max_iterations = 1000;
    /// The first step's tau relative to R^2 (R as above); grows by tau_growth per accepted step.
    double tau_start = 1e-2;
    double tau_growth = 4;
    /// The largest tau relative to R^2; from there on the steps are accelerated (Anderson).
    double tau_max = 1e4;
    /// Relative volume error |V_b - V*_b| / V*_b the result must reach to count as converged.
    double volume_tol = 1e-12;
    /// 0, or stop ("settled") once the energy changed by at most settle |E| over the last
    /// settle_window accepted steps: how Evolver's users judge a foam whose residual the mesh
    /// holds up (a sliver among 10^5 facets), where the residual never reaches tol.
    double settle = 0;
    int settle_window = 100;
    /// Newton's steps near the equilibrium (flows/hessian_step.h; Evolver's `hessian`), for
    /// isotropic clusters without walls (others ignore it), once the residual is below
    /// hessian_below. Newton's steps move the vertices along the normals only, so the mesh
    /// keeps the tangential layout it has then; the BGN steps before relax it (their fixed
    /// point has no tangential force either), and the later Newton starts the closer its
    /// equilibrium is to theirs: the double bubble at h = 0.2 from 1e-2 ends 9e-5 above their
    /// area, from 1e-3 1.8e-6, from 1e-4 1.5e-8.
    bool hessian = false;
    double hessian_below = 1e-3;
};

/// What one minimize() hands to the next on the same bodies (minimize_with_transitions'
/// rounds): the Schur complements that precondition the constraint solves of a cluster of many
/// bodies (solvers/schur_complement.h), the plain steps' and Newton's, the energies after the
/// last accepted steps (for MinimizeOptions::settle, across the rounds and the transitions between
/// them), and Newton's damping and back-off, so that a round does not retry at once what failed
/// in the last.
struct MinimizeCarry {
    LaggedSchurComplement schur;
    LaggedSchurComplement newton_schur{false}; ///< Newton's steps' (indefinite)
    std::vector<double> energies; ///< the last settle_window + 1 at most, oldest first
    /// Newton's damping (relative to sigma_mean / R^2), the iterations left before Newton is
    /// tried again, and the pause after its next failure (doubling with each).
    double newton_mu = 1e-3;
    int newton_pause = 0, newton_next_pause = 10;
};

struct MinimizeResult {
    double energy = 0;
    std::vector<double> volumes, pressures;
    double residual = 0;
    double volume_error = 0; ///< max_b |V_b - V*_b| / V*_b
    int iterations = 0;      ///< accepted steps
    int rejected = 0;        ///< steps rejected (tau shrunk)
    int hessian_steps = 0;   ///< of the accepted steps, Newton's (MinimizeOptions::hessian)
    double tau = 0;          ///< the tau the next step would have tried, relative to R^2
    double wall_seconds = 0;
    bool converged = false;
    /// "converged", "settled: <by how much>", "max_iterations", "interrupted", "stalled: <why>",
    /// or "topology: <what>" (a facet angle below 1 degree, or films without bodies shrinking
    /// away).
    std::string stop_reason;
};

/// Moves c to an equilibrium at its target volumes (Cluster::target_volumes). Stops cleanly
/// on Ctrl-C (core/interrupt.h) between steps with the last accepted state.
/// \throw InvalidInput for bad options (the cluster unchanged); on any other throw (a wall
/// function's error, a singular system) the cluster is restored to where it started.
/// `carry`: what an earlier minimize of the same bodies left (MinimizeCarry), updated for the
/// next; none: a fresh one for this call.
MinimizeResult minimize(Cluster& c, const MinimizeOptions& options, MinimizeCarry* carry = nullptr);

} // namespace froth
