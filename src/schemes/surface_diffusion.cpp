// Surface diffusion: the saddle point of surface_diffusion.h, and the scheme's cached kappa
// basis and systems (the volume-exact step is volume_exact_sd.cpp).
#include "schemes/surface_diffusion.h"

#include "core/errors.h"

#include "assembly/exact_volumes.h"
#include "assembly/stiffness.h"

namespace froth {

void assemble_sd(const Cluster& c, const PairGeometry& g, const KappaBasis& Z,
                 const PositionBasis& P, double tau, const FacetNormals* lagged, SparseBuilder& M,
                 Eigen::VectorXd& rhs, double line_relaxation) {
    const int n = P.size(), size = n + Z.n_reduced;
    M.begin(size, size);
    add_position_stiffness(c, P, lagged, M);
    add_line_relaxation(c, g, P, line_relaxation / tau, M);
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

Eigen::VectorXd SurfaceDiffusionScheme::solve_corrector(const Cluster& c, const Bdf2Step& s,
                                                        const PositionBasis& P, StepCost& cost) {
    return holds_volumes(c) ? solve_corrector_exact_volumes(c, s, P, cost)
                            : Scheme::solve_corrector(c, s, P, cost);
}

void SurfaceDiffusionScheme::reset() {
    Scheme::reset();
    Z_.reset();
    last_z_.resize(0), last_end_.clear();
}

void SurfaceDiffusionScheme::save_history(std::vector<NamedValues>& out) const {
    if (last_end_.empty()) return;
    out.push_back({"sd.last_z", {last_z_.data(), last_z_.data() + last_z_.size()}});
    out.push_back({"sd.last_tau", {last_tau_}});
    std::vector<double> end;
    end.reserve(3 * last_end_.size());
    for (const Vec3& x : last_end_)
        end.insert(end.end(), {x[0], x[1], x[2]});
    out.push_back({"sd.last_end", std::move(end)});
}

void SurfaceDiffusionScheme::restore_history(const Cluster& c,
                                             const std::vector<NamedValues>& in) {
    const auto find = [&](const char* name) { return find_named(in, name); };
    const std::vector<double>*z = find("sd.last_z"), *tau = find("sd.last_tau"),
                           *end = find("sd.last_end");
    if (!z && !tau && !end) return;
    if (!z || !tau || !end || tau->size() != 1 || !(tau->front() > 0) ||
        end->size() != 3 * static_cast<std::size_t>(c.n_vertices()))
        throw InvalidInput("surface diffusion history: sd.last_z, sd.last_tau and sd.last_end "
                           "must come together, with one tau > 0 and 3 numbers per vertex");
    reset();
    Z_ = std::make_shared<const KappaBasis>(kappa_basis(c)); // the warm start's size check
    last_z_ = Eigen::Map<const Eigen::VectorXd>(z->data(), static_cast<Eigen::Index>(z->size()));
    last_tau_ = tau->front();
    last_end_.resize(c.n_vertices());
    for (int v = 0; v < c.n_vertices(); ++v)
        last_end_[v] = Vec3((*end)[3 * v], (*end)[3 * v + 1], (*end)[3 * v + 2]);
}

void SurfaceDiffusionScheme::drop_systems() {
    Scheme::drop_systems();
    volume_jacobian_ = SparseBuilder(), exact_solver_ = SparseDirectSolver(Factorization::LU);
}

void SurfaceDiffusionScheme::assemble_system(const Cluster& c, const PairGeometry& g,
                                             const PositionBasis& P, double tau,
                                             const FacetNormals* lagged) {
    if (!Z_) Z_ = std::make_shared<const KappaBasis>(kappa_basis(c));
    assemble_sd(c, g, *Z_, P, tau, lagged, matrix_, rhs_, line_relaxation_);
    for (SparseDirectSolver* s : {&solver_, &exact_solver_})
        s->set_saddle_point(P.size(), saddle_solver_);
    if (kappa_rhs_) add_kappa_rhs(*Z_, *kappa_rhs_, P.size(), rhs_);
    if (bdf2_) { // order 2 (bdf2.h): N~^T (a dX - b D) / a = N~^T dX - N~^T E
        Eigen::VectorXd memory(c.n_pairs());
        for (int v = 0; v < c.n_vertices(); ++v)
            for (int k = c.pair_begin(v); k < c.pair_begin(v + 1); ++k)
                memory[k] = g.mass[k] * g.omega[k].dot(bdf2_->memory[v]);
        add_kappa_rhs(*Z_, memory, P.size(), rhs_);
        add_line_relaxation_memory(c, g, P, tau);
    }
}

} // namespace froth
