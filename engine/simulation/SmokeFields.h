#pragma once
/// @file SmokeFields.h
/// The smoke a run carries: density and temperature as concentrations per smoke cell (the basis
/// grid refined by `[smoke] resolution_scale`, MacGrid cell order), what both backends read back;
/// with `[fire]`, the fuel and the flame too.

#include <vector>

namespace modeflow {

/// Density and temperature, one value per smoke cell each; fuel and flame as many, or none
/// without fire.
struct SmokeFields {
    std::vector<double> density;
    std::vector<double> temperature;
    std::vector<double> fuel = {};   ///< carried like the density; burns (Combustion.h)
    std::vector<double> flame = {};  ///< fuel burned per unit time in the last step; not carried
};

}  // namespace modeflow
