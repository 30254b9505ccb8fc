#pragma once
/// @file DenseCoefficients.h
/// Structural coefficients (seed eq. 6.7) for general domains, where nearly every C[k][i][j] is
/// non-zero: the k < j half in the packed layout of PackedLayout.h, N²(N−1)/2 doubles. Each
/// contraction streams the array once, split over OpenMP threads by contiguous pair ranges.

#include <cstddef>
#include <span>
#include <vector>

#include "engine/dynamics/StructuralCoefficients.h"

namespace modeflow {

class DenseCoefficients final : public StructuralCoefficients {
public:
    /// Takes the packed array (PackedLayout.h); throws modeflow::Error if its size is not
    /// packedSize(n).
    DenseCoefficients(int n, std::vector<double> packed);

    /// From a full array, full[(k·N + i)·N + j] = C[k][i][j]. Keeps the k < j half and measures
    /// the antisymmetry error (see antisymmetryError()); throws modeflow::Error if the size is
    /// not N³ or the error exceeds `tolerance` (a sign that the array is not what it claims).
    static DenseCoefficients fromFull(int n, std::span<const double> full, double tolerance = 1e-8);

    /// max |C[k][i][j] + C[j][i][k]| / max |C[k][i][j]| of the array fromFull was given (0 if
    /// C ≡ 0 or if built from packed data, which is antisymmetric by construction).
    double antisymmetryError() const { return mAntisymmetryError; }

    /// The packed array, for the cache writer and the GPU upload.
    const std::vector<double>& packed() const { return mPacked; }

    int size() const override { return mN; }
    std::size_t storedBytes() const override { return mPacked.size() * sizeof(double); }
    double entry(int k, int i, int j) const override;
    void apply(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
               Eigen::VectorXd& out) const override;
    void linearize(const Eigen::VectorXd& a, const Eigen::VectorXd& b, Eigen::MatrixXd& byI,
                   Eigen::MatrixXd& byJ) const override;
    void advect(const Eigen::VectorXd& u, const Eigen::VectorXd& x,
                Eigen::VectorXd& out) const override;

private:
    /// Equal-size contiguous pair ranges, one per thread.
    std::vector<std::size_t> threadBounds() const;

    int mN = 0;
    std::vector<double> mPacked;
    std::vector<int> mPairK, mPairJ;  ///< (k, j) of each packed pair, so kernels need no index math
    double mAntisymmetryError = 0.0;
};

}  // namespace modeflow
