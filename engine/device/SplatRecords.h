#pragma once
/// @file SplatRecords.h
/// Stirring splats as the device kernels read them (shaders/ForceFieldParams.h ForceSplatRecord,
/// float32): the grids' force field and a surface's force take them the same way. For the
/// device's sources only (it includes the shaders' header).

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "engine/simulation/ForceSplat.h"
#include "shaders/ForceFieldParams.h"

namespace modeflow::device {

/// `splats` as records.
/// @throw modeflow::Error naming `kernel` for more than `maxSplats` splats or a radius that is
///        not positive.
std::vector<shaders::ForceSplatRecord> splatRecords(std::span<const ForceSplat> splats,
                                                    std::size_t maxSplats, const char* kernel);

}  // namespace modeflow::device
