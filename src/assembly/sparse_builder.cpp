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
    // Pattern: unique (col, row) pairs in column-major order; slot = position in valuePtr.
    std::vector<long long> keys(rows_.size());
    const long long n_rows = M_.rows();
    for (std::size_t k = 0; k < rows_.size(); ++k) keys[k] = cols_[k] * n_rows + rows_[k];
    std::vector<long long> unique_keys = keys;
    std::sort(unique_keys.begin(), unique_keys.end());
    unique_keys.erase(std::unique(unique_keys.begin(), unique_keys.end()), unique_keys.end());
    std::vector<Eigen::Triplet<double>> pattern;
    pattern.reserve(unique_keys.size());
    for (long long key : unique_keys)
        pattern.emplace_back(static_cast<int>(key % n_rows), static_cast<int>(key / n_rows), 0.0);
    M_.setFromTriplets(pattern.begin(), pattern.end());
    M_.makeCompressed();
    slot_.resize(keys.size());
    for (std::size_t k = 0; k < keys.size(); ++k) {
        slot_[k] = static_cast<int>(std::lower_bound(unique_keys.begin(), unique_keys.end(),
                                                     keys[k]) - unique_keys.begin());
        M_.valuePtr()[slot_[k]] += values_[k];
    }
    recording_ = false;
    next_ = slot_.size();
    rows_ = {}, cols_ = {}, values_ = {};
    return M_;
}

} // namespace froth
