#pragma once
/// @file PackedLayout.h
/// The packed layout of dense structural coefficients (engine/README.md, "Reduced dynamics", seed
/// eq. 6.7). Because C[k][i][j] = −C[j][i][k] (and so C[k][i][k] = 0), only the pairs k < j are
/// stored. Pairs are numbered in row order (0,1), (0,2), …, (0,N−1), (1,2), …, (N−2,N−1), and each
/// pair owns the contiguous vector over i:
///
///     packed[pairIndex(N,k,j) · N + i] = C[k][i][j]        (0 ≤ k < j < N, 0 ≤ i < N)
///
/// so one contraction reads the array front to back exactly once. The cache writer stores this
/// array as is and the Vulkan runtime uploads it as is.

#include <cstddef>

namespace modeflow {

/// Number of stored pairs k < j: N(N−1)/2.
constexpr std::size_t pairCount(std::size_t n) {
    return n * (n - 1) / 2;
}

/// Number of doubles in the packed array: N²(N−1)/2.
constexpr std::size_t packedSize(std::size_t n) {
    return pairCount(n) * n;
}

/// Position of the pair (k, j), k < j, in row order.
constexpr std::size_t pairIndex(std::size_t n, std::size_t k, std::size_t j) {
    return k * n - k * (k + 1) / 2 + (j - k - 1);
}

/// Position of C[k][i][j], k < j, in the packed array.
constexpr std::size_t packedIndex(std::size_t n, std::size_t k, std::size_t i, std::size_t j) {
    return pairIndex(n, k, j) * n + i;
}

}  // namespace modeflow
