#pragma once
/// @file Preflight.h
/// What every command (and every other composition root) refuses before any precompute or
/// simulation work, in one order: the `--device` option, the scene file, what the chosen backend
/// supports, and, for a run with smoke, its memory. Opening the backend and refusing what its
/// device cannot hold (Backend::requireFits) follows, before any output is made.

#include <filesystem>
#include <string_view>

#include "engine/core/SceneSpec.h"
#include "engine/run/Backend.h"
#include "engine/simulation/RunMemory.h"
#include "tools/compose/RunPreparation.h"

namespace modeflow {

struct Preflight {
    BackendChoice backend;
    SceneSpec scene;
    RunMemory memory;  ///< the run's estimate (RunParts::DynamicsAndSmoke only; else zero)
};

/// @throw modeflow::Error naming the option, the scene key or the memory that is refused.
Preflight preflight(const std::filesystem::path& sceneFile, std::string_view deviceOption,
                    RunParts parts);
/// The same for a scene already read (the Python module's Scene.from_dict, from_toml).
Preflight preflight(SceneSpec scene, std::string_view deviceOption, RunParts parts);

}  // namespace modeflow
