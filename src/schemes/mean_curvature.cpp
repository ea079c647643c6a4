// Mean curvature flow: the system (4.6b) of mean_curvature.h.
#include "schemes/mean_curvature.h"

#include "assembly/stiffness.h"

namespace froth {

namespace {

/// sum_i m_iv^2 / mb_iv omega_iv omega_iv^T: the normal block of vertex v in (4.6b), times tau.
Eigen::Matrix3d normal_block(const Cluster& c, const PairGeometry& g, int v) {
    const bool beta = !g.mass_beta.empty();
    Eigen::Matrix3d B = Eigen::Matrix3d::Zero();
    for (int k = c.pair_begin(v); k < c.pair_begin(v + 1); ++k) {
        const double m = beta ? g.mass[k] * g.mass[k] / g.mass_beta[k] : g.mass[k];
        B += m * g.omega[k] * g.omega[k].transpose();
    }
    return B;
}

} // namespace

void assemble_mcf(const Cluster& c, const PairGeometry& g, const PositionBasis& P, double tau,
                  const FacetNormals* lagged, SparseBuilder& M, Eigen::VectorXd& rhs,
                  double line_relaxation) {
    const int n = P.size();
    M.begin(n, n);
    add_position_stiffness(c, P, lagged, M);
    // (4.6b): kappa_iv = m_iv omega_iv . dX_v / (tau mb_iv) from the lumped (3.7a), so (3.7b)
    // gains m_iv^2 / mb_iv omega_iv omega_iv^T / tau (mb = m for beta = 1).
    for (int v = 0; v < c.n_vertices(); ++v)
        P.add_block(M, v, v, normal_block(c, g, v) / tau);
    add_line_relaxation(c, g, P, line_relaxation / tau, M);
    M.finish();
    rhs.resize(n);
    set_minus_stiffness_rhs(c, P, lagged, rhs);
}

void MeanCurvatureScheme::assemble_system(const Cluster& c, const PairGeometry& g,
                                          const PositionBasis& P, double tau,
                                          const FacetNormals* lagged) {
    assemble_mcf(c, g, P, tau, lagged, matrix_, rhs_, line_relaxation_);
    if (!bdf2_) return;
    // Order 2 (bdf2.h): (a dX - b D) / tau_step = (dX - E) / tau with tau = tau_step / a.
    Eigen::VectorXd memory(3 * c.n_vertices());
    for (int v = 0; v < c.n_vertices(); ++v)
        memory.segment<3>(3 * v) = normal_block(c, g, v) * bdf2_->memory[v] / tau;
    rhs_ += P.restrict(memory);
    add_line_relaxation_memory(c, g, P, tau);
}

} // namespace froth
