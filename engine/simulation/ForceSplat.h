#pragma once
/// @file ForceSplat.h
/// A stirring splat (`modeflow stir`): a Gaussian force density pushing along `force` around
/// `centre`, g = (force · n) exp(−|x − centre|² / radius²) on a face of normal n. A plain value
/// both backends take (the device copies it as float32).

#include <cstddef>

#include "engine/core/GridSpec.h"

namespace modeflow {

/// A stirring splat; a plain value (the device kernel copies it as float32).
struct ForceSplat {
    Vec3 centre{0.0, 0.0, 0.0};
    Vec3 force{0.0, 0.0, 0.0};  ///< direction × strength: force density at the centre
    double radius = 1.0;        ///< Gaussian radius (> 0)
};

/// The most splats a simulation takes at once (a stir stroke makes up to 8).
inline constexpr std::size_t maxForceSplats = 16;

}  // namespace modeflow
