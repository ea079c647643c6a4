#pragma once
/// Anderson acceleration of fixed-point iterations x -> x + f(x) (type II, as in Walker and
/// Ni, SIAM J. Numer. Anal. 49, 2011): the next iterate combines the last `depth` iterates so
/// that the linearised residual is smallest. Used where the schemes (schemes/) iterate a linear solve to
/// a fixed point that converges linearly: minimize's steps at the largest tau and the averaged
/// normals of the volume-exact surface diffusion step.

#include <Eigen/Dense>

#include <vector>

namespace froth {

/// The iteration's history; reset() when a step is rejected or the map changes.
class Anderson {
  public:
    explicit Anderson(int depth) : depth_(depth) {}
    void reset() { dx_.clear(), df_.clear(), have_last_ = false; }
    /// The next iterate from x and f = step(x) - x.
    Eigen::VectorXd next(const Eigen::VectorXd& x, const Eigen::VectorXd& f) {
        if (have_last_) {
            dx_.push_back(x - x_last_), df_.push_back(f - f_last_);
            if (static_cast<int>(dx_.size()) > depth_) dx_.erase(dx_.begin()), df_.erase(df_.begin());
        }
        x_last_ = x, f_last_ = f, have_last_ = true;
        if (dx_.empty()) return x + f;
        Eigen::MatrixXd DF(f.size(), df_.size()), DX(f.size(), dx_.size());
        for (std::size_t j = 0; j < df_.size(); ++j) DF.col(j) = df_[j], DX.col(j) = dx_[j];
        const Eigen::VectorXd gamma = DF.colPivHouseholderQr().solve(f);
        return x + f - (DX + DF) * gamma;
    }

  private:
    int depth_;
    std::vector<Eigen::VectorXd> dx_, df_;
    Eigen::VectorXd x_last_, f_last_;
    bool have_last_ = false;
};

} // namespace froth
