#pragma once
/// Anisotropic surface energy densities of the class (1.15) of the seed (Barrett, Garcke and
/// Nürnberg 2009), their duals (1.16), the seed's presets (1.17), (5.6), Figs. 2 and 3. The
/// element matrices of <nabla_s^Gt X, nabla_s^Gt chi>_gamma (1.24a,b) are assembly/elements.h.
///
///   gamma(p)   = ( sum_l [gamma_l(p)]^r )^(1/r),  gamma_l(p) = sqrt(p . G_l p),  r >= 1   (1.15)
///   gamma'(p)  = gamma^(1-r) sum_l gamma_l^(r-1) G_l p / gamma_l                         (1.15)
///   gamma*(q)  = sup_{p != 0} (q . p) / gamma(p)                                          (1.16)

#include <Eigen/Dense>

#include <array>
#include <vector>

namespace froth {

/// One anisotropy gamma_i of the form (1.15); immutable after construction.
class Anisotropy {
  public:
    /// gamma from the matrices G_l (each symmetric positive definite) and r >= 1. Throws
    /// InvalidInput naming the term (1-based) and the value when a G_l is not symmetric, not
    /// positive definite or not finite, when r < 1 or not finite, or when there is no term.
    explicit Anisotropy(std::vector<Eigen::Matrix3d> G, double r = 1.0);

    /// (1.17): G_l = R(theta_l)^T diag(1, eps^2, eps^2) R(theta_l), R = R1(t1) R2(t2) R3(t3).
    /// Throws InvalidInput for eps <= 0 (or not finite), no angles, r < 1.
    static Anisotropy from_angles(double eps, const std::vector<Eigen::Vector3d>& theta,
                                  double r = 1.0);

    // Presets (the seed's examples).
    /// (1.14): gamma(p) = sigma |p| (L = 1, G = sigma^2 I).
    static Anisotropy isotropic(double sigma = 1.0);
    /// L = 1, r = 1: gamma(p) = sqrt(p . G p); its Wulff shape is the ellipsoid q . G^-1 q <= 1.
    static Anisotropy ellipsoidal(const Eigen::Matrix3d& G);
    /// (5.6), Fig. 2 left (and with r = 30 Fig. 3 left): the regularised l1 norm,
    /// gamma(p) = sum_j [eps^2 |p|^2 + p_j^2 (1 - eps^2)]^(1/2), i.e. (1.17) with L = 3,
    /// theta = (0, (pi/2,0,0), (0,pi/2,0)).
    static Anisotropy l1(double eps, double r = 1.0);
    /// Fig. 2 right: (1.17) with r = 1, L = 4, theta = (0, (0,pi/3,0), (0,2pi/3,0), (pi/2,0,0));
    /// the seed uses eps = 1e-2.
    static Anisotropy hexagonal(double eps = 1e-2);
    /// Fig. 3 left: l1(eps, 30), the seed uses eps = 1e-2.
    static Anisotropy fig3_left(double eps = 1e-2);
    /// Fig. 3 right: (1.17) with r = 30, L = 6, theta = (0, (0,pi/2,0), (pi/4,0,0), (-pi/4,0,0),
    /// (0,pi/2,pi/4), (0,pi/2,-pi/4)); the seed uses eps = 1e-2.
    static Anisotropy fig3_right(double eps = 1e-2);

    int n_terms() const { return static_cast<int>(G_.size()); }
    double r() const { return r_; }
    const Eigen::Matrix3d& G(int l) const { return G_[l]; }
    /// Gt_l = det(G_l)^(1/2) G_l^-1, the metric of (1.24a,b).
    const Eigen::Matrix3d& G_tilde(int l) const { return Gt_[l]; }
    bool is_isotropic() const { return isotropic_; }
    /// True if gamma has several terms and some is needle-like: the largest eigenvalue of G_l
    /// at least 25 times the middle one (eps <= 0.2 in (1.17)). Such gamma (l1, hexagonal,
    /// Fig. 3) are close to crystalline; their Wulff shapes have sharp edges and the schemes
    /// make thin facets along them. (One needle term alone is a smooth elongated ellipsoid.)
    bool nearly_crystalline() const { return nearly_crystalline_; }

    /// gamma_l(p) = sqrt(p . G_l p).
    double gamma_term(int l, const Eigen::Vector3d& p) const;
    /// gamma(p), positively homogeneous of degree 1; gamma(0) = 0.
    double gamma(const Eigen::Vector3d& p) const;
    /// gamma'(p), homogeneous of degree 0; p must be non-zero.
    Eigen::Vector3d gamma_prime(const Eigen::Vector3d& p) const;
    /// gamma''(p), homogeneous of degree -1, symmetric positive semidefinite with p in its kernel.
    Eigen::Matrix3d gamma_hessian(const Eigen::Vector3d& p) const;
    /// The lagged weights [gamma_l(nu)/gamma(nu)]^(r-1) of (1.24a) (all 1 for r = 1).
    std::vector<double> term_weights(const Eigen::Vector3d& nu) const;
    /// The gradients of term_weights at a non-zero p (not necessarily unit; homogeneous of
    /// degree -1): dw_l/dp = (r - 1) w_l (G_l p / gamma_l^2 - gamma'(p) / gamma(p)); all zero
    /// for r = 1. Newton's method for (3.9) needs them (numerics.md "Anisotropic schemes").
    std::vector<Eigen::Vector3d> term_weight_gradients(const Eigen::Vector3d& p) const;

    /// gamma*(q) of (1.16). Computed as 1 / min { gamma(p) : q . p = 1 } (the sup is attained
    /// with q . p > 0 and is scale invariant), a smooth convex problem on a plane, solved by
    /// damped Newton from the best of a sphere sampling; see numerics.md "Anisotropy". If
    /// `argmax` is given it receives the maximiser p (unit length), for which gamma'(p) is
    /// parallel to q (Cahn–Hoffmann). gamma*(0) = 0.
    double gamma_star(const Eigen::Vector3d& q, Eigen::Vector3d* argmax = nullptr) const;

  private:
    std::vector<Eigen::Matrix3d> G_;
    std::vector<Eigen::Matrix3d> Gt_;
    double r_ = 1.0;
    bool isotropic_ = false;
    bool nearly_crystalline_ = false;
    // gamma_l for all l, with their maximum (to evaluate powers r without overflow).
    void terms(const Eigen::Vector3d& p, std::vector<double>& g, double& gmax) const;
};

/// n points of the Fibonacci spiral, nearly uniform on the unit sphere (n >= 1): the starting
/// guesses of gamma_star and the direction sets of the Wulff shapes (wulff/).
std::vector<Eigen::Vector3d> fibonacci_sphere(int n);

} // namespace froth
