// Newton's step for minimize on the normal directions (hessian_step.h has the equations).
#include "flows/hessian_step.h"

#include "assembly/lagrangian_hessian.h"
#include "assembly/stiffness.h"
#include "solvers/schur_complement.h"
#include "solvers/sparse_solvers.h"

#include <Eigen/Dense>

#include <cmath>

namespace froth {

Eigen::MatrixXd normal_basis(const Cluster& c, const PositionBasis& P, const PairGeometry& g,
                             int v) {
    const int n = P.dim(v), pairs = c.pair_begin(v + 1) - c.pair_begin(v);
    if (n == 0) return Eigen::MatrixXd(0, 0); // a fixed vertex
    Eigen::MatrixXd N(n, pairs);
    for (int k = 0; k < pairs; ++k)
        N.col(k) = P.T(v).leftCols(n).transpose() * g.omega[c.pair_begin(v) + k];
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(N, Eigen::ComputeThinU);
    const auto& s = svd.singularValues();
    int rank = 0;
    while (rank < s.size() && s[rank] > 1e-8 * s[0])
        ++rank;
    return svd.matrixU().leftCols(rank);
}

namespace {

/// N = diag(T_v Q_v) (3 rows per vertex, a column per normal unknown) and the unknowns' lumped
/// masses m_v.
struct NormalUnknowns {
    SparseMatrix N;
    Eigen::VectorXd mass;
};

NormalUnknowns normal_unknowns(const Cluster& c, const PositionBasis& P, const PairGeometry& g,
                               const Eigen::VectorXd& vertex_mass) {
    std::vector<Eigen::Triplet<double>> t;
    std::vector<double> mass;
    for (int v = 0; v < c.n_vertices(); ++v) {
        const Eigen::MatrixXd Q = normal_basis(c, P, g, v);
        if (Q.size() == 0) continue;
        const Eigen::MatrixXd B = P.T(v).leftCols(P.dim(v)) * Q;
        for (Eigen::Index j = 0; j < B.cols(); ++j) {
            for (int i = 0; i < 3; ++i)
                t.emplace_back(3 * v + i, static_cast<int>(mass.size()), B(i, j));
            mass.push_back(vertex_mass[v]);
        }
    }
    NormalUnknowns u;
    u.N.resize(3 * c.n_vertices(), static_cast<Eigen::Index>(mass.size()));
    u.N.setFromTriplets(t.begin(), t.end());
    u.mass = Eigen::Map<const Eigen::VectorXd>(mass.data(), static_cast<Eigen::Index>(mass.size()));
    return u;
}

} // namespace

HessianStep hessian_step(const Cluster& c, const PositionBasis& P, const PairGeometry& g,
                         const std::vector<double>& pressures, const Eigen::VectorXd& dV, double mu,
                         LaggedSchurComplement& schur) {
    const std::vector<Vec3>& X = c.positions();
    const Eigen::VectorXd vertex_mass = vertex_masses(c, g);
    const NormalUnknowns u = normal_unknowns(c, P, g, vertex_mass);
    const SparseMatrix Nt = u.N.transpose();
    const Eigen::VectorXd f = -(Nt * apply_stiffness(c, X));
    const SparseMatrix G =
        Nt * sparse_body_volume_gradients(c, X).leftCols(c.n_volume_constraints());
    const double total_area = vertex_mass.sum();
    const double sigma_mean = energy(c) / total_area, R2 = total_area / (4 * M_PI);
    // mu M as a sparse diagonal: coeffRef would insert where N^T H N has no diagonal entry
    std::vector<Eigen::Triplet<double>> damping;
    for (Eigen::Index k = 0; k < u.mass.size(); ++k)
        damping.emplace_back(k, k, mu * sigma_mean / R2 * u.mass[k]);
    SparseMatrix D(u.mass.size(), u.mass.size());
    D.setFromTriplets(damping.begin(), damping.end());
    const SparseMatrix K = Nt * lagrangian_hessian(c, pressures) * u.N + D;
    SparseDirectSolver lu(Factorization::LU);
    bool fresh = true;
    const auto solve = [&](const Eigen::MatrixXd& B) {
        Eigen::MatrixXd Y = fresh ? lu.solve_fresh(K, B) : lu.solve_with_last_factor(B);
        fresh = false;
        return Y;
    };
    HessianStep step;
    const Eigen::VectorXd z = schur.solve(solve, G, f, dV, step.pressures);
    const Eigen::VectorXd dX = u.N * z;
    step.X = X;
    for (int v = 0; v < c.n_vertices(); ++v)
        step.X[v] += dX.segment<3>(3 * v);
    return step;
}

} // namespace froth
