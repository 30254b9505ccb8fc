#pragma once
/// @file FrameLoop.h
/// The frame loop of `modeflow run` (and of every other composition root that writes frames):
/// resume or a clean folder, then per frame the step, the frame file, the picture and, on
/// CheckpointSchedule's frames, the checkpoint, with progress on stderr; a contact sheet of the
/// pictures at the end. The stir window has its loop beside it (engine/stir/StirApp.h).

#include <cstdint>
#include <optional>
#include <string>

#include "engine/output/RunFolder.h"
#include "engine/run/FramedRun.h"
#include "engine/simulation/Checkpoint.h"
#include "engine/simulation/RunMemory.h"

namespace modeflow {

struct FrameLoopOptions {
    const RunFolder& folder;
    std::string sceneName;
    int frames = 0;                        ///< the last frame to write
    std::uint64_t runHash = 0;             ///< written into every checkpoint
    std::optional<Checkpoint> resumeFrom;  ///< readResumePoint's; empty: start afresh
    int previewEvery = 0;                  ///< a picture every this many frames; 0: none
    const RunMemory& memory;               ///< the estimate named when an allocation fails
    /// A checkpoint every this many frames (and the last); empty: CheckpointSchedule's
    /// automatic schedule.
    std::optional<int> checkpointEvery = {};
};

/// The checkpoint of an interrupted run in `folder` when `resume` and there is one; empty
/// otherwise. @throw modeflow::Error when it was written for another `runHash` (another scene
/// text, basis or device) or cannot be read.
std::optional<Checkpoint> readResumePoint(const RunFolder& folder, bool resume,
                                          std::uint64_t runHash);

/// Writes frames resumeFrom.frame + 1 … frames of `run` into the folder.
/// @throw modeflow::Error when a frame diverges (with the advice of ModalDivergence.h), a file
///        cannot be written, or memory runs out (naming the frame and the estimate).
void runFrames(FramedRun& run, const FrameLoopOptions& options);

}  // namespace modeflow
