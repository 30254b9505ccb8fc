#pragma once
/// @file CachedCoefficients.h
/// The structural coefficients a cache file holds, as the storage it says (dense or sparse).

#include <memory>

#include "engine/dynamics/StructuralCoefficients.h"
#include "engine/format/BasisCache.h"

namespace modeflow {

/// DenseCoefficients or SparseCoefficients of `cache.coefficients` for its velocity modes.
/// @throw modeflow::Error when the stored arrays do not fit the mode count.
std::unique_ptr<StructuralCoefficients> coefficientsFromCache(const BasisCache& cache);

}  // namespace modeflow
