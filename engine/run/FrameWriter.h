#pragma once
/// @file FrameWriter.h
/// Writes a run's frames beside its simulation: one frame's files (and then its checkpoint, when
/// it writes one: CheckpointSchedule) on another thread while the next frame is simulated, at
/// most one frame at a time, in frame order. A frame's checkpoint is written after its files, so
/// a resumed run never starts past a frame that is missing. What a frame's writing throws comes
/// out of the next call (start or finish).

#include <filesystem>
#include <future>

#include "engine/run/FrameProgress.h"
#include "engine/run/FramedRun.h"

namespace modeflow {

class FrameWriter {
public:
    /// Checkpoints go to `checkpointPath`; times go to `bar` (which must outlive this).
    FrameWriter(std::filesystem::path checkpointPath, FrameProgress& bar);
    /// Waits for the frame being written (its error, if any, is lost: the run has failed already).
    ~FrameWriter();
    FrameWriter(const FrameWriter&) = delete;
    FrameWriter& operator=(const FrameWriter&) = delete;

    /// Waits for the previous frame's files, then starts writing `frame`'s files and, with
    /// `checkpoint`, its checkpoint.
    /// @throw modeflow::Error (or what else it threw) when the previous frame's writing failed.
    void start(FrameOutput frame, bool checkpoint = true);
    /// Waits for the last frame's files and checkpoint.
    /// @throw what its writing threw.
    void finish();
    /// Seconds the last checkpoint of the frames finished so far took to write (0: none yet).
    double lastCheckpointSeconds() const { return mLastCheckpointSeconds; }

private:
    std::filesystem::path mCheckpointPath;
    FrameProgress& mBar;
    std::future<double> mWriting;  ///< the checkpoint's seconds, 0 without one
    double mLastCheckpointSeconds = 0.0;
};

}  // namespace modeflow
