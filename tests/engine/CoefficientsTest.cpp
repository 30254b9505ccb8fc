/// @file CoefficientsTest.cpp
/// Structural coefficient storages: the packed layout, antisymmetry, dense/sparse agreement, and
/// every contraction against brute force from the definitions (seed eq. 6.7, appendix C.3).

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>
#include <type_traits>
#include <vector>

#include <Eigen/Core>

#include "engine/core/Error.h"
#include "engine/core/PackedLayout.h"
#include "engine/dynamics/CachedCoefficients.h"
#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/SparseCoefficients.h"
#include "engine/dynamics/ThreadCount.h"
#include "tests/support/RandomCoefficients.h"
#include "tests/support/SyntheticBases.h"

namespace modeflow {
namespace {

using testing::bruteApply;
using testing::randomDense;
using testing::randomFullTensor;
using testing::randomVector;

double relativeError(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
    return (a - b).norm() / std::max(b.norm(), 1e-300);
}

TEST(PackedLayout, EnumeratesTheUpperHalfContiguously) {
    const std::size_t n = 7;
    std::size_t expected = 0;
    for (std::size_t k = 0; k < n; ++k)
        for (std::size_t j = k + 1; j < n; ++j)
            for (std::size_t i = 0; i < n; ++i) {
                ASSERT_EQ(packedIndex(n, k, i, j), expected)
                    << "C[" << k << "][" << i << "][" << j << "]";
                ++expected;
            }
    EXPECT_EQ(expected, packedSize(n));
    EXPECT_EQ(packedSize(n), n * n * (n - 1) / 2);
}

TEST(DenseCoefficients, FromFullKeepsEveryEntryAndMeasuresAntisymmetry) {
    const int n = 20;
    const std::vector<double> full = randomFullTensor(n, 1);
    const DenseCoefficients c = DenseCoefficients::fromFull(n, full);
    EXPECT_EQ(c.antisymmetryError(), 0.0);
    double worst = 0.0;
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) {
                worst = std::max(worst, std::abs(c.entry(k, i, j) - full[(k * n + i) * n + j]));
                worst = std::max(worst, std::abs(c.entry(k, i, j) + c.entry(j, i, k)));
            }
    EXPECT_EQ(worst, 0.0) << "largest entry mismatch " << worst;
}

TEST(DenseCoefficients, ReportsAndRejectsBrokenAntisymmetry) {
    const int n = 6;
    std::vector<double> full = randomFullTensor(n, 2);
    double largest = 0.0;
    for (double x : full) largest = std::max(largest, std::abs(x));
    full[(1 * n + 2) * n + 4] += 1e-12 * largest;
    EXPECT_NEAR(DenseCoefficients::fromFull(n, full).antisymmetryError(), 1e-12, 1e-14);
    full[(4 * n + 2) * n + 1] = full[(1 * n + 2) * n + 4];  // symmetric pair: not a C tensor
    EXPECT_THROW(DenseCoefficients::fromFull(n, full), Error);
    EXPECT_THROW(DenseCoefficients::fromFull(n, std::vector<double>(n * n)), Error);
    EXPECT_THROW(DenseCoefficients(n, std::vector<double>(packedSize(n) - 1)), Error);
}

TEST(DenseCoefficients, PackedRoundTripIsExact) {
    const DenseCoefficients c = randomDense(25, 3);
    const DenseCoefficients copy(c.size(), c.packed());
    EXPECT_EQ(copy.packed(), c.packed());
    const SparseCoefficients sparse = SparseCoefficients::fromDense(c);
    EXPECT_EQ(sparse.nonZeros(), c.packed().size());
    std::vector<double> repacked(packedSize(c.size()), 0.0);
    for (std::size_t r = 0; r < sparse.pairK().size(); ++r)
        for (std::size_t t = sparse.rowStart()[r]; t < sparse.rowStart()[r + 1]; ++t)
            repacked[packedIndex(c.size(), sparse.pairK()[r], sparse.columns()[t],
                                 sparse.pairJ()[r])] = sparse.values()[t];
    EXPECT_EQ(repacked, c.packed());
}

TEST(SparseCoefficients, RejectsBadEntries) {
    EXPECT_THROW(SparseCoefficients(4, {{2, 0, 1, 1.0}}), Error);                  // k > j
    EXPECT_THROW(SparseCoefficients(4, {{1, 0, 1, 1.0}}), Error);                  // k = j
    EXPECT_THROW(SparseCoefficients(4, {{0, 4, 1, 1.0}}), Error);                  // i out of range
    EXPECT_THROW(SparseCoefficients(4, {{0, 1, 2, 1.0}, {0, 1, 2, 2.0}}), Error);  // twice
    const SparseCoefficients c(4, {{0, 3, 2, 1.5}, {1, 1, 3, -2.0}, {0, 0, 2, 0.0}});
    EXPECT_EQ(c.nonZeros(), 2u);
    EXPECT_EQ(c.entry(0, 3, 2), 1.5);
    EXPECT_EQ(c.entry(2, 3, 0), -1.5);
    EXPECT_EQ(c.entry(3, 1, 1), 2.0);
    EXPECT_EQ(c.entry(0, 0, 2), 0.0);
}

TEST(SparseCoefficients, ListsInAnyOrderGiveTheSameRows) {
    // A cache's lists come in the assembler's order (by wave-vector group), not by pair.
    const SparseCoefficients sorted = SparseCoefficients::fromDense(randomDense(25, 7, 0.2));
    std::vector<std::int32_t> k, i, j;
    std::vector<double> value;
    for (std::size_t r = 0; r < sorted.pairK().size(); ++r)
        for (std::size_t t = sorted.rowStart()[r]; t < sorted.rowStart()[r + 1]; ++t) {
            k.push_back(sorted.pairK()[r]);
            i.push_back(sorted.columns()[t]);
            j.push_back(sorted.pairJ()[r]);
            value.push_back(sorted.values()[t]);
        }
    std::vector<std::size_t> order(value.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::shuffle(order.begin(), order.end(), std::mt19937(3));
    const auto permuted = [&](const auto& list) {
        std::remove_const_t<std::remove_reference_t<decltype(list)>> out;
        for (std::size_t e : order) out.push_back(list[e]);
        return out;
    };
    const SparseCoefficients shuffled =
        SparseCoefficients::fromLists(25, permuted(k), permuted(i), permuted(j), permuted(value));
    EXPECT_EQ(shuffled.pairK(), sorted.pairK());
    EXPECT_EQ(shuffled.pairJ(), sorted.pairJ());
    EXPECT_EQ(shuffled.rowStart(), sorted.rowStart());
    EXPECT_EQ(shuffled.columns(), sorted.columns());
    EXPECT_EQ(shuffled.values(), sorted.values());
    EXPECT_THROW(SparseCoefficients::fromLists(4, {0}, {1}, {2, 3}, {1.0}), Error);  // lengths
    EXPECT_THROW(SparseCoefficients::fromLists(4, {0, 0}, {1, 1}, {2, 2}, {1.0, 2.0}), Error);
}

/// Every contraction of `c` against the definitions, for one random (a, b).
void expectContractionsMatchDefinitions(const StructuralCoefficients& c, std::uint64_t seed) {
    const int n = c.size();
    const Eigen::VectorXd a = randomVector(n, seed), b = randomVector(n, seed + 1);
    Eigen::VectorXd out;
    c.apply(a, b, out);
    EXPECT_LT(relativeError(out, bruteApply(c, a, b)), 1e-13);

    Eigen::MatrixXd byI, byJ, expectI(n, n), expectJ(n, n);
    c.linearize(a, b, byI, byJ);
    for (int k = 0; k < n; ++k)
        for (int m = 0; m < n; ++m) {
            double sI = 0.0, sJ = 0.0;
            for (int l = 0; l < n; ++l) {
                sI += c.entry(k, l, m) * a[l];
                sJ += c.entry(k, m, l) * b[l];
            }
            expectI(k, m) = sI;
            expectJ(k, m) = sJ;
        }
    EXPECT_LT(relativeError(byI, expectI), 1e-13);
    EXPECT_LT(relativeError(byJ, expectJ), 1e-13);
    EXPECT_EQ((byI + byI.transpose()).norm(), 0.0);

    Eigen::VectorXd advected, expectAdvected = Eigen::VectorXd::Zero(n);
    c.advect(a, b, advected);
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) expectAdvected[k] += c.entry(j, k, i) * b[i] * a[j];
    EXPECT_LT(relativeError(advected, expectAdvected), 1e-13);
}

TEST(DenseCoefficients, ContractionsMatchDefinitions) {
    expectContractionsMatchDefinitions(randomDense(20, 4), 10);
    const ThreadCount threads(2);  // the suite's tests run with one thread unless they ask
    expectContractionsMatchDefinitions(randomDense(70, 5), 11);  // large enough to use threads
}

TEST(SparseCoefficients, ContractionsMatchDefinitions) {
    expectContractionsMatchDefinitions(SparseCoefficients::fromDense(randomDense(30, 6, 0.1)), 12);
}

TEST(Coefficients, DenseAndSparseAgree) {
    for (double density : {1.0, 0.1}) {
        const DenseCoefficients dense = randomDense(40, 7, density);
        const SparseCoefficients sparse = SparseCoefficients::fromDense(dense);
        EXPECT_NEAR(sparse.density(), density, 0.02);
        const Eigen::VectorXd a = randomVector(40, 20), b = randomVector(40, 21);
        Eigen::VectorXd d, s;
        dense.apply(a, b, d);
        sparse.apply(a, b, s);
        EXPECT_LT(relativeError(s, d), 1e-14) << "apply, density " << density;
        dense.advect(a, b, d);
        sparse.advect(a, b, s);
        EXPECT_LT(relativeError(s, d), 1e-14) << "advect, density " << density;
        Eigen::MatrixXd jd, js;
        dense.jacobian(a, jd, d);
        sparse.jacobian(a, js, s);
        EXPECT_LT(relativeError(js, jd), 1e-14) << "jacobian, density " << density;
        EXPECT_LT(relativeError(s, d), 1e-14) << "f(v), density " << density;
    }
}

TEST(Coefficients, JacobianMatchesFiniteDifferences) {
    const DenseCoefficients c = randomDense(15, 8);
    const Eigen::VectorXd v = randomVector(15, 30);
    Eigen::MatrixXd jac;
    Eigen::VectorXd f, plus, minus;
    c.jacobian(v, jac, f);
    EXPECT_LT(relativeError(f, bruteApply(c, v, v)), 1e-13);
    const double eps = 1e-6;
    for (int l = 0; l < 15; ++l) {
        Eigen::VectorXd dv = Eigen::VectorXd::Zero(15);
        dv[l] = eps;
        c.apply(v + dv, v + dv, plus);
        c.apply(v - dv, v - dv, minus);
        // f is quadratic, so the central difference is exact up to round-off.
        EXPECT_LT(relativeError((plus - minus) / (2 * eps), jac.col(l)), 1e-8) << "column " << l;
    }
}

TEST(Coefficients, EnergyAndKelvinIdentitiesHold) {
    // vᵀ(vᵀC v) = 0 (energy, eq. 6.8) and d/dt Σ v_i γ_i = 0 for a loop γ advected by v (C.3).
    const DenseCoefficients c = randomDense(30, 9);
    const Eigen::VectorXd v = randomVector(30, 40), gamma = randomVector(30, 41);
    Eigen::VectorXd f, advected;
    c.apply(v, v, f);
    c.advect(v, gamma, advected);
    const double scale = f.norm() * v.norm();
    EXPECT_LT(std::abs(v.dot(f)) / scale, 1e-14);
    const double circulationRate = gamma.dot(f) + v.dot(advected);
    EXPECT_LT(std::abs(circulationRate) / scale, 1e-14) << "d/dt <v, gamma> = " << circulationRate;
}

TEST(Coefficients, MismatchedVectorsThrow) {
    const DenseCoefficients dense = randomDense(5, 10);
    const SparseCoefficients sparse = SparseCoefficients::fromDense(dense);
    Eigen::VectorXd out;
    Eigen::MatrixXd m1, m2;
    for (const StructuralCoefficients* c : {static_cast<const StructuralCoefficients*>(&dense),
                                            static_cast<const StructuralCoefficients*>(&sparse)}) {
        EXPECT_THROW(c->apply(Eigen::VectorXd::Ones(5), Eigen::VectorXd::Ones(4), out), Error);
        EXPECT_THROW(c->linearize(Eigen::VectorXd::Ones(6), Eigen::VectorXd::Ones(5), m1, m2),
                     Error);
        EXPECT_THROW(c->advect(Eigen::VectorXd::Ones(4), Eigen::VectorXd::Ones(5), out), Error);
    }
}

TEST(Coefficients, ARunTakesTheCachesTensorInsteadOfCopyingIt) {
    // A run keeps its coefficients once: the cache is left without them, and they are the ones
    // a copy would have given.
    BasisCache cache = testing::syntheticBasis(testing::boxGrid(2, 8), 6, 3);
    ASSERT_EQ(cache.coefficients.storage, BasisCache::Coefficients::Storage::Dense);
    const auto copied = coefficientsFromCache(cache);
    const auto taken = takeCoefficientsFromCache(cache);
    EXPECT_EQ(cache.coefficients.storage, BasisCache::Coefficients::Storage::None);
    EXPECT_TRUE(cache.coefficients.packed.empty());
    for (int k = 0; k < 6; ++k)
        for (int i = 0; i < 6; ++i)
            for (int j = 0; j < 6; ++j)
                ASSERT_EQ(taken->entry(k, i, j), copied->entry(k, i, j)) << k << i << j;
}

}  // namespace
}  // namespace modeflow
