#pragma once
/// @file SharedRuns.h
/// Runs set up on the shared real bases (RealBases.h), the way `run` and `stir` set them up.

#include "engine/core/SceneSpec.h"
#include "tools/compose/RunPreparation.h"

namespace modeflow::testing {

/// The scene's run (prepareRun) on its shared basis.
RunInputs sharedRun(const SceneSpec& scene);

}  // namespace modeflow::testing
