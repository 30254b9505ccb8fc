// Lanczos from one start vector finds one vector per eigenspace in exact arithmetic, so copies
// of a degenerate eigenvalue need the deflated runs of findMissedCopies: periodic axes and
// symmetric domains make many (ShiftInvertEigensolver.h). Block Lanczos finds as many copies as
// its block has vectors, and looks for more with the same deflated runs when it finds half as
// many.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "engine/dynamics/ThreadCount.h"
#include "precompute/solve/BlasThreads.h"
#include "precompute/solve/ShiftInvertEigensolver.h"

namespace modeflow {
namespace {

/// 1, 2, 3 once, then `copies` times 4, then 5, 6, … once each.
Eigen::SparseMatrix<double> degenerate(int n, int copies) {
    Eigen::SparseMatrix<double> k(n, n);
    for (int i = 0; i < n; ++i)
        k.insert(i, i) = i < 3 ? i + 1.0 : i < 3 + copies ? 4.0 : double(i - copies + 5);
    return k;
}

/// The `count` lowest pairs of degenerate(n, copies), checked against the exact values (mass 2).
void expectEveryCopy(const EigenPairs& pairs, int copies, int count) {
    const Eigen::VectorXd mass = Eigen::VectorXd::Constant(pairs.vectors.rows(), 2.0);
    ASSERT_EQ(pairs.values.size(), count);
    for (int i = 0; i < count; ++i) {
        const double exact = i < 3 ? i + 1.0 : i < 3 + copies ? 4.0 : double(i - copies + 5);
        EXPECT_NEAR(2.0 * pairs.values[i], exact, 1e-9) << "eigenvalue " << i + 1 << " (mass 2)";
    }
    const Eigen::MatrixXd gram = pairs.vectors.transpose() * mass.asDiagonal() * pairs.vectors;
    EXPECT_LE((gram - Eigen::MatrixXd::Identity(count, count)).cwiseAbs().maxCoeff(), 1e-10);
}

TEST(DegenerateEigenvalues, DeflatedRunsFindEveryCopy) {
    const int n = 300, copies = 16, count = 30;
    const Eigen::VectorXd mass = Eigen::VectorXd::Constant(n, 2.0);
    EigenRequest request{count, -0.01, 1e-12, "test eigensolve", {}, true};
    expectEveryCopy(smallestEigenpairs(degenerate(n, copies), mass, request), copies, count);
}

TEST(DegenerateEigenvalues, TwoEqualEigenvaluesFoundStartTheSearchForMissedCopies) {
    // Not asked for: one run finds some of the 16 copies (fewer than all, measured), and two
    // equal eigenvalues among them are enough to look for the others.
    const int n = 300, copies = 16, count = 30;
    const Eigen::VectorXd mass = Eigen::VectorXd::Constant(n, 2.0);
    EigenRequest request{count, -0.01, 1e-12, "test eigensolve", {}, false};
    expectEveryCopy(smallestEigenpairs(degenerate(n, copies), mass, request), copies, count);
}

/// The `count` lowest pairs of degenerate(n, copies) by block Lanczos, every copy found.
void expectBlockRunsFindEveryCopy(int n, int copies, int count) {
    const Eigen::VectorXd mass = Eigen::VectorXd::Constant(n, 2.0);
    const EigenRequest request{count, -0.01, 1e-12, "test eigensolve", {}, false};
    expectEveryCopy(
        smallestEigenpairs(degenerate(n, copies), mass, request, KrylovMethod::BlockLanczos),
        copies, count);
}

TEST(DegenerateEigenvalues, BlockRunsFindSixteenCopies) {
    expectBlockRunsFindEveryCopy(300, 16, 30);
}

TEST(DegenerateEigenvalues, MoreCopiesThanABlockHoldsAreFoundByDeflatedBlockRuns) {
    // 40 copies: a block of 16 vectors holds at most 16 of them in exact arithmetic.
    expectBlockRunsFindEveryCopy(400, 40, 50);
}

/// The 5-point Dirichlet Laplacian of an m × m grid: eigenvalues 4 sin²(πi/2(m+1)) + the same
/// for j, each i ≠ j twice (a factorization with real supernodes, unlike the diagonal above).
Eigen::SparseMatrix<double> gridLaplacian(int m) {
    std::vector<Eigen::Triplet<double>> entries;
    for (int y = 0; y < m; ++y)
        for (int x = 0; x < m; ++x) {
            const int i = y * m + x;
            entries.emplace_back(i, i, 4.0);
            if (x > 0) entries.emplace_back(i, i - 1, -1.0);
            if (x + 1 < m) entries.emplace_back(i, i + 1, -1.0);
            if (y > 0) entries.emplace_back(i, i - m, -1.0);
            if (y + 1 < m) entries.emplace_back(i, i + m, -1.0);
        }
    Eigen::SparseMatrix<double> k(m * m, m * m);
    k.setFromTriplets(entries.begin(), entries.end());
    return k;
}

TEST(DegenerateEigenvalues, BlockSolvesInPartsOnTwoThreadsGiveTheSamePairs) {
    // Two OpenMP threads: each block's 16 solves go to CHOLMOD as two parts at once, each with
    // one BLAS thread (where the BLAS lets its threads be set: OpenBLAS, as installed here).
    ASSERT_TRUE(BlasThreads::controllable());
    const int m = 60, count = 40;
    const Eigen::SparseMatrix<double> k = gridLaplacian(m);
    const Eigen::VectorXd mass = Eigen::VectorXd::Ones(m * m);
    const EigenRequest request{count, -0.01, 1e-12, "test eigensolve", {}, false};
    const auto solve = [&](int threads) {
        const ThreadCount team(threads);
        return smallestEigenpairs(k, mass, request, KrylovMethod::BlockLanczos);
    };
    const EigenPairs one = solve(1), two = solve(2);
    std::vector<double> exact;
    const auto s = [&](int i) {
        return std::pow(2.0 * std::sin(std::numbers::pi * i / (2.0 * (m + 1))), 2);
    };
    for (int i = 1; i <= m; ++i)
        for (int j = 1; j <= m; ++j) exact.push_back(s(i) + s(j));
    std::sort(exact.begin(), exact.end());
    for (int i = 0; i < count; ++i) {
        EXPECT_NEAR(two.values[i] / exact[std::size_t(i)], 1.0, 1e-10) << i;
        EXPECT_NEAR(two.values[i] / one.values[i], 1.0, 1e-12) << i;
    }
    // Equal spans: the two-thread vectors lie in the span of the one-thread ones.
    const Eigen::MatrixXd overlap = one.vectors.transpose() * two.vectors;
    EXPECT_LE((overlap.transpose() * overlap - Eigen::MatrixXd::Identity(count, count))
                  .cwiseAbs()
                  .maxCoeff(),
              1e-9);
}

}  // namespace
}  // namespace modeflow
