#pragma once
/// Mean curvature flow, the seed's (3.5a,b) (isotropic), (3.7a,b) (anisotropic, r = 1) and
/// (3.10a,b) (with walls; X^{m+1} - X^m in V_partial^h):
///   < (X^{m+1} - X^m) / tau, chi nu^m >^h_mb = < kappa^{m+1}, chi >^h               (3.7a)
///   < kappa^{m+1} nu^m, eta >^h + < nabla_s^Gt X^{m+1}, nabla_s^Gt eta >_gamma = 0   (3.7b)
/// With mass lumping (3.7a) gives kappa_iv = m_iv omega_iv . dX_v / (tau mb_iv) per
/// (surface, vertex) pair, and eliminating it leaves the SPD system (4.6b) in dX = T y:
///   T^T ( A_gamma + 1/tau sum_i blockdiag_v(m_iv^2 / mb_iv omega_iv omega_iv^T) ) T y
///       = -T^T A_gamma X^m,
/// A_gamma the stiffness of assembly/stiffness.h (r > 1: weights at nu^{m+1}, (3.9)), m_iv the
/// lumped masses, omega_iv the area-weighted vertex normals, mb the mobility-weighted masses
/// (mb = m for beta = 1). Solved by CHOLMOD. Testing with y gives the seed's Theorem 3.2:
/// E(X^{m+1}) <= E(X^m) for every tau. Order 2 (bdf2.h) adds B~ E / tau' to the right side,
/// B the block above on the predictor and tau' = tau / a.

#include "schemes/scheme.h"

namespace froth {

/// The system (4.6b) of one step into M and rhs (also minimize's step, flows/minimize.h), with
/// the line relaxation term of Scheme::set_line_relaxation for a time > 0.
void assemble_mcf(const Cluster& c, const PairGeometry& g, const PositionBasis& P, double tau,
                  const FacetNormals* lagged, SparseBuilder& M, Eigen::VectorXd& rhs,
                  double line_relaxation = 0);

class MeanCurvatureScheme final : public Scheme {
  public:
    MeanCurvatureScheme() : Scheme(Factorization::Cholesky) {}
    std::unique_ptr<Scheme> clone() const override {
        return std::make_unique<MeanCurvatureScheme>(*this);
    }
    bool holds_volumes(const Cluster&) const override { return false; }

  protected:
    void assemble_system(const Cluster& c, const PairGeometry& g, const PositionBasis& P,
                         double tau, const FacetNormals* lagged) override;
};

} // namespace froth
