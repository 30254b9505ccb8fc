#pragma once
/// @file StrokeSplats.h
/// A stirring stroke as force splats (the pointer's drag in `modeflow stir`, on a grid or a
/// surface): splats two radii apart along the path, at most 8, each pushing along the motion
/// with `force` times the pointer's speed.

#include <vector>

#include "engine/simulation/ForceSplat.h"

namespace modeflow::stir {

/// The splats of a pointer that moved from `from` to `to` in `elapsed` seconds, of Gaussian
/// radius `radius`; none when it did not move or no time passed.
std::vector<ForceSplat> strokeSplats(const Vec3& from, const Vec3& to, double elapsed,
                                     double radius, double force);

}  // namespace modeflow::stir
