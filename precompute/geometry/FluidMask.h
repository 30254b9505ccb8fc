#pragma once
/// @file FluidMask.h
/// Which cells of the smoke grid (the basis grid refined by a scale) are fluid: the runtime keeps
/// smoke at exactly zero in the others, so nothing appears outside Ω.

#include <cstdint>
#include <vector>

#include "engine/format/BasisCache.h"

namespace modeflow {

/// One byte per cell of MacGrid::fromSpec(cache.grid).refined(scale) (cellIndex order), 1 where
/// smoke may be. A smoke cell is fluid when its basis cell has a positive fraction inside Ω (the
/// basis's own notion of fluid: at scale 1 a uniform temperature's buoyancy, a gradient, then
/// projects to round-off, where a cell-centre test leaves 1–2% spurious flow along cut walls)
/// and, on a finer smoke grid, when its centre is inside Ω as well (χ > 0, precompute/README.md).
/// @throw modeflow::Error when a domain shape cannot be built (e.g. a missing mesh file).
std::vector<std::uint8_t> fluidMask(const SceneSpec& scene, const BasisCache& cache, int scale);

/// Whether fluidMask builds the domain (a finer smoke grid in a domain other than the whole
/// box); otherwise it reads the cache's cell fractions alone.
bool fluidMaskNeedsDomain(const SceneSpec& scene, int scale);

}  // namespace modeflow
