#pragma once
/// @file RandomCoefficients.h
/// Random structural-coefficient tensors with the exact antisymmetry C[k][i][j] = −C[j][i][k],
/// random states, and brute-force contractions straight from the definitions: for the dynamics
/// and kernel tests and for tools/bench.

#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/StructuralCoefficients.h"

namespace modeflow::testing {

/// A full array full[(k·N + i)·N + j]. density 1: A uniform in [−1, 1] and C = A − (A with k↔j
/// swapped), which is antisymmetric bit for bit. density < 1: each triple k < j (any i) is
/// non-zero with that probability and its mirror gets the negated value.
std::vector<double> randomFullTensor(int n, std::uint64_t seed, double density = 1.0);

/// randomFullTensor packed.
DenseCoefficients randomDense(int n, std::uint64_t seed, double density = 1.0);

/// Dense coefficients drawn straight into the packed k < j half, uniform in [−1, 1]: for sizes
/// whose full N³ array would not fit (N = 1000: 8 GB full, 4 GB packed).
DenseCoefficients randomPackedDense(int n, std::uint64_t seed);

/// The vector rounded to float32 and back: what a device run starts from.
Eigen::VectorXd roundedToFloat(const Eigen::VectorXd& v);

/// The coefficients rounded to float32, so a CPU reference sees what the device sees and a
/// comparison measures the device's float32 accumulation alone.
DenseCoefficients roundedDense(const DenseCoefficients& c);

/// n standard normal values.
Eigen::VectorXd randomVector(Eigen::Index n, std::uint64_t seed);

/// κ² of a frequency-shaped basis: a low band and a high band, interleaved, not sorted.
Eigen::VectorXd shapedKappaSquared(int n);

/// Σ_ij C[k][i][j] a_i b_j from entry().
Eigen::VectorXd bruteApply(const StructuralCoefficients& c, const Eigen::VectorXd& a,
                           const Eigen::VectorXd& b);

}  // namespace modeflow::testing
