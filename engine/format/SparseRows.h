#pragma once
/// @file SparseRows.h
/// A sparse matrix by rows (CSR) as a cache file stores it: row r holds the entries
/// start[r] … start[r+1]−1 of `column` and `value`.

#include <cstdint>
#include <vector>

namespace modeflow {

struct SparseRows {
    std::vector<std::int64_t> start{0};
    std::vector<std::int32_t> column;
    std::vector<double> value;

    std::int64_t rows() const { return std::int64_t(start.size()) - 1; }
    std::int64_t nonZeros() const { return std::int64_t(value.size()); }
    /// Bytes of the three arrays.
    std::size_t bytes() const {
        return start.size() * sizeof(std::int64_t) + column.size() * sizeof(std::int32_t) +
               value.size() * sizeof(double);
    }
};

}  // namespace modeflow
