#include "assembly/sparse_builder.h"

#include "core/errors.h"

#include <algorithm>

namespace froth {

void SparseBuilder::begin(int rows, int cols) {
    if (!recording_ && (M_.rows() != rows || M_.cols() != cols)) recording_ = true;
    if (recording_) {
        rows_.clear(), cols_.clear(), values_.clear();
        M_.resize(rows, cols);
    } else {
        std::fill(M_.valuePtr(), M_.valuePtr() + M_.nonZeros(), 0.0);
        next_ = 0;
    }
}

const SparseMatrix& SparseBuilder::finish() {
    if (!recording_) {
        if (next_ != slot_.size()) throw Error("assembly: pattern changed between passes");
        return M_;
    }
    // Pattern: unique (col, row) pairs in column-major order, built directly as compressed
    // columns from the sorted keys; slot = position in valuePtr. One sort of (key, index)
    // pairs gives both (a binary search per contribution cost 10% of a small minimize run).
    const long long n_rows = M_.rows();
    std::vector<std::pair<long long, int>> order(rows_.size());
    for (std::size_t k = 0; k < rows_.size(); ++k)
        order[k] = {cols_[k] * n_rows + rows_[k], static_cast<int>(k)};
    std::sort(order.begin(), order.end());
    slot_.resize(order.size());
    std::vector<int> outer(M_.cols() + 1, 0), inner;
    inner.reserve(order.size());
    long long last = -1;
    for (const auto& [key, k] : order) {
        if (key != last) {
            last = key;
            inner.push_back(static_cast<int>(key % n_rows));
            ++outer[key / n_rows + 1];
        }
        slot_[k] = static_cast<int>(inner.size()) - 1;
    }
    for (std::size_t j = 1; j < outer.size(); ++j) outer[j] += outer[j - 1];
    const std::vector<double> zeros(inner.size(), 0.0);
    M_ = Eigen::Map<const SparseMatrix>(M_.rows(), M_.cols(), static_cast<int>(inner.size()),
                                        outer.data(), inner.data(), zeros.data());
    // Values summed in the order of the contributions, as every later pass does.
    for (std::size_t k = 0; k < slot_.size(); ++k) M_.valuePtr()[slot_[k]] += values_[k];
    recording_ = false;
    next_ = slot_.size();
    rows_ = {}, cols_ = {}, values_ = {};
    return M_;
}

} // namespace froth
