// Surface diffusion: the saddle point of surface_diffusion.h, and the scheme's cached kappa
// basis and systems (the volume-exact step is volume_exact_sd.cpp).
#include "schemes/surface_diffusion.h"

#include "assembly/exact_volumes.h"
#include "assembly/stiffness.h"

namespace froth {

void assemble_sd(const Cluster& c, const PairGeometry& g, const KappaBasis& Z,
                 const PositionBasis& P, double tau, const FacetNormals* lagged, SparseBuilder& M,
                 Eigen::VectorXd& rhs) {
    const int n = P.size(), size = n + Z.n_reduced;
    M.begin(size, size);
    add_position_stiffness(c, P, lagged, M);
    // -tau Z^T A_beta Z: the scalar stiffness of each surface, weighted by beta_i(nu_sigma), on
    // its kappa pairs, through Z. (3.8a)
    std::vector<int> facet(c.n_surfaces(), 0);
    for_each_facet(c, [&](int i, const Tri& t, const Eigen::Matrix3d& K) {
        const double beta = g.facet_beta.empty() ? 1.0 : g.facet_beta[i][facet[i]];
        ++facet[i];
        int p[3];
        for (int a = 0; a < 3; ++a)
            p[a] = c.pair_index(t[a], i);
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                for (int x = Z.start[p[a]]; x < Z.start[p[a] + 1]; ++x)
                    for (int y = Z.start[p[b]]; y < Z.start[p[b] + 1]; ++y)
                        M.add(n + Z.col[x], n + Z.col[y],
                              -tau * beta * K(a, b) * Z.val[x] * Z.val[y]);
    });
    // N Z and its transpose: <kappa nu, eta>^h = m_iv kappa_iv omega_iv . eta_v (3.8b).
    for (int v = 0; v < c.n_vertices(); ++v)
        for (int k = c.pair_begin(v); k < c.pair_begin(v + 1); ++k)
            for (int x = Z.start[k]; x < Z.start[k + 1]; ++x)
                P.add_column_pair(M, v, n + Z.col[x], g.mass[k] * Z.val[x] * g.omega[k]);
    M.finish();
    rhs = Eigen::VectorXd::Zero(size);
    set_minus_stiffness_rhs(c, P, lagged, rhs);
}

SurfaceDiffusionScheme::SurfaceDiffusionScheme(bool exact_volumes)
    : Scheme(Factorization::LU), exact_(exact_volumes) {}

std::unique_ptr<Scheme> SurfaceDiffusionScheme::clone() const {
    return std::make_unique<SurfaceDiffusionScheme>(*this);
}

Eigen::VectorXd SurfaceDiffusionScheme::solve(const Cluster& c, double tau, const PositionBasis& P,
                                              const FixedPointOptions& fp, StepCost& cost) {
    return holds_volumes(c) ? solve_exact_volumes(c, tau, P, fp, cost)
                            : Scheme::solve(c, tau, P, fp, cost);
}

void SurfaceDiffusionScheme::reset() {
    Scheme::reset();
    Z_.reset();
    last_z_.resize(0), last_end_.clear();
}

void SurfaceDiffusionScheme::drop_systems() {
    Scheme::drop_systems();
    volume_jacobian_ = SparseBuilder(), exact_solver_ = SparseDirectSolver(Factorization::LU);
}

void SurfaceDiffusionScheme::assemble_system(const Cluster& c, const PairGeometry& g,
                                             const PositionBasis& P, double tau,
                                             const FacetNormals* lagged) {
    if (!Z_) Z_ = std::make_shared<const KappaBasis>(kappa_basis(c));
    assemble_sd(c, g, *Z_, P, tau, lagged, matrix_, rhs_);
    if (kappa_rhs_) add_kappa_rhs(*Z_, *kappa_rhs_, P.size(), rhs_);
}

} // namespace froth
