// Spectrum slicing (SlicedEigensolver.h) finds every eigenvalue of its intervals once: against
// closed-form spectra, with clusters of equal eigenvalues placed on the ends of its intervals, and
// against shift-invert Lanczos (ShiftInvertEigensolver.h) on the same operator.

#include <gtest/gtest.h>

#include "precompute/solve/ShiftInvertEigensolver.h"
#include "precompute/solve/SlicedEigensolver.h"
#include "tests/support/ChainLaplacian.h"

namespace modeflow {
namespace {

double chainEigenvalue(int n, int j) {
    const double h = 1.0 / (n + 1), s = std::sin(j * M_PI * h / 2.0);
    return 4.0 * s * s / (h * h);
}

TEST(SlicedEigensolver, ChainSpectrumExact) {
    const int n = 3000, count = 120;
    const double h = 1.0 / (n + 1);
    long reported = 0;
    EigenRequest request{
        count, -1.0, 1e-12, "test eigensolve", [&reported](long solves) { reported = solves; },
        false};
    request.spectralDimension = 1;
    request.estimate = 0.5 * chainEigenvalue(n, count);  // too low on purpose: a second interval
    const EigenPairs pairs =
        slicedEigenpairs(testing::chainLaplacian(n), Eigen::VectorXd::Constant(n, h), request);
    ASSERT_EQ(pairs.values.size(), count);
    double worst = 0.0;
    for (int j = 1; j <= count; ++j)
        worst = std::max(worst, std::abs(pairs.values[j - 1] / chainEigenvalue(n, j) - 1.0));
    EXPECT_LE(worst, 1e-9) << "largest relative eigenvalue error";
    const Eigen::MatrixXd gram = pairs.vectors.transpose() * h * pairs.vectors;
    EXPECT_LE((gram - Eigen::MatrixXd::Identity(count, count)).cwiseAbs().maxCoeff(), 1e-9);
    EXPECT_GE(pairs.stats.factorizations, 2);
    EXPECT_GT(reported, 0) << "no progress reported";
    EXPECT_LE(reported, pairs.stats.operations);
}

/// 1, 2, … with `copies` equal eigenvalues `cluster` in place of as many integers above it.
Eigen::SparseMatrix<double> clustered(int n, double cluster, int copies,
                                      std::vector<double>& exact) {
    exact.clear();
    for (int i = 1; int(exact.size()) < n; ++i) {
        if (double(i) > cluster && double(i - 1) < cluster)
            for (int c = 0; c < copies; ++c) exact.push_back(cluster);
        if (int(exact.size()) < n) exact.push_back(double(i));
    }
    Eigen::SparseMatrix<double> k(n, n);
    // Shuffled on the diagonal, so that no structure helps the solver.
    for (int i = 0; i < n; ++i) k.insert(i, i) = 3.0 * exact[size_t((i * 7919) % n)];
    std::sort(exact.begin(), exact.end());
    return k;
}

TEST(SlicedEigensolver, ClusterOnAnIntervalEndFoundOnce) {
    const int n = 2000, count = 60, copies = 16;
    EigenRequest request{count, -0.5, 1e-12, "test eigensolve", {}, false};
    request.spectralDimension = 2;
    request.estimate = 30.0;
    const double end = 1.02 * request.estimate;  // where the first interval ends
    std::vector<double> exact;
    const Eigen::SparseMatrix<double> k = clustered(n, end, copies, exact);
    const EigenPairs pairs = slicedEigenpairs(k, Eigen::VectorXd::Constant(n, 3.0), request);
    ASSERT_EQ(pairs.values.size(), count);
    int atEnd = 0;
    for (int j = 0; j < count; ++j) {
        EXPECT_NEAR(pairs.values[j], exact[size_t(j)], 1e-9 * exact[size_t(j)])
            << "eigenvalue " << j + 1;
        atEnd += std::abs(pairs.values[j] - end) < 1e-9 * end;
    }
    EXPECT_EQ(atEnd, copies) << "copies of the eigenvalue on the interval's end";
    const Eigen::MatrixXd gram = pairs.vectors.transpose() * 3.0 * pairs.vectors;
    EXPECT_LE((gram - Eigen::MatrixXd::Identity(count, count)).cwiseAbs().maxCoeff(), 1e-9);
}

}  // namespace
}  // namespace modeflow
