#include "engine/run/FrameWriter.h"

#include <chrono>
#include <utility>

namespace modeflow {

FrameWriter::FrameWriter(std::filesystem::path checkpointPath, FrameProgress& bar)
    : mCheckpointPath(std::move(checkpointPath)), mBar(bar), mWriter([this] { writeFrames(); }) {}

FrameWriter::~FrameWriter() {
    {
        std::unique_lock lock(mMutex);
        mChanged.wait(lock, [&] { return mJobs.empty(); });
        mStopping = true;
    }
    mChanged.notify_all();
    mWriter.join();
}

void FrameWriter::writeFrames() {
    std::unique_lock lock(mMutex);
    while (true) {
        mChanged.wait(lock, [&] { return mStopping || !mJobs.empty(); });
        if (mJobs.empty()) return;
        Job& job = mJobs.front();
        lock.unlock();
        double seconds = 0.0;
        std::exception_ptr failure;
        try {
            job.frame.writeFiles(job.frame.checkpoint, mBar);
            if (job.checkpoint) {
                const auto begin = std::chrono::steady_clock::now();
                mBar.timed("checkpoint",
                           [&] { writeCheckpoint(mCheckpointPath, job.frame.checkpoint); });
                seconds =
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
            }
        } catch (...) {
            failure = std::current_exception();
        }
        lock.lock();
        if (failure) {
            // No frame after a failed one is written: the files on disk stay a run's prefix.
            mFailure = failure;
            mJobs.clear();
        } else {
            if (seconds > 0.0) mLastCheckpointSeconds = seconds;
            mJobs.pop_front();
        }
        mChanged.notify_all();
    }
}

void FrameWriter::rethrowFailure() {
    if (!mFailure) return;
    std::exception_ptr failure = std::exchange(mFailure, nullptr);
    std::rethrow_exception(failure);
}

void FrameWriter::start(FrameOutput frame, bool checkpoint) {
    std::unique_lock lock(mMutex);
    if (!mFailure && int(mJobs.size()) >= kFramesAhead) {
        // Time the simulation waits for the files: what writing beside it did not hide.
        lock.unlock();
        mBar.timed("waiting for files", [&] {
            std::unique_lock waiting(mMutex);
            mChanged.wait(waiting, [&] { return mFailure || int(mJobs.size()) < kFramesAhead; });
        });
        lock.lock();
    }
    rethrowFailure();
    mJobs.push_back({std::move(frame), checkpoint});
    mChanged.notify_all();
}

void FrameWriter::finish() {
    std::unique_lock lock(mMutex);
    if (!mJobs.empty()) {
        lock.unlock();
        mBar.timed("waiting for files", [&] {
            std::unique_lock waiting(mMutex);
            mChanged.wait(waiting, [&] { return mJobs.empty(); });
        });
        lock.lock();
    }
    rethrowFailure();
}

double FrameWriter::lastCheckpointSeconds() const {
    const std::lock_guard lock(mMutex);
    return mLastCheckpointSeconds;
}

}  // namespace modeflow
