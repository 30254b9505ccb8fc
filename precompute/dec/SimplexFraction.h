#pragma once
/// @file SimplexFraction.h
/// Exact measure of {φ > 0} inside a simplex where φ is linear (given by its vertex values).

#include <span>

namespace modeflow {

/// Fraction (0..1) of a k-simplex (k = 1, 2, 3; k+1 vertex values) where the linear interpolant
/// of `values` is strictly positive. Exactly 0 when no value is positive, exactly 1 when all are.
double positiveFraction(std::span<const double> values);

}  // namespace modeflow
