#include "engine/run/FrameWriter.h"

#include <memory>
#include <utility>

namespace modeflow {

FrameWriter::FrameWriter(std::filesystem::path checkpointPath, FrameProgress& bar)
    : mCheckpointPath(std::move(checkpointPath)), mBar(bar) {}

FrameWriter::~FrameWriter() {
    if (mWriting.valid()) mWriting.wait();
}

void FrameWriter::start(FrameOutput frame) {
    finish();
    auto output = std::make_shared<FrameOutput>(std::move(frame));
    mWriting = std::async(std::launch::async, [this, output] {
        output->writeFiles(output->checkpoint, mBar);
        mBar.timed("checkpoint", [&] { writeCheckpoint(mCheckpointPath, output->checkpoint); });
    });
}

void FrameWriter::finish() {
    if (!mWriting.valid()) return;
    // Time the simulation waits for the files: what writing beside it did not hide.
    mBar.timed("waiting for files", [&] { mWriting.wait(); });
    mWriting.get();
}

}  // namespace modeflow
