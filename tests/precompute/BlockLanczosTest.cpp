/// @file BlockLanczosTest.cpp
/// Thick-restart block Lanczos (precompute/solve/BlockLanczos.h) on operators with known spectra:
/// the largest pairs to the tolerance, orthonormal vectors, the deflated directions kept out,
/// and clear refusals.

#include <gtest/gtest.h>

#include <string>

#include <Eigen/QR>

#include "engine/core/Error.h"
#include "precompute/solve/BlockLanczos.h"

namespace modeflow {
namespace {

/// A = Uᵀ diag(d) U for a fixed orthogonal U: a dense, non-diagonal operator with spectrum d.
class KnownSpectrum {
public:
    explicit KnownSpectrum(const Eigen::VectorXd& d) : mValues(d) {
        const Eigen::MatrixXd r = Eigen::MatrixXd::Random(d.size(), d.size());
        mBasis = Eigen::HouseholderQR<Eigen::MatrixXd>(r).householderQ();
    }

    BlockApply apply() const {
        return [this](const Eigen::Ref<const Eigen::MatrixXd>& x, Eigen::Ref<Eigen::MatrixXd> y) {
            y = mBasis * (mValues.asDiagonal() * (mBasis.transpose() * x));
        };
    }
    const Eigen::MatrixXd& basis() const { return mBasis; }

private:
    Eigen::VectorXd mValues;
    Eigen::MatrixXd mBasis;
};

/// θ_i = 1 / i: the shape of a shift-invert spectrum, whose wanted end is the slowly decaying
/// top, with copies of θ = 1/5 (repeated `copies` times).
Eigen::VectorXd inverseSpectrum(int n, int copies) {
    Eigen::VectorXd d(n);
    for (int i = 0; i < n; ++i) d[i] = 1.0 / (i < 4 ? i + 1 : i < 4 + copies ? 5 : i - copies + 6);
    return d;
}

BlockLanczosRequest request(int count) {
    BlockLanczosRequest r;
    r.count = count;
    r.blockSize = 8;
    r.what = "test eigensolve";
    return r;
}

TEST(BlockLanczos, LargestPairsOfAKnownSpectrumWithCopies) {
    const int n = 400, copies = 6, count = 40;
    const Eigen::VectorXd d = inverseSpectrum(n, copies);
    const KnownSpectrum a(d);
    const BlockLanczosResult r =
        largestEigenpairs(a.apply(), n, Eigen::MatrixXd(n, 0), request(count));
    ASSERT_EQ(r.values.size(), count);
    for (int i = 0; i < count; ++i) EXPECT_NEAR(r.values[i] / d[i], 1.0, 1e-12) << i;
    EXPECT_LE((r.vectors.transpose() * r.vectors - Eigen::MatrixXd::Identity(count, count))
                  .cwiseAbs()
                  .maxCoeff(),
              1e-12);
    // Each vector is its pair's: A y = θ y.
    Eigen::MatrixXd ay(n, count);
    a.apply()(r.vectors, ay);
    for (int i = 0; i < count; ++i)
        EXPECT_LE((ay.col(i) - r.values[i] * r.vectors.col(i)).norm(), 1e-10 * r.values[i]) << i;
    EXPECT_GT(r.applied, 0);
}

// Two distinct eigenvalues: the Krylov space of a block of 8 is invariant after two blocks, so the
// third has nothing left (Cholesky QR cannot resolve that; Householder QR finds it and starts
// random directions), and the 30 pairs wanted are all copies of the top one.
TEST(BlockLanczos, AnInvariantSpaceReachedGoesOnWithFreshDirections) {
    const int n = 200, count = 30;
    Eigen::VectorXd d = Eigen::VectorXd::Constant(n, 0.5);
    d.head(100).setOnes();
    const KnownSpectrum a(d);
    const BlockLanczosResult r =
        largestEigenpairs(a.apply(), n, Eigen::MatrixXd(n, 0), request(count));
    ASSERT_EQ(r.values.size(), count);
    for (int i = 0; i < count; ++i) EXPECT_NEAR(r.values[i], 1.0, 1e-12) << i;
    EXPECT_LE((r.vectors.transpose() * r.vectors - Eigen::MatrixXd::Identity(count, count))
                  .cwiseAbs()
                  .maxCoeff(),
              1e-12);
    // In the top eigenspace: no part along the eigenvectors of 0.5.
    EXPECT_LE((a.basis().rightCols(n - 100).transpose() * r.vectors).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(BlockLanczos, DeflatedDirectionsStayOut) {
    const int n = 300, count = 10;
    const Eigen::VectorXd d = inverseSpectrum(n, 1);
    const KnownSpectrum a(d);
    // The first three eigenvectors deflated: the pairs found are the 4th to the 13th.
    const Eigen::MatrixXd deflated = a.basis().leftCols(3);
    const BlockLanczosResult r = largestEigenpairs(a.apply(), n, deflated, request(count));
    for (int i = 0; i < count; ++i) EXPECT_NEAR(r.values[i] / d[i + 3], 1.0, 1e-12) << i;
    EXPECT_LE((deflated.transpose() * r.vectors).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(BlockLanczos, TooFewRestartsIsAnErrorNamingTheSolve) {
    const int n = 400, count = 60;
    const KnownSpectrum a(inverseSpectrum(n, 1));
    BlockLanczosRequest r = request(count);
    r.maxRestarts = 0;
    try {
        largestEigenpairs(a.apply(), n, Eigen::MatrixXd(n, 0), r);
        FAIL() << "converged without a restart";
    } catch (const Error& e) {
        EXPECT_EQ(std::string(e.what()).rfind("test eigensolve: block Lanczos did not converge", 0),
                  0u)
            << e.what();
    }
}

TEST(BlockLanczos, MorePairsThanTheSpaceHoldsAreRefused) {
    const int n = 40;
    const KnownSpectrum a(inverseSpectrum(n, 1));
    EXPECT_THROW(largestEigenpairs(a.apply(), n, Eigen::MatrixXd(n, 0), request(35)), Error);
}

}  // namespace
}  // namespace modeflow
