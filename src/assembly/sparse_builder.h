#pragma once
/// Assembles a sparse matrix whose pattern is fixed after the first assembly. The first pass
/// records (row, col) of every contribution and builds the compressed pattern; later passes
/// must emit the same contributions in the same order and only add values into their slots.
/// So the solver's symbolic analysis is done once per mesh, and no triplet sort runs per step.

#include "solvers/sparse_solvers.h"

#include <vector>

namespace froth {

class SparseBuilder {
  public:
    /// Starts a pass; the first pass for a given size records the pattern.
    void begin(int rows, int cols);
    void add(int row, int col, double value) {
        if (recording_) {
            rows_.push_back(row);
            cols_.push_back(col);
            values_.push_back(value);
        } else {
            M_.valuePtr()[slot_[next_++]] += value;
        }
    }
    /// Ends a pass and returns the matrix (same pattern after every pass).
    const SparseMatrix& finish();

  private:
    SparseMatrix M_;
    bool recording_ = true;
    std::vector<int> rows_, cols_, slot_;
    std::vector<double> values_;
    std::size_t next_ = 0;
};

} // namespace froth
