#pragma once
/// @file RandomCoefficients.h
/// Random structural-coefficient tensors with the exact antisymmetry C[k][i][j] = −C[j][i][k], and
/// brute-force contractions straight from the definitions, for the dynamics tests.

#include <cstdint>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/StructuralCoefficients.h"

namespace modeflow::testing {

/// A full array full[(k·N + i)·N + j]. density 1: A uniform in [−1, 1] and C = A − (A with k↔j
/// swapped), which is antisymmetric bit for bit. density < 1: each triple k < j (any i) is
/// non-zero with that probability and its mirror gets the negated value.
inline std::vector<double> randomFullTensor(int n, std::uint64_t seed, double density = 1.0) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    std::bernoulli_distribution keep(density);
    const auto at = [n](int k, int i, int j) { return (std::size_t(k) * n + i) * n + j; };
    std::vector<double> a(std::size_t(n) * n * n, 0.0), c(a.size(), 0.0);
    if (density >= 1.0) {
        for (double& x : a) x = value(rng);
        for (int k = 0; k < n; ++k)
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j) c[at(k, i, j)] = a[at(k, i, j)] - a[at(j, i, k)];
        return c;
    }
    for (int k = 0; k < n; ++k)
        for (int j = k + 1; j < n; ++j)
            for (int i = 0; i < n; ++i)
                if (keep(rng)) {
                    c[at(k, i, j)] = value(rng);
                    c[at(j, i, k)] = -c[at(k, i, j)];
                }
    return c;
}

inline DenseCoefficients randomDense(int n, std::uint64_t seed, double density = 1.0) {
    return DenseCoefficients::fromFull(n, randomFullTensor(n, seed, density));
}

/// The vector rounded to float32 and back: what a device run starts from.
inline Eigen::VectorXd roundedToFloat(const Eigen::VectorXd& v) { return v.cast<float>().cast<double>(); }

/// The coefficients rounded to float32, so a CPU reference sees what the device sees and a
/// comparison measures the device's float32 accumulation alone.
inline DenseCoefficients roundedDense(const DenseCoefficients& c) {
    std::vector<double> packed(c.packed().size());
    for (std::size_t e = 0; e < packed.size(); ++e) packed[e] = double(float(c.packed()[e]));
    return DenseCoefficients(c.size(), std::move(packed));
}

inline Eigen::VectorXd randomVector(int n, std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::normal_distribution<double> normal;
    Eigen::VectorXd v(n);
    for (double& x : v) x = normal(rng);
    return v;
}

/// κ² of a frequency-shaped basis: a low band and a high band, interleaved, not sorted.
inline Eigen::VectorXd shapedKappaSquared(int n) {
    Eigen::VectorXd k2(n);
    for (int i = 0; i < n; ++i) k2[i] = (i % 2 == 0) ? 5.0 + 3.0 * i : 900.0 - 7.0 * i;
    return k2;
}

/// Σ_ij C[k][i][j] a_i b_j from entry().
inline Eigen::VectorXd bruteApply(const StructuralCoefficients& c, const Eigen::VectorXd& a,
                                  const Eigen::VectorXd& b) {
    const int n = c.size();
    Eigen::VectorXd out = Eigen::VectorXd::Zero(n);
    for (int k = 0; k < n; ++k)
        for (int i = 0; i < n; ++i)
            for (int j = 0; j < n; ++j) out[k] += c.entry(k, i, j) * a[i] * b[j];
    return out;
}

}  // namespace modeflow::testing
