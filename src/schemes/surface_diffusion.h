#pragma once
/// Surface diffusion, the seed's (3.6a,b) (isotropic), (3.8a,b) (anisotropic, r = 1) and
/// (3.11a,b) (with walls):
///   < (X^{m+1} - X^m) / tau, chi nu^m >^h = -< beta nabla_s kappa^{m+1}, nabla_s chi >   (3.8a)
///   < kappa^{m+1} nu^m, eta >^h + < nabla_s^Gt X^{m+1}, nabla_s^Gt eta >_gamma = 0       (3.8b)
/// with kappa in W^h: one value per (surface, vertex) pair, tied at triple lines by (1.10)/(3.3)
/// through the null-space basis kappa = Z k (assembly/kappa_basis.h). In dX = T y the step is
/// the symmetric saddle point
///   [ T^T A_gamma T    T^T N Z          ] [y]   [ -T^T A_gamma X^m ]
///   [ Z^T N^T T       -tau Z^T A_beta Z ] [k] = [  0               ]
/// A_beta the per-surface scalar stiffness weighted by beta_i(nu_sigma), N mapping kappa_iv to
/// m_iv omega_iv at vertex v; solved by UMFPACK. Testing with (y, k) gives the seed's
/// Theorem 3.4: E(X^{m+1}) <= E(X^m) for every tau. The linear scheme changes each body's
/// volume by O(tau^2) a step; the volume-exact form (the default; volume_exact_sd.cpp, the
/// equations in assembly/exact_volumes.h) replaces m omega by the Simpson-averaged area vectors
/// of the step in both off-diagonal blocks, a fixed point in dX that keeps every body at its
/// target volume and keeps the symmetric structure, hence the same energy bound.

#include "schemes/scheme.h"

#include "assembly/kappa_basis.h"

#include <memory>

namespace froth {

/// The saddle point of one step into M and rhs (positions first, then k), with the line
/// relaxation term of Scheme::set_line_relaxation in the position block for a time > 0.
void assemble_sd(const Cluster& c, const PairGeometry& g, const KappaBasis& Z,
                 const PositionBasis& P, double tau, const FacetNormals* lagged, SparseBuilder& M,
                 Eigen::VectorXd& rhs, double line_relaxation = 0);

class SurfaceDiffusionScheme final : public Scheme {
  public:
    /// exact_volumes: the volume-exact step on clusters with bodies; else the seed's (3.6).
    explicit SurfaceDiffusionScheme(bool exact_volumes);
    std::unique_ptr<Scheme> clone() const override;
    void set_exact_volumes(bool exact) { exact_ = exact; }
    /// How the saddle points are solved (solvers/sparse_solvers.h SaddleSolver).
    void set_saddle_solver(SaddleSolver how) { saddle_solver_ = how; }
    bool holds_volumes(const Cluster& c) const override { return exact_ && c.n_bodies() > 0; }
    bool iterative(const Cluster& c) const override { return c.nonlinear() || holds_volumes(c); }
    Eigen::VectorXd solve(const Cluster& c, double tau, const PositionBasis& P,
                          const FixedPointOptions& fp, StepCost& cost) override;
    void reset() override;
    /// "sd.last_z", "sd.last_tau", "sd.last_end": the warm start (nothing before a
    /// volume-exact step).
    void save_history(std::vector<NamedValues>& out) const override;
    void restore_history(const Cluster& c, const std::vector<NamedValues>& in) override;

  protected:
    /// Order 2; when volume-exact, the linear BDF2 corrector plus a uniform normal velocity per
    /// body (volume_exact_sd.cpp).
    Eigen::VectorXd solve_corrector(const Cluster& c, const Bdf2Step& s, const PositionBasis& P,
                                    StepCost& cost) override;
    void assemble_system(const Cluster& c, const PairGeometry& g, const PositionBasis& P,
                         double tau, const FacetNormals* lagged) override;
    void drop_systems() override;

  private:
    /// The volume-exact step: the fixed point over the averaged normals (volume_exact_sd.cpp).
    /// Its order-2 form corrects the linear BDF2 step by the kappa-row terms of volume_rhs.
    Eigen::VectorXd solve_corrector_exact_volumes(const Cluster& c, const Bdf2Step& s,
                                             const PositionBasis& P, StepCost& cost);
    Eigen::VectorXd solve_exact_volumes(const Cluster& c, double tau, const PositionBasis& P,
                                        const FixedPointOptions& fp, StepCost& cost);
    bool exact_;
    SaddleSolver saddle_solver_ = SaddleSolver::Auto;
    std::shared_ptr<const KappaBasis>
        Z_; ///< of the cluster's topology (immutable: shared by copies)
    // Set during a volume-exact step: the kappa rows assemble_system adds.
    const Eigen::VectorXd* kappa_rhs_ = nullptr;
    // The volume-exact step's Newton-corrected system: the averaged normals' derivative C and
    // the solver of (M(w) + C).
    SparseBuilder volume_jacobian_;
    SparseDirectSolver exact_solver_{Factorization::LU};
    // The last volume-exact step's solution, its tau and the positions it ended at: the next
    // step starts its fixed point from it (positions scaled by the taus) when it starts there.
    Eigen::VectorXd last_z_;
    double last_tau_ = 1;
    std::vector<Vec3> last_end_;
};

} // namespace froth
