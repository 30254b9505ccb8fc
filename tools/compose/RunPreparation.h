#pragma once
/// @file RunPreparation.h
/// Scene + cache folder → a ready run (engine/run/RunInputs.h): the basis cache (precomputed on
/// a miss), its structural coefficients, the run's settings, the smoke mask and the initial
/// state. The one way `run`, `stir`, `modes`, the tests and the benchmarks set up a run.

#include <filesystem>

#include "engine/core/Progress.h"
#include "engine/core/SceneSpec.h"
#include "engine/format/BasisCache.h"
#include "engine/run/RunInputs.h"

namespace modeflow {

/// What a command needs of the scene: the reduced dynamics alone (`modes`), or the smoke too.
enum class RunParts { Dynamics, DynamicsAndSmoke };

/// The scene's cache from `cacheDir` (computed and written on a miss), and all the rest from it.
/// @throw modeflow::Error naming the scene key or stage that failed: an initial state that is
///        not finite, a [[source]] with no fluid cell to emit into, a failed precompute.
RunInputs prepareRun(const SceneSpec& scene, const std::filesystem::path& cacheDir,
                     Progress& progress, RunParts parts = RunParts::DynamicsAndSmoke);

/// The same on a basis already in memory (tests and benchmarks; `cache.key` may be empty, the
/// smoke mask is then built from the domain).
RunInputs prepareRun(const SceneSpec& scene, BasisCache cache,
                     RunParts parts = RunParts::DynamicsAndSmoke);

}  // namespace modeflow
