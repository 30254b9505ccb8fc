#pragma once
/// @file FrameWriter.h
/// Writes a run's frames beside its simulation: frames' files (and then a frame's checkpoint,
/// when it writes one: CheckpointSchedule) on a writer thread while the next frames are
/// simulated, one frame at a time, in frame order, with up to kFramesAhead frames handed over
/// and not yet written (so a frame that writes slowly, or a simulation that runs fast for a
/// frame, does not stall the other side). A frame's checkpoint is written after its files, so a
/// resumed run never starts past a frame that is missing. What a frame's writing throws comes out
/// of a later call (start or finish), and no frame after it is written.

#include <condition_variable>
#include <deque>
#include <exception>
#include <filesystem>
#include <mutex>
#include <thread>

#include "engine/run/FrameProgress.h"
#include "engine/run/FramedRun.h"

namespace modeflow {

class FrameWriter {
public:
    /// Frames handed over and not yet written at most; start() waits beyond that.
    static constexpr int kFramesAhead = 2;

    /// Checkpoints go to `checkpointPath`; times go to `bar` (which must outlive this).
    FrameWriter(std::filesystem::path checkpointPath, FrameProgress& bar);
    /// Waits for the frames handed over (an error is lost: the run has failed already).
    ~FrameWriter();
    FrameWriter(const FrameWriter&) = delete;
    FrameWriter& operator=(const FrameWriter&) = delete;

    /// Hands `frame`'s files and, with `checkpoint`, its checkpoint to the writer, first waiting
    /// while kFramesAhead frames are waiting or being written.
    /// @throw modeflow::Error (or what else it threw) when an earlier frame's writing failed.
    void start(FrameOutput frame, bool checkpoint = true);
    /// Waits for every frame handed over, files and checkpoints.
    /// @throw what a frame's writing threw.
    void finish();
    /// Seconds the last checkpoint of the frames written so far took to write (0: none yet).
    double lastCheckpointSeconds() const;

private:
    struct Job {
        FrameOutput frame;
        bool checkpoint = true;
    };
    void writeFrames();
    /// Rethrows a frame's error once (the caller holds mMutex).
    void rethrowFailure();

    std::filesystem::path mCheckpointPath;
    FrameProgress& mBar;
    mutable std::mutex mMutex;
    std::condition_variable mChanged;
    std::deque<Job> mJobs;  ///< the front is being written
    std::exception_ptr mFailure;
    bool mStopping = false;
    double mLastCheckpointSeconds = 0.0;
    std::thread mWriter;  ///< last: it starts once the members above exist
};

}  // namespace modeflow
