#pragma once
/// @file Fit.h
/// Small numerical helpers the studies share.

#include <vector>

namespace modeflow::validate {

/// The least-squares slope of log(y) against log(x): the order p of y ≈ C x^p.
double logLogSlope(const std::vector<double>& x, const std::vector<double>& y);

/// max_i |computed_i − exact_i| / exact_i over the first exact.size() values.
double maxRelativeError(const std::vector<double>& computed, const std::vector<double>& exact);

}  // namespace modeflow::validate
