#include "engine/run/FrameWriter.h"

#include <chrono>
#include <memory>
#include <utility>

namespace modeflow {

FrameWriter::FrameWriter(std::filesystem::path checkpointPath, FrameProgress& bar)
    : mCheckpointPath(std::move(checkpointPath)), mBar(bar) {}

FrameWriter::~FrameWriter() {
    if (mWriting.valid()) mWriting.wait();
}

void FrameWriter::start(FrameOutput frame, bool checkpoint) {
    finish();
    auto output = std::make_shared<FrameOutput>(std::move(frame));
    mWriting = std::async(std::launch::async, [this, output, checkpoint] {
        output->writeFiles(output->checkpoint, mBar);
        if (!checkpoint) return 0.0;
        const auto begin = std::chrono::steady_clock::now();
        mBar.timed("checkpoint", [&] { writeCheckpoint(mCheckpointPath, output->checkpoint); });
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
    });
}

void FrameWriter::finish() {
    if (!mWriting.valid()) return;
    // Time the simulation waits for the files: what writing beside it did not hide.
    mBar.timed("waiting for files", [&] { mWriting.wait(); });
    if (const double seconds = mWriting.get(); seconds > 0.0) mLastCheckpointSeconds = seconds;
}

}  // namespace modeflow
