/// The stir window's clock: real time while steps are cheap, slow motion that says so when not.

#include <gtest/gtest.h>

#include "engine/stir/RealTimeClock.h"

namespace modeflow::stir {
namespace {

TEST(RealTimeClockTest, FollowsTheWallClockWhenStepsAreCheap) {
    RealTimeClock clock(0.01, 1.0 / 30.0);
    int steps = 0;
    for (int frame = 0; frame < 600; ++frame) steps += clock.stepsFor(1.0 / 60.0, 0.001);
    // 10 s of wall time in steps of 0.01 s, give or take the step owed at the end.
    EXPECT_NEAR(steps, 1000, 1);
    EXPECT_NEAR(clock.speed(), 1.0, 1e-9);
    EXPECT_FALSE(clock.isSlowMotion());
}

TEST(RealTimeClockTest, TakesWhatTheBudgetAllowsAndReportsSlowMotion) {
    // Steps of 10 ms of simulated time that cost 20 ms each, 30 fps: one step a frame fits
    // the 1/30 s budget (one more would not), so the simulation runs at 0.3 of real time.
    RealTimeClock clock(0.01, 1.0 / 30.0);
    int steps = 0;
    for (int frame = 0; frame < 300; ++frame) steps += clock.stepsFor(1.0 / 30.0, 0.02);
    EXPECT_EQ(steps, 300);
    EXPECT_NEAR(clock.speed(), 0.3, 1e-3);
    EXPECT_TRUE(clock.isSlowMotion());
    // Cheap steps again: back to real time, without a burst to catch up the time let go.
    const int next = clock.stepsFor(1.0 / 30.0, 0.001);
    EXPECT_LE(next, 4);
    for (int frame = 0; frame < 60; ++frame) clock.stepsFor(1.0 / 30.0, 0.001);
    EXPECT_FALSE(clock.isSlowMotion());
}

TEST(RealTimeClockTest, RestartForgetsTheTimeOwed) {
    RealTimeClock clock(0.01, 1.0);
    EXPECT_EQ(clock.stepsFor(0.005, 0.0), 0);
    clock.restart();
    EXPECT_EQ(clock.stepsFor(0.006, 0.0), 0) << "the 5 ms before the restart are gone";
    EXPECT_EQ(clock.stepsFor(0.004, 0.0), 1);
}

}  // namespace
}  // namespace modeflow::stir
