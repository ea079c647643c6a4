#pragma once
/// Compressed row lists (internal to the mesh module).

#include <utility>
#include <vector>

namespace froth {

/// Builds CSR lists from (key, value) pairs: list[start[k] .. start[k+1]) are the values of key
/// k, in the order of the pairs.
inline void build_csr_lists(int n_keys, const std::vector<std::pair<int, int>>& pairs,
                            std::vector<int>& start, std::vector<int>& list) {
    start.assign(n_keys + 1, 0);
    for (const auto& kv : pairs) ++start[kv.first + 1];
    for (int k = 0; k < n_keys; ++k) start[k + 1] += start[k];
    list.resize(pairs.size());
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (const auto& [k, value] : pairs) list[fill[k]++] = value;
}

} // namespace froth
