#pragma once
/// @file ModeMaterialization.h
/// The dense columns of a closed-form velocity basis (engine/format/SeparableModes.h), for what
/// takes columns only: the Vulkan device's basis kernels. A cache stores such a basis as
/// descriptors only, and the CPU reference goes through its transforms (VelocityBasis.h); the
/// columns are formed once, after checking that faces × modes doubles fit in memory.

#include <cstdint>

#include "engine/format/BasisCache.h"

namespace modeflow {

/// Bytes the dense velocity columns take (faces × modes doubles), stored or to be materialized.
double velocityModeBytes(std::int64_t faces, std::int64_t modes);

/// The columns of a closed-form basis from its descriptors (memory checked as below).
Eigen::MatrixXd materializedVelocityModes(const BasisCache& cache);

/// Fills cache.velocity.modes from its descriptors when the basis is closed form and the
/// columns are not there yet; nothing for an eigensolved basis.
/// @throw modeflow::Error naming the mode and face counts, the bytes and the memory available,
///        when the columns would not fit (engine/core/AvailableMemory.h).
void materializeVelocityModes(BasisCache& cache);

}  // namespace modeflow
