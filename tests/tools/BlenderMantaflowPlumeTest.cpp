/// @file BlenderMantaflowPlumeTest.cpp
/// The outside check of `reduced_vs_full` (tools/validate/mantaflow_plume.py run in Blender,
/// MantaflowPlume.h) at 16³ for 3 frames, a few seconds: the script builds the scene, steps it
/// and reads back what the study draws, in the study's units. Skipped, saying why, where no
/// `blender` is on the PATH (label `blender`).

#include <gtest/gtest.h>

#include "tools/validate/MantaflowPlume.h"

namespace modeflow {
namespace {

TEST(BlenderMantaflowPlume, SixteenCubedStepsTheHotBallInTheStudysUnits) {
    const validate::BlenderChoice blender = validate::findBlender(std::nullopt);
    if (blender.program.empty()) GTEST_SKIP() << blender.absence;
    const nlohmann::json run = validate::runMantaflowPlume(blender.program, 16, 3);
    ASSERT_EQ(run.at("resolution"), 16);
    const nlohmann::json& frames = run.at("frames");
    ASSERT_EQ(frames.size(), 3u) << run.dump(1);
    const double dt = 0.02;
    for (std::size_t f = 0; f < frames.size(); ++f) {
        const double k = double(f + 1);
        EXPECT_NEAR(frames[f].at("time").get<double>(), k * dt, 1e-12);
        // The smoke sits in the ball (z in [0.02, 0.18]) and is added at 1 per unit time over
        // the ball's cells: 8 of 16³ (centres inside r = 0.08 at (0.5, 0.5, 0.1)), each 1/16³.
        const double height = frames[f].at("centroid_height");
        EXPECT_GT(height, 0.02) << "frame " << k;
        EXPECT_LT(height, 0.18) << "frame " << k;
        EXPECT_NEAR(frames[f].at("smoke_mass").get<double>(), k * dt * 8.0 / 4096.0, 1e-6)
            << "frame " << k;
    }
    // The heat is (frame − 1)·dt, so no buoyancy in the first step; after it the speed is that
    // of dt·Σ T projected: below dt²·(0 + 1 + 2) = 1.2e-3 at frame 3, and a good part of it (the
    // 64³ ball's projection keeps 0.72 of its peak). A unit slip (Blender's frames, cells or
    // gravity) would be a factor of 2.5 or more.
    EXPECT_LT(frames[0].at("peak_speed").get<double>(), 1e-9);
    const double third = frames[2].at("peak_speed");
    EXPECT_GT(third, 0.3 * 1.2e-3) << "peak speed at frame 3";
    EXPECT_LT(third, 1.0 * 1.2e-3) << "peak speed at frame 3";
}

}  // namespace
}  // namespace modeflow
