#pragma once
/// @file SparseCoefficients.h
/// Structural coefficients (seed eq. 6.7) for domains where most C[k][i][j] vanish (boxes: a
/// mode triple interacts only when its wave vectors close a triangle, appendix C.2). Stored like
/// CSR with one row per pair k < j that has any non-zero: the row's (i, value) entries, i
/// ascending. Rows are ordered by (k, j), as in the dense layout.

#include <cstddef>
#include <cstdint>
#include <vector>

#include "engine/dynamics/StructuralCoefficients.h"

namespace modeflow {

class DenseCoefficients;

/// One stored coefficient C[k][i][j] = value, with k < j.
struct CoefficientEntry {
    int k = 0;
    int i = 0;
    int j = 0;
    double value = 0.0;
};

class SparseCoefficients final : public StructuralCoefficients {
public:
    /// Entries in any order, each with 0 ≤ k < j < n and 0 ≤ i < n, no (k, i, j) twice (throws
    /// modeflow::Error otherwise). C[j][i][k] = −value is implied; zero values are dropped.
    SparseCoefficients(int n, std::vector<CoefficientEntry> entries);
    /// The same from parallel lists (a cache's storage), taken over and freed as the rows are
    /// filled: memory of about 28 bytes an entry at the peak, against 48 through entries.
    /// @throw modeflow::Error as the constructor does, or for lists of different lengths.
    static SparseCoefficients fromLists(int n, std::vector<std::int32_t> k,
                                        std::vector<std::int32_t> i, std::vector<std::int32_t> j,
                                        std::vector<double> value);

    /// The entries of `dense` with |C| > relativeDropTolerance · max |C| (0 keeps every non-zero).
    static SparseCoefficients fromDense(const DenseCoefficients& dense,
                                        double relativeDropTolerance = 0.0);

    std::size_t nonZeros() const { return mValue.size(); }
    /// Stored fraction of the k < j half, nonZeros() / (N²(N−1)/2).
    double density() const;

    /// The raw arrays: row r is the pair (pairK()[r], pairJ()[r]) and holds the entries
    /// rowStart()[r] .. rowStart()[r+1]−1 of columns() (the index i) and values().
    const std::vector<int>& pairK() const { return mPairK; }
    const std::vector<int>& pairJ() const { return mPairJ; }
    const std::vector<std::size_t>& rowStart() const { return mRowStart; }
    const std::vector<int>& columns() const { return mColumn; }
    const std::vector<double>& values() const { return mValue; }

    int size() const override { return mN; }
    std::size_t storedBytes() const override;
    double entry(int k, int i, int j) const override;
    void apply(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
               Eigen::VectorXd& out) const override;
    void linearize(const Eigen::VectorXd& a, const Eigen::VectorXd& b, Eigen::MatrixXd& byI,
                   Eigen::MatrixXd& byJ) const override;
    void advect(const Eigen::VectorXd& u, const Eigen::VectorXd& x,
                Eigen::VectorXd& out) const override;

private:
    SparseCoefficients() = default;
    /// Contiguous row ranges of about equal entry counts, one per thread.
    std::vector<std::size_t> threadBounds() const;
    /// Σ_i C[k][i][j] a_i over the stored entries of row r.
    double rowDot(std::size_t r, const Eigen::VectorXd& a) const;

    int mN = 0;
    std::vector<int> mPairK, mPairJ;
    std::vector<std::size_t> mRowStart{0};
    std::vector<int> mColumn;
    std::vector<double> mValue;
};

}  // namespace modeflow
