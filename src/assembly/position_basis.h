#pragma once
/// The space V_partial^h of (3.10)/(3.11) as a change of basis (numerics.md §3): at a vertex
/// attached to walls, dX_v = T_v y_v with T_v an orthonormal basis of the directions tangent to
/// its walls (3x2 on one wall, 3x1 on two), none at a fixed vertex; elsewhere T_v = I. The position unknowns of the
/// systems are the y_v, numbered vertex by vertex. T_v follows the wall normals at X^m (the
/// seed's linearisation), so it changes each step on curved walls; its size never does.

#include "assembly/sparse_builder.h"
#include "mesh/cluster.h"

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include <vector>

namespace froth {

class PositionBasis {
  public:
    /// The basis at the cluster's current positions.
    explicit PositionBasis(const Cluster& c);

    int size() const { return offset_.back(); }
    int offset(int v) const { return offset_[v]; }
    int dim(int v) const { return offset_[v + 1] - offset_[v]; }
    /// T_v (columns beyond dim(v) unused); the identity at a free vertex.
    const Eigen::Matrix3d& T(int v) const { return constrained_[v] ? T_[v] : identity_; }
    bool constrained(int v) const { return constrained_[v]; }

    /// M(y_a, y_b) += value T_a^T T_b (a value times I_3 in the full coordinates).
    void add_scaled_identity(SparseBuilder& M, int a, int b, double value) const;
    /// M(y_a, y_b) += T_a^T B T_b.
    void add_block(SparseBuilder& M, int a, int b, const Eigen::Matrix3d& B) const;
    /// M(y_v, col) += T_v^T u and M(col, y_v) += u^T T_v.
    void add_column_pair(SparseBuilder& M, int v, int col, const Eigen::Vector3d& u) const;
    /// T^T g for a full-coordinate vector g (3 per vertex).
    Eigen::VectorXd restrict(const Eigen::VectorXd& g) const;
    /// T^T G for a sparse full-coordinate matrix G (3 rows per vertex), column by column.
    Eigen::SparseMatrix<double> restrict(const Eigen::SparseMatrix<double>& G) const;
    /// d projected onto the directions vertex v may move in, T_v T_v^T d.
    Eigen::Vector3d project_tangent(int v, const Eigen::Vector3d& d) const {
        if (!constrained_[v]) return d;
        const auto T = T_[v].leftCols(dim(v));
        return T * (T.transpose() * d);
    }
    /// The displacement of vertex v, T_v y_v, from the reduced solution.
    Eigen::Vector3d displacement(const Eigen::VectorXd& y, int v) const;

  private:
    std::vector<int> offset_;
    std::vector<char> constrained_;
    std::vector<Eigen::Matrix3d> T_;
    Eigen::Matrix3d identity_ = Eigen::Matrix3d::Identity();
};

} // namespace froth
