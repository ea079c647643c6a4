// Mean curvature flow: the system (4.6b) of mean_curvature.h.
#include "schemes/mean_curvature.h"

#include "assembly/stiffness.h"

namespace froth {

void assemble_mcf(const Cluster& c, const PairGeometry& g, const PositionBasis& P, double tau,
                  const FacetNormals* lagged, SparseBuilder& M, Eigen::VectorXd& rhs) {
    const int n = P.size();
    M.begin(n, n);
    add_position_stiffness(c, P, lagged, M);
    // (4.6b): kappa_iv = m_iv omega_iv . dX_v / (tau mb_iv) from the lumped (3.7a), so (3.7b)
    // gains m_iv^2 / mb_iv omega_iv omega_iv^T / tau (mb = m for beta = 1).
    const bool beta = !g.mass_beta.empty();
    for (int v = 0; v < c.n_vertices(); ++v) {
        Eigen::Matrix3d B = Eigen::Matrix3d::Zero();
        for (int k = c.pair_begin(v); k < c.pair_begin(v + 1); ++k) {
            const double m = beta ? g.mass[k] * g.mass[k] / g.mass_beta[k] : g.mass[k];
            B += m * g.omega[k] * g.omega[k].transpose();
        }
        P.add_block(M, v, v, B / tau);
    }
    M.finish();
    rhs.resize(n);
    set_minus_stiffness_rhs(c, P, lagged, rhs);
}

} // namespace froth
