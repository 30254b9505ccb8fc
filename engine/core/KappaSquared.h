#pragma once
/// @file KappaSquared.h
/// The one check of κ² lists (velocity eigenvalues) that every consumer applies: precompute,
/// dynamics, LANS-α, the device's modal step. A harmonic field has κ² = 0 exactly (seed §6.3.1),
/// but an eigensolve returns it as round-off of either sign (±1e-11 on a 128² annulus, where the
/// first non-zero κ² is about 3); such values become exactly 0, clearly negative ones are refused.

#include <string>

#include <Eigen/Core>

namespace modeflow {

/// |κ²| at most this fraction of the first non-zero κ² is the round-off of a harmonic mode. The
/// eigensolves' round-off is about 1e-11 of it, the next mode is O(1) of it: any value between
/// leaves a wide margin on both sides.
inline constexpr double kHarmonicTolerance = 1e-6;

/// The first non-zero κ² of a list: its smallest value above kHarmonicTolerance × `anchor`, where
/// `anchor` is a κ² known not to be round-off; `anchor` itself when no value is above.
double firstNonZeroKappaSquared(const Eigen::VectorXd& kappaSquared, double anchor);

/// `kappaSquared` with harmonic round-off (|κ²| ≤ kHarmonicTolerance × `firstNonZero`) set to 0.
/// @throw modeflow::Error naming `consumer` and the mode for a non-finite κ² or one below
/// −kHarmonicTolerance × `firstNonZero`.
Eigen::VectorXd checkedKappaSquared(const Eigen::VectorXd& kappaSquared, double firstNonZero,
                                    const std::string& consumer);

/// The same, the first non-zero κ² taken from the list itself (anchored at its largest |κ²|).
Eigen::VectorXd checkedKappaSquared(const Eigen::VectorXd& kappaSquared,
                                    const std::string& consumer);

}  // namespace modeflow
