/// @file FrameWriterTest.cpp
/// FrameWriter writes a frame's files and then its checkpoint beside the simulation, one frame at
/// a time in frame order, up to kFramesAhead frames behind the caller, and what a frame's writing
/// throws comes out of a later call, no frame after it written.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <string>
#include <thread>
#include <vector>

#include "engine/core/Error.h"
#include "engine/run/FrameWriter.h"
#include "tests/support/TestFolder.h"
#include "tests/support/ThrownMessage.h"

namespace modeflow {
namespace {

/// Frame `frame`'s output: its checkpoint (a little smoke) and files that `write` writes.
FrameOutput frameOutput(int frame, std::function<void(const Checkpoint&, FrameProgress&)> write) {
    FrameOutput out;
    out.checkpoint.frame = frame;
    out.checkpoint.time = 0.1 * frame;
    out.checkpoint.velocity = Eigen::VectorXd::Constant(3, double(frame));
    out.checkpoint.smoke.density = {double(frame)};
    out.checkpoint.smoke.temperature = {0.0};
    out.writeFiles = std::move(write);
    return out;
}

TEST(FrameWriter, WritesAFramesFilesBesideTheCallerThenItsCheckpoint) {
    const testing::TestFolder folder;
    const std::filesystem::path checkpoint = folder / "run.checkpoint";
    FrameProgress bar(0, 2, 1);
    FrameWriter writer(checkpoint, bar);
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    bool checkpointBeforeFiles = true;
    writer.start(frameOutput(1, [&](const Checkpoint& state, FrameProgress&) {
        released.wait();  // the files are written while the caller goes on
        checkpointBeforeFiles = std::filesystem::exists(checkpoint);
        std::ofstream(folder / ("frame_" + std::to_string(state.frame))) << state.frame;
    }));
    // start() came back with frame 1's files still being written.
    EXPECT_FALSE(std::filesystem::exists(folder / "frame_1"));
    release.set_value();
    writer.finish();
    EXPECT_FALSE(checkpointBeforeFiles);
    EXPECT_TRUE(std::filesystem::exists(folder / "frame_1"));
    EXPECT_EQ(readCheckpoint(checkpoint).frame, 1);
}

TEST(FrameWriter, WritesOneFrameAtATimeInFrameOrder) {
    const testing::TestFolder folder;
    FrameProgress bar(0, 5, 1);
    FrameWriter writer(folder / "run.checkpoint", bar);
    std::vector<int> written;
    int writing = 0, mostAtOnce = 0;
    for (int frame = 1; frame <= 5; ++frame)
        writer.start(frameOutput(frame, [&](const Checkpoint& state, FrameProgress&) {
            mostAtOnce = std::max(mostAtOnce, ++writing);
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
            written.push_back(state.frame);
            --writing;
        }));
    writer.finish();
    EXPECT_EQ(written, (std::vector<int>{1, 2, 3, 4, 5}));
    EXPECT_EQ(mostAtOnce, 1);
    EXPECT_EQ(readCheckpoint(folder / "run.checkpoint").frame, 5);
}

TEST(FrameWriter, TheCallerRunsUpToTwoFramesAheadOfTheFiles) {
    const testing::TestFolder folder;
    FrameProgress bar(0, 4, 1);
    FrameWriter writer(folder / "run.checkpoint", bar);
    std::promise<void> release;
    std::shared_future<void> released = release.get_future().share();
    std::vector<int> written;
    const auto write = [&](const Checkpoint& state, FrameProgress&) {
        released.wait();
        written.push_back(state.frame);
    };
    // Frame 1 is being written and frame 2 waits: both handed over at once.
    writer.start(frameOutput(1, write));
    writer.start(frameOutput(2, write));
    ASSERT_EQ(FrameWriter::kFramesAhead, 2);
    // A third waits for frame 1's files.
    std::future<void> third =
        std::async(std::launch::async, [&] { writer.start(frameOutput(3, write)); });
    EXPECT_EQ(third.wait_for(std::chrono::milliseconds(100)), std::future_status::timeout);
    release.set_value();
    third.get();
    writer.start(frameOutput(4, write));
    writer.finish();
    EXPECT_EQ(written, (std::vector<int>{1, 2, 3, 4}));
    EXPECT_EQ(readCheckpoint(folder / "run.checkpoint").frame, 4);
}

TEST(FrameWriter, AFailedFrameComesOutOfALaterCallAndNoFrameAfterItIsWritten) {
    const testing::TestFolder folder;
    const std::filesystem::path checkpoint = folder / "run.checkpoint";
    FrameProgress bar(0, 3, 1);
    FrameWriter writer(checkpoint, bar);
    const auto fine = [](const Checkpoint&, FrameProgress&) {};
    bool thirdWritten = false;
    writer.start(frameOutput(1, fine));
    writer.start(frameOutput(2, [](const Checkpoint&, FrameProgress&) {
        throw Error("cannot write VDB frame f_0002.vdb: No space left on device");
    }));
    // The error comes out of start(3) if frame 2 failed before it, else out of finish().
    EXPECT_EQ(testing::thrownMessage([&] {
                  writer.start(frameOutput(
                      3, [&](const Checkpoint&, FrameProgress&) { thirdWritten = true; }));
                  writer.finish();
              }),
              "cannot write VDB frame f_0002.vdb: No space left on device");
    EXPECT_FALSE(thirdWritten);
    // Frame 2's checkpoint was never written: a resumed run starts after frame 1.
    EXPECT_EQ(readCheckpoint(checkpoint).frame, 1);

    // The same from finish(), for the last frame.
    FrameWriter last(checkpoint, bar);
    last.start(frameOutput(4, [](const Checkpoint&, FrameProgress&) {
        throw Error("cannot write PLY frame f_0004.ply: Read-only file system");
    }));
    EXPECT_EQ(testing::thrownMessage([&] { last.finish(); }),
              "cannot write PLY frame f_0004.ply: Read-only file system");
    EXPECT_EQ(readCheckpoint(checkpoint).frame, 1);
}

TEST(FrameWriter, ACheckpointThatCannotBeWrittenComesOutOfFinish) {
    const testing::TestFolder folder;
    FrameProgress bar(0, 1, 1);
    // Its folder is missing: the checkpoint's write fails after the frame's files.
    FrameWriter writer(folder / "gone" / "run.checkpoint", bar);
    writer.start(frameOutput(1, [](const Checkpoint&, FrameProgress&) {}));
    EXPECT_NE(testing::thrownMessage([&] { writer.finish(); }).find("run.checkpoint"),
              std::string::npos);
}

}  // namespace
}  // namespace modeflow
