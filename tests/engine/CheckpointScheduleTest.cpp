/// @file CheckpointScheduleTest.cpp
/// Which frames write a checkpoint (engine/run/CheckpointSchedule.h): every K-th and the last;
/// automatically, the first, then once 20 times the last one's cost has passed, and the last.

#include <optional>
#include <vector>

#include <gtest/gtest.h>

#include "engine/core/Error.h"
#include "engine/run/CheckpointSchedule.h"

namespace modeflow {
namespace {

std::vector<int> dueFrames(CheckpointSchedule& schedule, int first, int last,
                           double secondsPerFrame, double checkpointSeconds) {
    std::vector<int> frames;
    for (int frame = first; frame <= last; ++frame)
        if (schedule.due(frame, frame * secondsPerFrame)) {
            frames.push_back(frame);
            schedule.written(checkpointSeconds);
        }
    return frames;
}

TEST(CheckpointSchedule, EveryKthFrameAndTheLast) {
    CheckpointSchedule every3(3, 10);
    EXPECT_EQ(dueFrames(every3, 1, 10, 1.0, 5.0), (std::vector<int>{3, 6, 9, 10}));
    // A resumed run keeps the frames' numbers: after frame 6, frames 9 and 10.
    CheckpointSchedule resumed(3, 10);
    EXPECT_EQ(dueFrames(resumed, 7, 10, 1.0, 5.0), (std::vector<int>{9, 10}));
    CheckpointSchedule every1(1, 4);
    EXPECT_EQ(dueFrames(every1, 1, 4, 1.0, 5.0), (std::vector<int>{1, 2, 3, 4}));
    EXPECT_THROW(CheckpointSchedule(0, 4), Error);
    EXPECT_THROW(CheckpointSchedule(-2, 4), Error);
}

TEST(CheckpointSchedule, AutomaticallyUnderAPartInTwentyOfTheRunsTime) {
    // Frames of 0.1 s. A checkpoint of 2 ms: 20 × 2 ms = 40 ms < a frame, every frame.
    CheckpointSchedule cheap(std::nullopt, 6);
    EXPECT_EQ(dueFrames(cheap, 1, 6, 0.1, 0.002), (std::vector<int>{1, 2, 3, 4, 5, 6}));
    // A checkpoint of 24 ms: one per 0.48 s of run, every fifth frame, and the last.
    CheckpointSchedule costly(std::nullopt, 12);
    EXPECT_EQ(dueFrames(costly, 1, 12, 0.1, 0.024), (std::vector<int>{1, 6, 11, 12}));
}

}  // namespace
}  // namespace modeflow
