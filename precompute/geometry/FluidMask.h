#pragma once
/// @file FluidMask.h
/// Which cells of a grid (typically the smoke grid, finer than the basis grid) are fluid: the
/// runtime keeps smoke at exactly zero in the others, so nothing appears outside Ω.

#include <cstdint>
#include <vector>

#include "engine/field/MacGrid.h"
#include "precompute/scene/SceneSpec.h"

namespace modeflow {

/// One byte per cell of `grid` (MacGrid::cellIndex order): 1 where the cell centre is inside the
/// scene's domain (χ > 0, DESIGN §2), else 0. A scene without [[domain]] is fluid everywhere.
/// @throw modeflow::Error when a domain shape cannot be built (e.g. a missing mesh file).
std::vector<std::uint8_t> fluidMask(const SceneSpec& scene, const MacGrid& grid);

}  // namespace modeflow
