// orient_parts: one orientation for a surface made of separately oriented parts.
#include "mesh/orient_parts.h"

#include "core/errors.h"

#include <algorithm>
#include <tuple>
#include <utility>

namespace froth {

// Works from the triangles alone: gmsh's oriented getBoundary signs are wrong in 4.8, and mesh
// files carry none. Each manifold seam between two parts links their signs; a depth-first walk
// fixes them, and a seam that contradicts the walk means no orientation exists.
void orient_parts(std::vector<std::vector<NodeTri>>& parts, const std::string& what) {
    if (parts.size() < 2) return;
    struct Half {
        std::size_t lo, hi;
        int part, dir;
    };
    std::vector<Half> h;
    for (int p = 0; p < static_cast<int>(parts.size()); ++p)
        for (const NodeTri& t : parts[p])
            for (int k = 0; k < 3; ++k) {
                const std::size_t a = t[k], b = t[(k + 1) % 3];
                h.push_back({std::min(a, b), std::max(a, b), p, a < b ? 1 : -1});
            }
    std::sort(h.begin(), h.end(), [](const Half& x, const Half& y) {
        return std::tie(x.lo, x.hi) < std::tie(y.lo, y.hi);
    });
    // links[p]: (q, r) meaning sign[q] must be r * sign[p]
    std::vector<std::vector<std::pair<int, int>>> links(parts.size());
    for (std::size_t i = 0, j; i < h.size(); i = j) {
        for (j = i + 1; j < h.size() && h[j].lo == h[i].lo && h[j].hi == h[i].hi; ++j) {
        }
        if (j - i != 2 || h[i].part == h[i + 1].part) continue; // only manifold seams link
        const int r = -h[i].dir * h[i + 1].dir;
        links[h[i].part].emplace_back(h[i + 1].part, r);
        links[h[i + 1].part].emplace_back(h[i].part, r);
    }
    std::vector<int> sign(parts.size(), 0);
    for (std::size_t root = 0; root < parts.size(); ++root) {
        if (sign[root] != 0) continue;
        sign[root] = 1;
        std::vector<int> stack{static_cast<int>(root)};
        while (!stack.empty()) {
            const int p = stack.back();
            stack.pop_back();
            for (auto [q, r] : links[p]) {
                if (sign[q] == 0)
                    sign[q] = r * sign[p], stack.push_back(q);
                else if (sign[q] != r * sign[p])
                    throw TopologyError(what + " cannot be oriented consistently");
            }
        }
    }
    for (std::size_t p = 0; p < parts.size(); ++p)
        if (sign[p] < 0)
            for (NodeTri& t : parts[p])
                std::swap(t[1], t[2]);
}

} // namespace froth
