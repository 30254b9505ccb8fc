#pragma once
/// @file CoefficientChoice.h
/// Which structural coefficients a cache keeps (`[basis] coefficients`): a dense or sparse tensor
/// assembled from the vorticity quadrature, or none (tensor-free: the runtime evaluates the
/// advection from the quadrature and the modes, engine/dynamics/TensorFreeCoefficients.h).
///
/// "auto" assembles no tensor when it would not fit (more than a quarter of the available memory:
/// a run holds it up to three times, engine/simulation/RunMemory.h) or when the tensor-free
/// advection is predicted cheaper per evaluation. Per evaluation a tensor streams N²(N−1)/2
/// coefficients; the tensor-free advection streams the modes twice (reconstruction, projection),
/// 2·V·N values for V velocity DOFs, plus the quadrature. Per value streamed the tensor-free
/// advection costs kTensorFreeValueCost times a stored coefficient (tools/bench/bench_tensor_free,
/// 48³ box, N = 250–1000: 0.8–1.2 on the CPU reference, 0.9–1.6 on lavapipe), so it wins once
/// N(N−1) > 4·kTensorFreeValueCost·V: N ≈ 1400 on a 48³ box.
/// A precompute that assembles none says why (TensorChoice::reason). A tensor that "auto"
/// assembles is stored sparse below a density of 0.25 (boxes, appendix C.2).

#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/Progress.h"
#include "engine/core/SceneSpec.h"
#include "engine/format/BasisCache.h"

namespace modeflow {

/// Cost of a value the tensor-free advection streams, relative to a stored coefficient.
inline constexpr double kTensorFreeValueCost = 1.5;

/// Whether a precompute assembles a tensor, and why, in words for its output.
struct TensorChoice {
    bool assemble = true;
    std::string
        reason;  ///< e.g. "auto: the tensor-free advection streams fewer values per step (…)"
};

/// The choice of a precompute with `requested` storage for `modes` velocity modes on
/// `velocityDofs` faces (auto: see the file comment; availableMemory() is read).
TensorChoice chooseTensor(CoefficientStorage requested, int modes, std::int64_t velocityDofs);

/// The coefficients a cache stores for `requested` from the packed k < j tensor: dense or
/// sparse as requested, or by density for auto (entries below 1e-12 · max |C| count as zero).
BasisCache::Coefficients storedCoefficients(CoefficientStorage requested,
                                            std::vector<double> packed, int modes);

/// A cache assembled without a tensor that is now wanted dense or sparse gets one, assembled from
/// its quadrature and modes (a "structural coefficients" stage on `progress`); true when it did.
/// Auto and tensor-free take the cache as it is.
bool completeCoefficients(BasisCache& cache, CoefficientStorage requested, Progress& progress);

}  // namespace modeflow
