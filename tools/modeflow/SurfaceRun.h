#pragma once
/// @file SurfaceRun.h
/// `run` for a surface scene (scenes/README.md, "Curved surfaces"): the CPU simulation of the flow
/// and its dye, one PLY file per frame (with --preview, PNG pictures and a contact sheet too) and
/// the resume checkpoint (the dye's modal state [mean, f] in
/// the checkpoint's density, zeros in its temperature).

#include <filesystem>
#include <optional>
#include <string>

#include "engine/core/SceneSpec.h"
#include "engine/output/RunFolder.h"
#include "engine/pipeline/RunMemory.h"
#include "engine/simulation/Checkpoint.h"

namespace modeflow::cli {

struct SurfaceRunOptions {
    const SceneSpec& scene;
    int frames = 0;
    const RunFolder& folder;
    std::string sceneHash;
    std::uint64_t runHash = 0;
    std::optional<Checkpoint> resumeFrom;
    std::filesystem::path cacheDir;
    const RunMemory& memory;
    int previewEvery = 0;  ///< a picture every this many frames; 0: none
};

/// Runs the frames and returns the exit status.
int runSurface(const SurfaceRunOptions& options);

}  // namespace modeflow::cli
