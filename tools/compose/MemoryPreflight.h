#pragma once
/// @file MemoryPreflight.h
/// A run's memory, checked before any work: the estimate of engine/simulation/RunMemory from
/// the velocity DOFs the precompute's estimate expects, refused when it does not fit (a failed
/// allocation despite it names the run's stage: inRunStage, RunMemory.h).

#include "engine/core/SceneSpec.h"
#include "engine/simulation/BackendCapabilities.h"
#include "engine/simulation/RunMemory.h"

namespace modeflow {

/// @throw modeflow::Error naming [grid].resolution, [smoke].resolution_scale and the modes, the
///        estimate and the memory available, when the run of `scene` on `backend` would not fit.
RunMemory requireRunMemory(const SceneSpec& scene, BackendKind backend);

}  // namespace modeflow
