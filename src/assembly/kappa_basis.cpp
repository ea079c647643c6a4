#include "assembly/kappa_basis.h"

#include <Eigen/SVD>

namespace froth {

KappaBasis kappa_basis(const Cluster& c) {
    KappaBasis Z;
    std::vector<std::vector<std::pair<int, double>>> rows(c.n_pairs());
    for (int v = 0; v < c.n_vertices(); ++v) {
        const int first = c.pair_begin(v), n = c.pair_begin(v + 1) - first;
        const std::vector<int> edges = c.vertex_junction_edges(v);
        if (edges.empty()) { // no constraint: one free kappa per surface at v
            for (int p = 0; p < n; ++p) rows[first + p].emplace_back(Z.n_reduced++, 1.0);
            continue;
        }
        Eigen::MatrixXd C = Eigen::MatrixXd::Zero(static_cast<int>(edges.size()), n);
        for (int r = 0; r < static_cast<int>(edges.size()); ++r) {
            const JunctionEdge& e = c.junction_edges()[edges[r]];
            for (int j = 0; j < 3; ++j) C(r, c.pair_index(v, e.surfaces[j]) - first) = e.o[j];
        }
        // Null space from the full SVD: right singular vectors beyond the numerical rank.
        Eigen::JacobiSVD<Eigen::MatrixXd> svd(C, Eigen::ComputeFullV);
        svd.setThreshold(1e-10);
        const int rank = static_cast<int>(svd.rank());
        for (int b = rank; b < n; ++b, ++Z.n_reduced)
            for (int p = 0; p < n; ++p)
                if (std::abs(svd.matrixV()(p, b)) > 1e-14)
                    rows[first + p].emplace_back(Z.n_reduced, svd.matrixV()(p, b));
    }
    Z.start.push_back(0);
    for (const auto& row : rows) {
        for (auto [j, value] : row) Z.col.push_back(j), Z.val.push_back(value);
        Z.start.push_back(static_cast<int>(Z.col.size()));
    }
    return Z;
}

} // namespace froth
