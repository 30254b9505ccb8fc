#pragma once
/// @file SmokeMask.h
/// The smoke mask of a run (which smoke cells hold smoke), from the cache: read from the cell
/// fractions at smoke scale 1 or in a whole-box domain, else from the mask file kept beside the
/// cache (SmokeMaskFile), which is made once per basis and smoke scale.

#include <cstdint>
#include <filesystem>
#include <vector>

#include "engine/core/Progress.h"
#include "engine/core/SceneSpec.h"
#include "engine/format/BasisCache.h"

namespace modeflow {

/// One byte per cell of the smoke grid at the scene's `[smoke] resolution_scale`, non-zero inside
/// Ω. A missing, damaged or stale mask file is rebuilt (noted on `progress`).
/// @throw modeflow::Error when the domain must be rebuilt and cannot be (e.g. a missing mesh), or
///        the mask file cannot be written.
std::vector<std::uint8_t> smokeMaskOf(const SceneSpec& scene, const BasisCache& cache,
                                      const std::filesystem::path& cachePath, Progress& progress);

}  // namespace modeflow
