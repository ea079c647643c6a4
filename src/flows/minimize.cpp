// Static equilibria at fixed volumes: the volume-constrained mean curvature step with tau
// growing without bound (minimize.h has the equations).
#include "flows/minimize.h"

#include "assembly/stiffness.h"
#include "core/errors.h"
#include "core/format.h"
#include "core/interrupt.h"
#include "flows/hessian_step.h"
#include "schemes/mean_curvature.h"
#include "solvers/anderson.h"
#include "solvers/schur_complement.h"
#include "solvers/sparse_solvers.h"

#include <Eigen/Dense>
#include <Eigen/SparseCholesky>

#include <chrono>
#include <cmath>
#include <limits>

namespace froth {
namespace {

using Clock = std::chrono::steady_clock;

/// The first variation of a cluster in the reduced position unknowns, with the weights of the
/// least-squares problem for the pressures.
struct Variation {
    Eigen::VectorXd grad_energy;      ///< T^T grad E, its component normal to the films
    Eigen::VectorXd grad_energy_full; ///< T^T grad E
    Eigen::SparseMatrix<double> grad_volume; ///< T^T G, one column per body
    Eigen::VectorXd weight;      ///< 1 / m_v on the rows of vertex v
    double area = 0, energy = 0;
    int bodies = 0; ///< all bodies (grad_volume may leave out the last: Cluster::fills_box)
};

/// y_v projected onto the span of T_v^T omega_iv over the surfaces i at v: the film normal at
/// a surface vertex, the plane normal to the line at a triple-line vertex, everything at a
/// quadruple point (Evolver's hessian_normal directions). The tangential rest of the first
/// variation only redistributes vertices within the films; BGN's tangential structure leaves it
/// nonzero, and it moves the energy by orders of magnitude less than the normal part.
void project_normal(const Cluster& c, const PositionBasis& P, const PairGeometry& g,
                    Eigen::VectorXd& y) {
    for (int v = 0; v < c.n_vertices(); ++v) {
        if (P.dim(v) == 0) continue; // a fixed vertex
        const Eigen::MatrixXd Q = normal_basis(c, P, g, v);
        auto seg = y.segment(P.offset(v), P.dim(v));
        seg = Q * (Q.transpose() * seg);
    }
}

Variation first_variation(const Cluster& c, const PositionBasis& P, const PairGeometry& g) {
    Variation d;
    d.grad_energy_full = P.restrict(apply_stiffness(c, c.positions()));
    d.grad_energy = d.grad_energy_full;
    project_normal(c, P, g, d.grad_energy);
    // Cells that fill a periodic box: the last volume is the box's less the others (its
    // gradient is minus their sum), so it is no constraint of its own and gets pressure 0.
    d.grad_volume = P.restrict(sparse_body_volume_gradients(c, c.positions()))
                        .leftCols(c.n_volume_constraints());
    d.bodies = c.n_bodies();
    const Eigen::VectorXd m = vertex_masses(c, g);
    d.weight.resize(P.size());
    for (int v = 0; v < c.n_vertices(); ++v) {
        d.weight.segment(P.offset(v), P.dim(v)).setConstant(1.0 / m[v]);
        d.area += m[v];
    }
    d.energy = energy(c);
    return d;
}

/// (B^T W B)^-1 r, with WB = W B. The Gram matrix of the volume gradients is sparse in a foam
/// (a cell's gradient meets only its neighbours'), so a sparse LDL^T: a dense factor of 1000
/// cells costs 0.1 s, and the volume restoration factors a few a step. The dense LDL^T where
/// the sparse one fails (gradients nearly dependent).
Eigen::VectorXd solve_gram(const Eigen::SparseMatrix<double>& B,
                           const Eigen::SparseMatrix<double>& WB, const Eigen::VectorXd& r) {
    const Eigen::SparseMatrix<double> BWB = B.transpose() * WB;
    const Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> sparse(BWB);
    if (sparse.info() == Eigen::Success) {
        Eigen::VectorXd x = sparse.solve(r);
        if (x.allFinite()) return x;
    }
    return Eigen::MatrixXd(BWB).ldlt().solve(r);
}

EquilibriumState balance(const Variation& d) {
    EquilibriumState s;
    const Eigen::SparseMatrix<double> WB = d.weight.asDiagonal() * d.grad_volume;
    const Eigen::VectorXd p = solve_gram(d.grad_volume, WB, WB.transpose() * d.grad_energy);
    const Eigen::VectorXd r = d.grad_energy - d.grad_volume * p;
    s.pressures.assign(p.data(), p.data() + p.size());
    s.pressures.resize(d.bodies, 0.0); // the gauge of a box filled with cells
    const double R = std::sqrt(d.area / (4 * M_PI)), sigma = d.energy / d.area;
    s.residual = std::sqrt(r.dot(d.weight.asDiagonal() * r) / d.area) * R / sigma;
    return s;
}

void check(const MinimizeOptions& o) {
    if (!(std::isfinite(o.tol) && o.tol > 0))
        throw InvalidInput("minimize: tol must be positive and finite, got " + fmt(o.tol));
    if (o.max_iterations < 1)
        throw InvalidInput("minimize: max_iterations must be at least 1, got " +
                           std::to_string(o.max_iterations));
    if (!(std::isfinite(o.tau_start) && o.tau_start > 0))
        throw InvalidInput("minimize: tau_start must be positive and finite, got " +
                           fmt(o.tau_start));
    if (!(o.tau_growth >= 1 && o.tau_growth <= 100))
        throw InvalidInput("minimize: tau_growth must be in [1, 100], got " + fmt(o.tau_growth));
    if (!(std::isfinite(o.tau_max) && o.tau_max >= o.tau_start))
        throw InvalidInput("minimize: tau_max must be finite and at least tau_start, got " +
                           fmt(o.tau_max));
    if (!(std::isfinite(o.volume_tol) && o.volume_tol > 0))
        throw InvalidInput("minimize: volume_tol must be positive and finite, got " +
                           fmt(o.volume_tol));
    if (!(std::isfinite(o.settle) && o.settle >= 0))
        throw InvalidInput("minimize: settle must be 0 or positive and finite, got " +
                           fmt(o.settle));
    if (!(std::isfinite(o.hessian_below) && o.hessian_below > 0))
        throw InvalidInput("minimize: hessian_below must be positive and finite, got " +
                           fmt(o.hessian_below));
    if (o.settle_window < 1)
        throw InvalidInput("minimize: settle_window must be at least 1, got " +
                           std::to_string(o.settle_window));
}

/// Solves K U = B column by column with one fresh factorisation, where K is the step's
/// matrix in the reduced unknowns: T^T (A + 1/tau sum m omega omega^T) T, or for an isotropic
/// cluster without walls or fixed vertices (K_scalar + 1/tau diag(m)) (x) I_3, whose three coordinates are one
/// scalar system with three times the columns.
class StepSystem {
  public:
    explicit StepSystem(const Cluster& c) {
        separable_ = !c.has_walls() && !c.has_fixed() && !c.anisotropic();
    }

    void assemble(const Cluster& c, const PositionBasis& P, const PairGeometry& g, double tau) {
        if (!separable_) {
            Eigen::VectorXd rhs;
            assemble_mcf(c, g, P, tau, nullptr, builder_, rhs);
            return;
        }
        Eigen::VectorXd mass = Eigen::VectorXd::Zero(c.n_vertices());
        for (int v = 0; v < c.n_vertices(); ++v)
            for (int k = c.pair_begin(v); k < c.pair_begin(v + 1); ++k) mass[v] += g.mass[k] / tau;
        assemble_scalar_stiffness(c, mass, builder_);
    }

    /// Solves with the matrix of the last assemble() (fresh) or with the last factor.
    Eigen::MatrixXd solve(const Eigen::MatrixXd& B, bool fresh) {
        if (!separable_) return fresh ? solver_.solve_fresh(builder_.finish(), B)
                                      : solver_.solve_with_last_factor(B);
        const Eigen::Index n = B.rows() / 3, k = B.cols();
        Eigen::MatrixXd S(n, 3 * k); // column j of B as an n x 3 block (rows are vertices)
        for (Eigen::Index j = 0; j < k; ++j)
            S.middleCols(3 * j, 3) = Eigen::Map<const RowBlock>(B.col(j).data(), n, 3);
        const Eigen::MatrixXd Y = fresh ? solver_.solve_fresh(builder_.finish(), S)
                                        : solver_.solve_with_last_factor(S);
        Eigen::MatrixXd U(B.rows(), k);
        for (Eigen::Index j = 0; j < k; ++j)
            Eigen::Map<RowBlock>(U.col(j).data(), n, 3) = Y.middleCols(3 * j, 3);
        return U;
    }

  private:
    using RowBlock = Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>;
    bool separable_ = false;
    SparseBuilder builder_;
    SparseDirectSolver solver_{Factorization::Cholesky};
};

/// The step of minimize.h from the first variation d: K y = -T^T grad E + B p, B^T y = dV with
/// B = T^T G, by the Schur complement (solvers/schur_complement.h; with many bodies by
/// iterations preconditioned with the Schur complement of an earlier step); K is factorised
/// (fresh) in the first solve only.
Eigen::VectorXd constrained_step(StepSystem& K, bool fresh, LaggedSchurComplement& schur,
                                 const Variation& d, const Eigen::VectorXd& dV,
                                 Eigen::VectorXd& p) {
    const auto solve = [&](const Eigen::MatrixXd& R) {
        const Eigen::MatrixXd U = K.solve(R, fresh);
        fresh = false;
        return U;
    };
    return schur.solve(solve, d.grad_volume, -d.grad_energy_full, dV, p);
}

Eigen::VectorXd flatten(const std::vector<Vec3>& X) {
    return Eigen::Map<const Eigen::VectorXd>(X[0].data(), 3 * static_cast<Eigen::Index>(X.size()));
}

std::vector<Vec3> unflatten(const Eigen::VectorXd& x) {
    std::vector<Vec3> X(x.size() / 3);
    for (std::size_t v = 0; v < X.size(); ++v) X[v] = x.segment<3>(3 * v);
    return X;
}

class Minimizer {
  public:
    Minimizer(Cluster& c, const MinimizeOptions& o, MinimizeCarry* carry)
        : c_(c), o_(o), system_(c), carry_(carry ? *carry : own_carry_) {
        hessian_ = o.hessian && !c.anisotropic() && !c.has_walls();
        double area = 0;
        for (double a : surface_areas(c)) area += a;
        R2_ = area / (4 * M_PI);
        tau_ = o.tau_start * R2_;
        for (const WallPtr& w : c.walls()) all_walls_flat_ = all_walls_flat_ && w->is_flat();
        for (double a : surface_areas(c)) initial_area_ += a;
    }

    MinimizeResult run() {
        const auto t0 = Clock::now();
        EngineLoopScope loop;
        MinimizeResult r;
        int rejects_in_row = 0;
        // a mesh that starts with small angles (after transitions) stops only once they halve
        const double start_angle = min_facet_angle(c_.positions());
        for (;;) {
            const PositionBasis P(c_);
            const PairGeometry g = pair_geometry(c_);
            const Variation d = first_variation(c_, P, g);
            const EquilibriumState s = balance(d);
            const std::vector<double> V = body_volumes(c_);
            r.residual = s.residual, r.pressures = s.pressures;
            r.volume_error = max_target_deviation(c_, V);
            if (r.residual <= o_.tol && r.volume_error <= o_.volume_tol) {
                r.converged = true, r.stop_reason = "converged";
                break;
            }
            if (r.iterations >= o_.max_iterations) {
                r.stop_reason = "max_iterations";
                break;
            }
            if (consume_interrupt()) {
                r.stop_reason = "interrupted";
                break;
            }
            if (rejects_in_row > 40) {
                r.stop_reason = "stalled: no step of tau >= " + fmt(tau_ / R2_) +
                                " R^2 lowers the energy (residual " + fmt(r.residual) + ")";
                break;
            }
            const bool newton = try_hessian_step(P, g, d, V, s);
            if (newton || try_step(P, g, d, V)) {
                ++r.iterations, rejects_in_row = 0;
                r.hessian_steps += newton;
                tau_ = std::min(tau_ * o_.tau_growth, o_.tau_max * R2_);
                double area = 0;
                for (double a : surface_areas(c_)) area += a;
                if (area < 1e-6 * initial_area_) {
                    r.stop_reason = "topology: the films have shrunk to " + fmt(area / initial_area_) +
                                    " of their area (nothing holds them: no body, no wall)";
                    break;
                }
                if (o_.settle > 0 && settled(r)) break;
                const double angle = min_facet_angle(c_.positions());
                if (angle < std::min(kDegenerateAngle, 0.5 * start_angle)) {
                    r.stop_reason = "topology: a facet angle fell to " + fmt(angle) +
                                    " degrees (a film or triple line is collapsing: the "
                                    "energy goes down by a change of topology, e.g. a pinch-off)";
                    break;
                }
            } else {
                ++r.rejected, ++rejects_in_row;
                tau_ /= 8;
                anderson_.reset();
            }
        }
        if (!r.converged) { // the state after the last accepted step
            const PositionBasis P(c_);
            const EquilibriumState s = balance(first_variation(c_, P, pair_geometry(c_)));
            r.residual = s.residual, r.pressures = s.pressures;
        }
        r.tau = tau_ / R2_;
        r.energy = energy(c_);
        r.volumes = body_volumes(c_);
        r.volume_error = max_target_deviation(c_, r.volumes);
        r.wall_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
        return r;
    }

  private:
    /// Records the energy of the step just accepted; true (r.stop_reason set) if it moved by at
    /// most settle |E| over the last settle_window steps (MinimizeOptions::settle).
    bool settled(MinimizeResult& r) {
        std::vector<double>& E = carry_.energies;
        E.push_back(energy(c_));
        const std::size_t n = static_cast<std::size_t>(o_.settle_window) + 1;
        if (E.size() > n) E.erase(E.begin(), E.end() - static_cast<std::ptrdiff_t>(n));
        if (E.size() < n) return false;
        // a rise (a transition's or the upkeep's between rounds) is no more settled than a fall
        const double drop = (E.front() - E.back()) / std::abs(E.back());
        if (!(std::abs(drop) <= o_.settle)) return false;
        r.stop_reason = "settled: the energy changed by " + fmt(-drop) + " of itself in the last " +
                        std::to_string(o_.settle_window) + " steps";
        return true;
    }

    /// Newton's step (hessian_step.h) where MinimizeOptions::hessian asks for it and the
    /// residual is below hessian_below: tried with the carried mu (MinimizeCarry), ten times
    /// larger after each failure (the merit rises, a facet angle halves, the system is
    /// singular) up to kHessianTries times; then none for 10, 20, 40, ... iterations, counted
    /// across the rounds. False: the cluster unchanged.
    bool try_hessian_step(const PositionBasis& P, const PairGeometry& g, const Variation& d,
                          const std::vector<double>& V, const EquilibriumState& s) {
        if (!hessian_ || s.residual > o_.hessian_below) return false;
        if (carry_.newton_pause > 0) return --carry_.newton_pause, false;
        const int nc = c_.n_volume_constraints();
        const Eigen::VectorXd dV = volume_defects(V);
        const std::vector<double> p(s.pressures.begin(), s.pressures.begin() + nc);
        double& mu = carry_.newton_mu;
        for (int k = 0; k < kHessianTries; ++k, mu *= 10) {
            HessianStep step;
            try {
                step = hessian_step(c_, P, g, p, dV, mu, carry_.newton_schur);
            } catch (const SolverError&) {
                continue;
            }
            restore_volumes(P, d, step.X);
            const auto merit = [&](const std::vector<Vec3>& Y) {
                return lagrangian(Y, step.pressures);
            };
            const double bound = merit(c_.positions()) + 1e-12 * std::abs(d.energy);
            if (acceptable(step.X, merit, bound) &&
                min_facet_angle(step.X) >= kAngleKept * min_facet_angle(c_.positions())) {
                c_.set_positions(std::move(step.X));
                mu = std::max(mu / 10, kMinMu);
                anderson_.reset();
                return true;
            }
        }
        // a mesh whose second variation misleads Newton (slivers, junctions tangled below the
        // mesh's scale) fails again: each failure doubles the pause (the 1000-cell foam's four
        // tries, each with a fresh Schur complement, cost 7 minutes)
        carry_.newton_pause = carry_.newton_next_pause;
        carry_.newton_next_pause *= 2;
        return false;
    }

    /// One step at the current tau (accelerated at the largest tau); false (cluster unchanged)
    /// if it collapses a facet or raises the energy by more than the volume correction accounts
    /// for.
    bool try_step(const PositionBasis& P, const PairGeometry& g, const Variation& d,
                  const std::vector<double>& V) {
        try {
            return try_step_or_throw(P, g, d, V);
        } catch (const SolverError&) { // a nearly singular system: a smaller tau regularises it
            has_factor_ = false;
            return false;
        }
    }

    bool try_step_or_throw(const PositionBasis& P, const PairGeometry& g, const Variation& d,
                           const std::vector<double>& V) {
        // At the largest tau the factor is reused for kReuse steps: the fixed point
        // (grad E = G p, y = 0) does not depend on the matrix, only the rate does, and a step
        // that fails the merit test is retried with a fresh one.
        const bool limit = tau_ >= o_.tau_max * R2_;
        const bool fresh = !limit || steps_on_factor_ >= kReuse || !has_factor_;
        if (fresh) {
            system_.assemble(c_, P, g, tau_);
            steps_on_factor_ = 0, has_factor_ = true;
        }
        ++steps_on_factor_;
        const Eigen::VectorXd dV = volume_defects(V);
        Eigen::VectorXd p;
        const Eigen::VectorXd y = constrained_step(system_, fresh, carry_.schur, d, dV, p);
        std::vector<Vec3> X = c_.positions();
        for (int v = 0; v < c_.n_vertices(); ++v) X[v] += P.displacement(y, v);
        if (!all_walls_flat_) project_onto_walls_of(c_, X);
        const auto merit = [&](const std::vector<Vec3>& Y) { return lagrangian(Y, p); };
        const double bound = merit(c_.positions()) + 1e-12 * std::abs(d.energy);
        if (limit) {
            const Eigen::VectorXd x = flatten(c_.positions());
            std::vector<Vec3> A = unflatten(anderson_.next(x, flatten(X) - x));
            if (!all_walls_flat_) project_onto_walls_of(c_, A);
            restore_volumes(P, d, A);
            if (acceptable(A, merit, bound) &&
                min_facet_angle(A) >= kAngleKept * min_facet_angle(c_.positions())) {
                c_.set_positions(std::move(A));
                return true;
            }
            anderson_.reset();
        }
        restore_volumes(P, d, X);
        if (!acceptable(X, merit, bound)) {
            if (!fresh) steps_on_factor_ = kReuse, tau_ *= 8; // retry at once, freshly factored
            return false;
        }
        // A step that would collapse a facet is retried smaller a few times (the caller divides
        // tau by 8): the first steps after a topological transition are too long for the small
        // facets beside it. A collapse that outlasts the retries is a change of topology.
        if (angle_retries_ < kAngleRetries &&
            min_facet_angle(X) < std::min(kDegenerateAngle, 0.5 * min_facet_angle(c_.positions()))) {
            ++angle_retries_;
            return false;
        }
        angle_retries_ = 0;
        c_.set_positions(std::move(X));
        return true;
    }

    /// Moves X along W G (W = diag(1 / m_v), within the walls' tangents) until every body has
    /// its target volume to round-off: a few Newton steps on the n_bodies equations, the
    /// projection that keeps Anderson's mixed iterates (and every other) volume exact.
    void restore_volumes(const PositionBasis& P, const Variation& d, std::vector<Vec3>& X) const {
        const int nb = c_.n_volume_constraints();
        double last = std::numeric_limits<double>::infinity();
        for (int it = 0; it < 12 && nb > 0; ++it) {
            const std::vector<double> V = body_volumes(c_, X);
            Eigen::VectorXd dV(nb);
            for (int b = 0; b < nb; ++b) dV[b] = c_.target_volumes()[b] - V[b];
            // Newton halves the deviation at least until it reaches the volumes' round-off
            // (3e-16 for most cells of a 1000-cell foam, 5e-13 for a filled box's last cell,
            // which carries the others' errors)
            const double deviation = max_target_deviation(c_, V);
            if (deviation <= 1e-15 || deviation > 0.5 * last) return;
            last = deviation;
            const Eigen::SparseMatrix<double> B =
                P.restrict(sparse_body_volume_gradients(c_, X)).leftCols(nb);
            const Eigen::SparseMatrix<double> WB = d.weight.asDiagonal() * B;
            const Eigen::VectorXd y = WB * solve_gram(B, WB, dV);
            for (int v = 0; v < c_.n_vertices(); ++v) X[v] += P.displacement(y, v);
        }
    }

    template <class Merit> bool acceptable(const std::vector<Vec3>& X, Merit&& merit, double bound) {
        return find_degenerate_facet(c_, X).first < 0 && merit(X) <= bound;
    }

    /// The smallest corner angle of any facet at X, degrees. The corner is found by its
    /// cotangent u.w / |u x w|, which falls as the angle grows, so only one atan2 is taken.
    double min_facet_angle(const std::vector<Vec3>& X) const {
        double best_cot = -std::numeric_limits<double>::infinity(), sine = 0, cosine = -1;
        for (const Surface& s : c_.surfaces())
            for (std::size_t f = 0; f < s.triangles.size(); ++f)
                for (int k = 0; k < 3; ++k) {
                    const auto x = s.corners(X, f);
                    const Vec3 u = x[(k + 1) % 3] - x[k], w = x[(k + 2) % 3] - x[k];
                    const double sn = u.cross(w).norm(), cs = u.dot(w);
                    // a degenerate corner (sn = 0) counts as 0 degrees unless it is a flat 180
                    const double cot = sn > 0 ? cs / sn
                                              : (cs >= 0 ? std::numeric_limits<double>::infinity()
                                                         : -std::numeric_limits<double>::infinity());
                    if (cot > best_cot)
                        best_cot = cot, sine = sn, cosine = cs;
                }
        return std::atan2(sine, cosine) * 180 / M_PI;
    }

    /// V*_b - V_b for the volume constraints (Cluster::n_volume_constraints).
    Eigen::VectorXd volume_defects(const std::vector<double>& V) const {
        Eigen::VectorXd dV(c_.n_volume_constraints());
        for (int b = 0; b < dV.size(); ++b)
            dV[b] = c_.target_volumes()[b] - V[b];
        return dV;
    }

    /// The merit of a step: the Lagrangian E - p . (V - V*) at X with the step's multipliers
    /// p, the energy at fixed volumes to first order, so that a step that corrects the volumes
    /// is not mistaken for one that raises the energy.
    double lagrangian(const std::vector<Vec3>& X, const Eigen::VectorXd& p) const {
        const std::vector<double> W = body_volumes(c_, X);
        double m = energy_at(X);
        for (int b = 0; b < p.size(); ++b)
            m -= p[b] * (W[b] - c_.target_volumes()[b]);
        return m;
    }

    double energy_at(const std::vector<Vec3>& X) const {
        double e = 0;
        for (const Surface& s : c_.surfaces())
            for (std::size_t f = 0; f < s.triangles.size(); ++f)
                e += 0.5 * s.density(area_vector2(s.corners(X, f)));
        return e;
    }

    static constexpr int kReuse = 8;       ///< steps per factorisation at the largest tau
    /// Anderson's extrapolations may not shrink the smallest facet angle below this fraction
    /// of the current one in one step (the plain steps are the scheme's own and keep theirs).
    static constexpr double kAngleKept = 0.5;
    /// Below this smallest facet angle (degrees) minimize stops: the mesh is collapsing.
    static constexpr double kDegenerateAngle = 1.0;
    static constexpr int kAngleRetries = 3;
    static constexpr int kHessianTries = 4;
    static constexpr double kMinMu = 1e-6; ///< relative to sigma_mean / R^2 (hessian_step.h)
    bool hessian_ = false;
    double initial_area_ = 0;
    int steps_on_factor_ = 0;
    int angle_retries_ = 0; // steps in a row refused for collapsing a facet
    bool has_factor_ = false;
    Cluster& c_;
    const MinimizeOptions& o_;
    double R2_ = 1, tau_ = 1;
    bool all_walls_flat_ = true;
    StepSystem system_;
    MinimizeCarry own_carry_;
    MinimizeCarry& carry_; // own_carry_ or the caller's
    Anderson anderson_{8};
};

} // namespace

EquilibriumState equilibrium_state(const Cluster& c) {
    if (auto [s, f] = find_degenerate_facet(c, c.positions()); s >= 0)
        throw GeometryError("pressures: " + facet_name(s, f) + " has zero area");
    const PositionBasis P(c);
    return balance(first_variation(c, P, pair_geometry(c)));
}

MinimizeResult minimize(Cluster& c, const MinimizeOptions& options, MinimizeCarry* carry) {
    check(options);
    check_filled_box_targets(c, "minimize");
    if (auto [s, f] = find_degenerate_facet(c, c.positions()); s >= 0)
        throw GeometryError("minimize: " + facet_name(s, f) + " has zero area");
    const std::vector<Vec3> X0 = c.positions();
    try {
        return Minimizer(c, options, carry).run();
    } catch (const std::exception&) {
        c.set_positions(X0);
        throw;
    }
}

} // namespace froth
