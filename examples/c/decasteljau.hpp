// A hand-written de Casteljau evaluation of a Bézier triangle: the kind of code tribez judges.
// Degree n, points in R^d, control points in tribez's canonical order (multi-indices
// (i, j, k), i + j + k = n, ordered by k ascending, then j ascending: 200, 110, 020, 101, 011,
// 002 for n = 2), d coordinates each.
#pragma once

#include <cstddef>
#include <vector>

namespace example {

// The position of (i, j, k), i + j + k = n, in the canonical order: the k rows before it hold
// (n + 1) + n + ... + (n + 2 - k) points, then j.
inline std::size_t tri_index(std::size_t n, std::size_t j, std::size_t k) {
    return k * (n + 1) - k * (k - 1) / 2 + j;
}

// The point of the triangle at barycentric (u, v, w): n levels of
// b^{r-1}_{ijk} = u b^r_{i+1,j,k} + v b^r_{i,j+1,k} + w b^r_{i,j,k+1}.
template <class T>
std::vector<T> de_casteljau(std::size_t n, std::size_t d, const T *net, T u, T v, T w) {
    std::vector<T> b(net, net + (n + 1) * (n + 2) / 2 * d);
    for (std::size_t r = n; r >= 1; --r) {
        std::vector<T> c(r * (r + 1) / 2 * d);
        for (std::size_t k = 0; k + 1 <= r; ++k) {
            for (std::size_t j = 0; j + k + 1 <= r; ++j) {
                const std::size_t to = tri_index(r - 1, j, k) * d;
                const std::size_t bi = tri_index(r, j, k) * d;      // (i + 1, j, k)
                const std::size_t bj = tri_index(r, j + 1, k) * d;  // (i, j + 1, k)
                const std::size_t bk = tri_index(r, j, k + 1) * d;  // (i, j, k + 1)
                for (std::size_t c_ = 0; c_ < d; ++c_) {
                    c[to + c_] = u * b[bi + c_] + v * b[bj + c_] + w * b[bk + c_];
                }
            }
        }
        b.swap(c);
    }
    return b;
}

}  // namespace example
