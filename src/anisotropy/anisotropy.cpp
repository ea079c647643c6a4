#include "anisotropy/anisotropy.h"

#include "core/errors.h"
#include "core/format.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

namespace froth {

using Eigen::Matrix3d;
using Eigen::Vector3d;

namespace {

std::string term_name(std::size_t l) {
    return "anisotropy: term " + std::to_string(l + 1);
}

void validate_G(const Matrix3d& G, std::size_t l) {
    if (!G.allFinite()) throw InvalidInput(term_name(l) + ": G has a non-finite entry");
    const double scale = G.cwiseAbs().maxCoeff();
    const double asym = (G - G.transpose()).cwiseAbs().maxCoeff();
    if (asym > 1e-12 * scale)
        throw InvalidInput(term_name(l) + ": G is not symmetric (|G - G^T| = " + fmt(asym) + ")");
    const Eigen::SelfAdjointEigenSolver<Matrix3d> eig(G, Eigen::EigenvaluesOnly);
    const double lmin = eig.eigenvalues().minCoeff();
    if (!(lmin > 0.0))
        throw InvalidInput(term_name(l) + ": G is not positive definite (smallest eigenvalue " +
                           fmt(lmin) + ")");
    // gamma_l(p)^2 = p.G p must not overflow for any normal a cluster can have (|p| up to the
    // area of a facet with coordinates of 1e100 is excluded elsewhere; here the scale of G).
    if (!(scale >= 1e-100 && scale <= 1e100))
        throw InvalidInput(term_name(l) + ": G's entries must be between 1e-100 and 1e100 in "
                           "magnitude (the largest is " + fmt(scale) + "); scale sigma instead");
    const double lmax = eig.eigenvalues().maxCoeff();
    if (lmin < 1e-14 * lmax)
        throw InvalidInput(term_name(l) + ": G is too close to singular (eigenvalues " +
                           fmt(lmin) + " .. " + fmt(lmax) + ")");
}

void validate_r(double r) {
    if (!std::isfinite(r) || !(r >= 1.0))
        throw InvalidInput("anisotropy: r must be a finite number >= 1 (got " + fmt(r) + ")");
}

// The rotations of (1.17).
Matrix3d R1(double t) {
    const double c = std::cos(t), s = std::sin(t);
    Matrix3d R;
    R << c, s, 0, -s, c, 0, 0, 0, 1;
    return R;
}
Matrix3d R2(double t) {
    const double c = std::cos(t), s = std::sin(t);
    Matrix3d R;
    R << c, 0, s, 0, 1, 0, -s, 0, c;
    return R;
}
Matrix3d R3(double t) {
    const double c = std::cos(t), s = std::sin(t);
    Matrix3d R;
    R << 1, 0, 0, 0, c, s, 0, -s, c;
    return R;
}

// Fibonacci points on the unit sphere: the starting guesses of gamma_star.
const std::vector<Vector3d>& sphere_samples() {
    static const std::vector<Vector3d> pts = fibonacci_sphere(400);
    return pts;
}

} // namespace

std::vector<Vector3d> fibonacci_sphere(int n) {
    std::vector<Vector3d> v;
    v.reserve(n);
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (int i = 0; i < n; ++i) {
        const double z = 1.0 - (2.0 * i + 1.0) / n;
        const double rho = std::sqrt(std::max(0.0, 1.0 - z * z));
        v.emplace_back(rho * std::cos(golden * i), rho * std::sin(golden * i), z);
    }
    return v;
}

Anisotropy::Anisotropy(std::vector<Matrix3d> G, double r) : G_(std::move(G)), r_(r) {
    if (G_.empty()) throw InvalidInput("anisotropy: needs at least one term (L = 0)");
    validate_r(r_);
    Gt_.reserve(G_.size());
    for (std::size_t l = 0; l < G_.size(); ++l) {
        validate_G(G_[l], l);
        G_[l] = 0.5 * (G_[l] + G_[l].transpose());
        // (1.24a): Gt = det(G)^(1/2) G^-1, computed for G / s (s its largest entry) and scaled
        // back by s^(1/2), so that the determinant cannot overflow or underflow.
        const double s = G_[l].cwiseAbs().maxCoeff();
        const Matrix3d unit = G_[l] / s;
        Gt_.push_back(std::sqrt(s * unit.determinant()) * unit.inverse());
        if (!Gt_.back().allFinite())
            throw InvalidInput(term_name(l) + ": G is too close to singular");
        const Vector3d lambda =
            Eigen::SelfAdjointEigenSolver<Matrix3d>(G_[l], Eigen::EigenvaluesOnly).eigenvalues();
        nearly_crystalline_ = nearly_crystalline_ || lambda[2] >= 25.0 * lambda[1];
    }
    nearly_crystalline_ = nearly_crystalline_ && G_.size() > 1;
    if (G_.size() == 1) {
        const double d = G_[0](0, 0);
        isotropic_ = (G_[0] - d * Matrix3d::Identity()).cwiseAbs().maxCoeff() <= 1e-15 * d;
    }
}

Anisotropy Anisotropy::from_angles(double eps, const std::vector<Vector3d>& theta, double r) {
    if (!std::isfinite(eps) || !(eps > 0.0))
        throw InvalidInput("anisotropy: eps must be a finite number > 0 (got " + fmt(eps) + ")");
    if (theta.empty()) throw InvalidInput("anisotropy: needs at least one term (L = 0)");
    const Matrix3d D = Vector3d(1.0, eps * eps, eps * eps).asDiagonal();
    std::vector<Matrix3d> G;
    for (std::size_t l = 0; l < theta.size(); ++l) {
        if (!theta[l].allFinite())
            throw InvalidInput(term_name(l) + ": the angles theta are not finite");
        // (1.17): R(theta) = R1(theta_1) R2(theta_2) R3(theta_3), G = R^T diag(1, eps^2, eps^2) R.
        const Matrix3d R = R1(theta[l][0]) * R2(theta[l][1]) * R3(theta[l][2]);
        G.push_back(R.transpose() * D * R);
    }
    return Anisotropy(std::move(G), r);
}

Anisotropy Anisotropy::isotropic(double sigma) {
    if (!std::isfinite(sigma) || !(sigma > 0.0))
        throw InvalidInput("anisotropy: sigma must be a finite number > 0 (got " + fmt(sigma) +
                           ")");
    return Anisotropy({sigma * sigma * Matrix3d::Identity()}, 1.0);
}

Anisotropy Anisotropy::ellipsoidal(const Matrix3d& G) {
    return Anisotropy({G}, 1.0);
}

Anisotropy Anisotropy::l1(double eps, double r) {
    // (5.6) = (1.17) with theta = (0, (pi/2,0,0), (0,pi/2,0)) (Fig. 2 left): the three terms are
    // eps^2 |p|^2 + (1 - eps^2) p_j^2 for j = 1, 2, 3.
    const double h = std::numbers::pi / 2;
    return from_angles(eps, {Vector3d(0, 0, 0), Vector3d(h, 0, 0), Vector3d(0, h, 0)}, r);
}

Anisotropy Anisotropy::hexagonal(double eps) {
    const double pi = std::numbers::pi;
    return from_angles(eps,
                       {Vector3d(0, 0, 0), Vector3d(0, pi / 3, 0), Vector3d(0, 2 * pi / 3, 0),
                        Vector3d(pi / 2, 0, 0)},
                       1.0);
}

Anisotropy Anisotropy::fig3_left(double eps) {
    return l1(eps, 30.0);
}

Anisotropy Anisotropy::fig3_right(double eps) {
    const double pi = std::numbers::pi;
    return from_angles(eps,
                       {Vector3d(0, 0, 0), Vector3d(0, pi / 2, 0), Vector3d(pi / 4, 0, 0),
                        Vector3d(-pi / 4, 0, 0), Vector3d(0, pi / 2, pi / 4),
                        Vector3d(0, pi / 2, -pi / 4)},
                       30.0);
}

double Anisotropy::gamma_term(int l, const Vector3d& p) const {
    return std::sqrt(std::max(0.0, p.dot(G_[l] * p)));
}

void Anisotropy::terms(const Vector3d& p, std::vector<double>& g, double& gmax) const {
    g.resize(G_.size());
    gmax = 0.0;
    for (std::size_t l = 0; l < G_.size(); ++l) {
        g[l] = gamma_term(static_cast<int>(l), p);
        gmax = std::max(gmax, g[l]);
    }
}

double Anisotropy::gamma(const Vector3d& p) const {
    if (!p.allFinite()) throw InvalidInput("anisotropy: gamma of a non-finite vector");
    std::vector<double> g;
    double gmax;
    terms(p, g, gmax);
    if (gmax == 0.0) return 0.0;
    if (r_ == 1.0) {
        double s = 0.0;
        for (double x : g)
            s += x;
        return s;
    }
    // gamma = gmax (sum (g_l/gmax)^r)^(1/r): no overflow for large r.
    double s = 0.0;
    for (double x : g)
        s += std::pow(x / gmax, r_);
    return gmax * std::pow(s, 1.0 / r_);
}

std::vector<double> Anisotropy::term_weights(const Vector3d& nu) const {
    std::vector<double> w(G_.size(), 1.0);
    if (r_ == 1.0) return w;
    const double gam = gamma(nu);
    if (!(gam > 0.0)) throw InvalidInput("anisotropy: the weights need a non-zero normal");
    for (std::size_t l = 0; l < G_.size(); ++l)
        w[l] = std::pow(gamma_term(static_cast<int>(l), nu) / gam, r_ - 1.0);
    return w;
}

std::vector<Vector3d> Anisotropy::term_weight_gradients(const Vector3d& p) const {
    std::vector<Vector3d> d(G_.size(), Vector3d::Zero());
    if (r_ == 1.0) return d;
    const std::vector<double> w = term_weights(p);
    const Vector3d dgamma = gamma_prime(p) / gamma(p);
    for (std::size_t l = 0; l < G_.size(); ++l) {
        const double gl = gamma_term(static_cast<int>(l), p);
        d[l] = (r_ - 1.0) * w[l] * (G_[l] * p / (gl * gl) - dgamma);
    }
    return d;
}

Vector3d Anisotropy::gamma_prime(const Vector3d& p) const {
    // (1.15): gamma' = sum_l [gamma_l/gamma]^(r-1) G_l p / gamma_l.
    if (!(p.norm() > 0.0)) throw InvalidInput("anisotropy: gamma' needs a non-zero vector");
    const std::vector<double> w = term_weights(p);
    Vector3d d = Vector3d::Zero();
    for (std::size_t l = 0; l < G_.size(); ++l)
        d += w[l] * (G_[l] * p) / gamma_term(static_cast<int>(l), p);
    return d;
}

Eigen::Matrix3d Anisotropy::gamma_hessian(const Vector3d& p) const {
    // gamma'' = sum_l w_l [G_l + (r - 2) g_l' g_l'^T] / g_l + (1 - r)/gamma gamma' gamma'^T, with
    // g_l' = G_l p / g_l and w_l = (g_l/gamma)^(r-1); for r = 1: sum_l (G_l - g_l' g_l'^T)/g_l.
    if (!(p.norm() > 0.0)) throw InvalidInput("anisotropy: gamma'' needs a non-zero vector");
    const std::vector<double> w = term_weights(p);
    Matrix3d H = Matrix3d::Zero();
    Vector3d gp = Vector3d::Zero();
    for (std::size_t l = 0; l < G_.size(); ++l) {
        const double gl = gamma_term(static_cast<int>(l), p);
        const Vector3d dl = G_[l] * p / gl;
        H += w[l] * (G_[l] + (r_ - 2.0) * dl * dl.transpose()) / gl;
        gp += w[l] * dl;
    }
    if (r_ != 1.0) H += (1.0 - r_) / gamma(p) * gp * gp.transpose();
    return 0.5 * (H + H.transpose());
}

double Anisotropy::gamma_star(const Vector3d& q_in, Vector3d* argmax) const {
    const double qn = q_in.norm();
    if (!std::isfinite(qn)) throw InvalidInput("anisotropy: gamma_star of a non-finite vector");
    if (qn == 0.0) {
        if (argmax) *argmax = Vector3d::Zero();
        return 0.0;
    }
    // gamma* is homogeneous of degree 1: work with the unit vector q.
    const Vector3d q = q_in / qn;

    // Start: the best of the sphere samples and of the single-term maximisers G_l^-1 q.
    Vector3d best = q;
    double best_val = q.dot(q) / gamma(q);
    auto consider = [&](const Vector3d& p) {
        const double qp = q.dot(p);
        if (qp <= 0.0) return;
        const double v = qp / gamma(p);
        if (v > best_val) best_val = v, best = p;
    };
    for (const Vector3d& p : sphere_samples())
        consider(p);
    for (const Matrix3d& G : G_)
        consider(G.ldlt().solve(q));

    // gamma*(q) = 1 / min { gamma(p) : q . p = 1 }: minimise the convex phi(s) = gamma(p0 + T s)
    // on the plane q . p = 1 (p0 = q, T an orthonormal basis of q^perp) by damped Newton.
    Vector3d t1 = q.unitOrthogonal();
    Vector3d t2 = q.cross(t1);
    Eigen::Matrix<double, 3, 2> T;
    T.col(0) = t1, T.col(1) = t2;
    Vector3d p = best / q.dot(best);
    double phi = gamma(p);
    for (int it = 0; it < 200; ++it) {
        const Eigen::Vector2d g = T.transpose() * gamma_prime(p);
        Eigen::Matrix2d H = T.transpose() * gamma_hessian(p) * T;
        // H is positive definite on q^perp for SPD G_l (the kernel of gamma'' is span p, and
        // q . p = 1); guard against round-off with a tiny Levenberg shift.
        H.diagonal().array() += 1e-14 * H.trace();
        Eigen::Vector2d d = -H.ldlt().solve(g);
        double dec = -g.dot(d); // Newton decrement squared
        if (!(dec > 0.0) || !d.allFinite()) d = -g, dec = g.squaredNorm();
        if (dec <= 1e-30 * phi * phi) break;
        double t = 1.0;
        bool moved = false;
        for (int ls = 0; ls < 60; ++ls, t *= 0.5) {
            const Vector3d pn = p + T * (t * d);
            const double phin = gamma(pn);
            if (phin < phi && phin <= phi - 1e-4 * t * dec) {
                p = pn, phi = phin, moved = true;
                break;
            }
        }
        if (!moved) {
            // phi is flat to round-off here, so Armijo cannot see progress; near the minimum the
            // full Newton step still sharpens the maximiser (quadratic convergence): take it
            // while it reduces the gradient.
            const Vector3d pn = p + T * d;
            if ((T.transpose() * gamma_prime(pn)).norm() < 0.5 * g.norm())
                p = pn, phi = std::min(phi, gamma(pn));
            else
                break;
        }
    }
    if (argmax) *argmax = p.normalized();
    return qn / phi;
}

} // namespace froth
