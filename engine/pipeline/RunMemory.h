#pragma once
/// @file RunMemory.h
/// A run's memory, checked before any work: the estimate of engine/simulation/RuntimeMemory from
/// the velocity DOFs the precompute's estimate expects, refused when it does not fit, and the
/// stages of a run named when an allocation fails despite it.

#include <new>
#include <string>

#include "engine/core/AvailableMemory.h"
#include "engine/core/SceneSpec.h"
#include "engine/simulation/BackendCapabilities.h"
#include "engine/simulation/RuntimeMemory.h"

namespace modeflow {

/// @throw modeflow::Error naming [grid].resolution, [smoke].resolution_scale and the modes, the
///        estimate and the memory available, when the run of `scene` on `backend` would not fit.
RunMemory requireRunMemory(const SceneSpec& scene, BackendKind backend);

/// What to lower when a run does not fit.
inline constexpr const char* kRunMemoryAdvice =
    "lower [smoke].resolution_scale, [grid].resolution or the velocity modes in [basis]";

/// `work()`; a std::bad_alloc inside it becomes "out of memory in <stage> (the estimated peak
/// was X); <advice>".
template <typename Work>
decltype(auto) inRunStage(const std::string& stage, const RunMemory& estimate, Work&& work) {
    try {
        return work();
    } catch (const std::bad_alloc&) {
        throw outOfMemoryIn(stage, estimate.peakBytes, kRunMemoryAdvice);
    }
}

}  // namespace modeflow
