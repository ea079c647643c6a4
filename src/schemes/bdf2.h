#pragma once
/// The second-order form of every scheme (BGN/BDF2, after Jiang, Su and Zhang, arXiv
/// 2402.03641; numerics.md "Second order in time"). With the step ratio w = tau / tau_prev,
/// D = X^m - X^{m-1} and the variable-step BDF2 derivative
///   X_t(t^{m+1}) ~ (a dX - b D) / tau,   a = (1 + 2w) / (1 + w),   b = w^2 / (1 + w)
/// (w = 1: (3 X^{m+1} - 4 X^m + X^{m-1}) / (2 tau)), the schemes of mean_curvature.h and
/// surface_diffusion.h keep their form with every geometric quantity (masses, normals, the
/// stiffness and the r > 1 weights) taken on a predictor Gamma~ of Gamma^{m+1} instead of
/// Gamma^m:
///   < (a dX - b D) / tau, chi nu~ >^h_mb = < kappa^{m+1}, chi >^h                  (3.7a)
///   < kappa^{m+1} nu~, eta >^h + < nabla_s^Gt~ X^{m+1}, nabla_s^Gt~ eta >_gamma = 0  (3.7b)
/// and the same for (3.8a) with its right side -< beta nabla_s kappa, nabla_s chi >. Written
/// for dX = T y (T the wall bases at X^m), this is the first-order system of step tau / a
/// assembled on Gamma~, plus two right-hand sides: the stiffness applied to the shift,
/// A~ (X~ - X^m) in the position rows (A~ X^{m+1} = A~ X~ + A~ (dX - (X~ - X^m))), and the
/// memory E = (b / a) D in the velocity equation (MCF: B~ E / tau' with B~ the normal block of
/// (4.6b); SD: N~^T E in the kappa rows). The predictor is the same linear BDF2 system
/// assembled on Gamma^m (X~ = X^m, no shift; r > 1 weights at nu^m): BDF2 with explicit
/// geometry, whose local error is O(tau^2) (the normals lag by one step), so the corrected
/// geometry is second-order accurate. Its matrix is the corrector's on a surface O(tau) away,
/// so both solve on one lagged factorisation. Jiang, Su and Zhang extrapolate the geometry
/// instead, Gamma~ = 2 X^m - X^{m-1}; measured here, that is unstable at triple lines: the
/// junctions' in-plane motion oscillates (BDF2's complex roots for lambda tau ~ 1) and
/// extrapolation amplifies it 3x, collapsing the facets at the line within 20-60 steps of a
/// double bubble; extrapolating tangential motion also carries a rotation of a sphere's
/// vertices on forever (a neutral mode). An implicit predictor damps both, for one more
/// linear solve per step. The r > 1 weights at the predictor's normals are explicit: an
/// order-2 step is two linear solves for every anisotropy. The first step (no history) is
/// the first-order scheme. Order 2 keeps no energy bound for all tau (BDF2 is A-stable, not
/// the BGN bound's gradient structure); numerics.md has what it keeps.

#include "mesh/cluster.h"

#include <vector>

namespace froth {

/// What an order-2 step adds to a scheme's first-order system.
struct Bdf2Step {
    double tau = 0;                ///< the step's length
    double a = 1, b = 0;           ///< the BDF2 coefficients of the header
    Cluster predictor;             ///< the cluster at X~
    std::vector<Vec3> shift;       ///< X~ - X^m
    std::vector<Vec3> memory;      ///< E = (b / a) D
    /// tau / a: the first-order step whose system the order-2 step solves.
    double effective_tau() const { return tau / a; }
};

/// The order-2 step of length tau from c (at X^m) with the predictor X~ = `predicted`, whose
/// previous step, of length previous_tau, started at `previous` (X^{m-1}).
/// \pre predicted and previous have one point per vertex.
Bdf2Step make_bdf2_step(const Cluster& c, std::vector<Vec3> predicted,
                        const std::vector<Vec3>& previous, double tau, double previous_tau);

/// max_v |Q_v^T (a_v - b_v)| / size, Q_v an orthonormal basis of the unit normals of the
/// surfaces at vertex v on the cluster's positions (one at a film vertex, two at a triple
/// line), size the diagonal of the bounding box: how far apart the shapes of a and b are,
/// blind to the tangential motion that BGN's schemes leave to the mesh.
double shape_difference(const Cluster& c, const std::vector<Vec3>& a, const std::vector<Vec3>& b);

} // namespace froth
