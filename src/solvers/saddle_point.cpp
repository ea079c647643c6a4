#include "solvers/saddle_point.h"

#include <Eigen/CholmodSupport>

#include <cmath>

namespace froth {

struct SaddlePointPreconditioner::Impl {
    int n = 0, m = 0;
    SparseMatrix B, C;  // symmetric parts of the coupling and of the kappa block (C = -K_22)
    Eigen::VectorXd w;  // the diagonal of W
    Eigen::CholmodSupernodalLLT<SparseMatrix, Eigen::Lower> h, s; // H^ and S^
    bool analyzed = false;
};

SaddlePointPreconditioner::SaddlePointPreconditioner() : impl_(std::make_unique<Impl>()) {
    impl_->h.cholmod().print = 0, impl_->s.cholmod().print = 0;
}

SaddlePointPreconditioner::~SaddlePointPreconditioner() = default;
SaddlePointPreconditioner::SaddlePointPreconditioner(SaddlePointPreconditioner&&) noexcept = default;
SaddlePointPreconditioner&
SaddlePointPreconditioner::operator=(SaddlePointPreconditioner&&) noexcept = default;

bool SaddlePointPreconditioner::factorize(const SparseMatrix& K, int n) {
    const int m = static_cast<int>(K.rows()) - n;
    if (n <= 0 || m <= 0) return false;
    if (impl_->analyzed && (impl_->n != n || impl_->m != m)) *this = SaddlePointPreconditioner();
    Impl& p = *impl_;
    p.n = n, p.m = m;
    const SparseMatrix H = K.topLeftCorner(n, n);
    const SparseMatrix B1 = K.topRightCorner(n, m);
    const SparseMatrix B2 = SparseMatrix(K.bottomLeftCorner(m, n)).transpose();
    const SparseMatrix C = -SparseMatrix(K.bottomRightCorner(m, m));
    const SparseMatrix Hs = 0.5 * (H + SparseMatrix(H.transpose()));
    p.B = 0.5 * (B1 + B2);
    p.C = 0.5 * (C + SparseMatrix(C.transpose()));
    Eigen::VectorXd D(m);
    for (int j = 0; j < m; ++j)
        D[j] = p.B.col(j).norm();
    // A kappa dof whose vertices are all fixed or on wires has no position coupling (D_j = 0):
    // its W_j meets no B, and S^_jj takes the mean mass.
    const double mean_d = D.sum() / std::max<Eigen::Index>(1, (D.array() > 0).count());
    for (int j = 0; j < m; ++j)
        if (D[j] == 0) D[j] = mean_d;
    const double mean_h = Hs.diagonal().sum() / n, mean_c = p.C.diagonal().sum() / m;
    if (!(mean_d > 0) || !(mean_h > 0) || !(mean_c > 0)) return false;
    const double sigma = std::sqrt(mean_c / mean_h);
    p.w = (sigma * D).cwiseInverse();
    const SparseMatrix Hhat = Hs + SparseMatrix(p.B * p.w.asDiagonal() * p.B.transpose());
    SparseMatrix Shat = p.C;
    for (int j = 0; j < m; ++j)
        Shat.coeffRef(j, j) += sigma * D[j];
    if (!p.analyzed) p.h.analyzePattern(Hhat), p.s.analyzePattern(Shat);
    p.analyzed = true;
    p.h.factorize(Hhat);
    if (p.h.info() != Eigen::Success) return false;
    p.s.factorize(Shat);
    return p.s.info() == Eigen::Success;
}

Eigen::VectorXd SaddlePointPreconditioner::apply(const Eigen::VectorXd& r) const {
    const Impl& p = *impl_;
    const auto rx = r.head(p.n), rk = r.tail(p.m);
    const Eigen::VectorXd yk = -p.s.solve(rk);
    // (B W) r_k from E, less B (I - W C) y_k from the upper block of P
    const Eigen::VectorXd t = p.w.cwiseProduct(rk) - yk + p.w.cwiseProduct(p.C * yk);
    Eigen::VectorXd y(r.size());
    y.head(p.n) = p.h.solve(rx + p.B * t);
    y.tail(p.m) = yk;
    return y;
}

} // namespace froth
