#pragma once
/// @file SmokeFields.h
/// The smoke a run carries: density and temperature as concentrations per smoke cell (the basis
/// grid refined by `[smoke] resolution_scale`, MacGrid cell order), what both backends read back.

#include <vector>

namespace modeflow {

/// Density and temperature, one value per smoke cell each.
struct SmokeFields {
    std::vector<double> density;
    std::vector<double> temperature;
};

}  // namespace modeflow
