#include "assembly/position_basis.h"

#include <Eigen/SVD>

namespace froth {

PositionBasis::PositionBasis(const Cluster& c) {
    const int n = c.n_vertices();
    offset_.assign(n + 1, 0);
    constrained_.assign(n, 0);
    T_.assign(c.has_walls() || c.has_fixed() ? n : 0, Eigen::Matrix3d::Identity());
    for (int v = 0; v < n; ++v) {
        const int free = c.vertex_freedom(v);
        offset_[v + 1] = offset_[v] + free;
        if (free == 3) continue;
        constrained_[v] = 1;
        if (free == 0) continue; // a fixed vertex: no directions
        const std::vector<int> walls = c.vertex_walls(v);
        Eigen::Matrix3Xd N(3, walls.size());
        for (std::size_t k = 0; k < walls.size(); ++k)
            N.col(k) = c.walls()[walls[k]]->normal(c.position(v));
        // The left singular vectors beyond the normals' rank span their orthogonal complement.
        Eigen::JacobiSVD<Eigen::Matrix3Xd> svd(N, Eigen::ComputeFullU);
        T_[v].leftCols(free) = svd.matrixU().rightCols(free);
    }
}

void PositionBasis::add_scaled_identity(SparseBuilder& M, int a, int b, double value) const {
    if (!constrained_[a] && !constrained_[b]) {
        for (int d = 0; d < 3; ++d) M.add(offset_[a] + d, offset_[b] + d, value);
        return;
    }
    add_block(M, a, b, value * Eigen::Matrix3d::Identity());
}

void PositionBasis::add_block(SparseBuilder& M, int a, int b, const Eigen::Matrix3d& B) const {
    const Eigen::Matrix3d R = T(a).transpose() * B * T(b);
    for (int r = 0; r < dim(a); ++r)
        for (int s = 0; s < dim(b); ++s) M.add(offset_[a] + r, offset_[b] + s, R(r, s));
}

void PositionBasis::add_column_pair(SparseBuilder& M, int v, int col,
                                    const Eigen::Vector3d& u) const {
    const Eigen::Vector3d w = T(v).transpose() * u;
    for (int d = 0; d < dim(v); ++d) {
        M.add(offset_[v] + d, col, w[d]);
        M.add(col, offset_[v] + d, w[d]);
    }
}

Eigen::VectorXd PositionBasis::restrict(const Eigen::VectorXd& g) const {
    Eigen::VectorXd y(size());
    for (int v = 0; v + 1 < static_cast<int>(offset_.size()); ++v)
        y.segment(offset_[v], dim(v)) = (T(v).transpose() * g.segment<3>(3 * v)).head(dim(v));
    return y;
}

Eigen::SparseMatrix<double> PositionBasis::restrict(const Eigen::SparseMatrix<double>& G) const {
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(3 * size());
    const int n = static_cast<int>(offset_.size()) - 1;
    for (int v = 0; v < n; ++v)
        for (int r = 0; r < dim(v); ++r)
            for (int d = 0; d < 3; ++d)
                if (T(v)(d, r) != 0) entries.emplace_back(offset_[v] + r, 3 * v + d, T(v)(d, r));
    Eigen::SparseMatrix<double> Tt(size(), 3 * n);
    Tt.setFromTriplets(entries.begin(), entries.end());
    return Tt * G;
}

Eigen::Vector3d PositionBasis::displacement(const Eigen::VectorXd& y, int v) const {
    if (!constrained_[v]) return y.segment<3>(offset_[v]);
    return T_[v].leftCols(dim(v)) * y.segment(offset_[v], dim(v));
}

} // namespace froth
