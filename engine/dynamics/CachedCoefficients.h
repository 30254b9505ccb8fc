#pragma once
/// @file CachedCoefficients.h
/// The structural coefficients of a cache file, in the storage a scene asks for.

#include <memory>

#include "engine/core/SceneSpec.h"
#include "engine/dynamics/StructuralCoefficients.h"
#include "engine/format/BasisCache.h"

namespace modeflow {

/// The coefficients of `cache` for its velocity modes:
///   auto         as stored: DenseCoefficients, SparseCoefficients, or TensorFreeCoefficients when
///                the cache holds no tensor;
///   dense/sparse the stored tensor in that storage (converted when stored the other way);
///   tensor-free  TensorFreeCoefficients over the cache's modes and quadrature (a stored tensor
///                is not used).
/// Tensor-free coefficients keep references into `cache`, which must outlive them.
/// @throw modeflow::Error when the stored arrays do not fit the mode count, or a tensor is asked
///        for and the cache holds none (precompute/CoefficientChoice.h completes such caches).
std::unique_ptr<StructuralCoefficients> coefficientsFromCache(
    const BasisCache& cache, CoefficientStorage requested = CoefficientStorage::Auto);

/// As coefficientsFromCache, moving the stored tensor out of `cache` (which then holds none)
/// instead of copying it: a run holds its gigabytes of coefficients once.
std::unique_ptr<StructuralCoefficients> takeCoefficientsFromCache(
    BasisCache& cache, CoefficientStorage requested = CoefficientStorage::Auto);

}  // namespace modeflow
