/// @file MovingSourceTest.cpp
/// Sources on key frames (`[[source]] path`, `rotation`): where they emit at each time, the
/// active list placing them, and the jet regions following them.

#include <gtest/gtest.h>

#include "engine/simulation/SimulationSettings.h"
#include "engine/simulation/SmokeEmitter.h"

namespace modeflow {
namespace {

/// A walled 2D grid (contains() and covers() read its dimension and periodic axes).
const MacGrid kPlane = [] {
    MacGrid grid;
    grid.dim = 2;
    return grid;
}();

TEST(MovingSource, ABallFollowsItsPath) {
    SmokeEmitter ball;
    ball.centre = {0.0, 0.0, 0.0};
    ball.radius = 0.1;
    ball.path = {{1.0, {0.0, 0.0, 0.0}}, {2.0, {1.0, 0.0, 0.0}}};
    const MacGrid& grid = kPlane;
    EXPECT_TRUE(ball.placedAt(0.0).contains({0.05, 0.0, 0.0}, grid)) << "still before the path";
    EXPECT_TRUE(ball.placedAt(1.5).contains({0.55, 0.0, 0.0}, grid));
    EXPECT_FALSE(ball.placedAt(1.5).contains({0.05, 0.0, 0.0}, grid));
    EXPECT_TRUE(ball.placedAt(9.0).contains({0.95, 0.0, 0.0}, grid)) << "held after it";
    ball.start = 1.0;
    EXPECT_TRUE(activeEmitters(std::span(&ball, 1), 1.5).front().contains({0.55, 0.0, 0.0}, grid))
        << "the active list places them";
    EXPECT_TRUE(activeEmitters(std::span(&ball, 1), 0.5).empty());
}

TEST(MovingSource, ABoxTurnsAboutItsMiddle) {
    // A bar along x through (1, 1), a quarter turn a second about z.
    SmokeEmitter bar;
    bar.shape = EmitterShape::Box;
    bar.min = {0.7, 0.95, 0.0};
    bar.max = {1.3, 1.05, 0.0};
    bar.rotation = {{0.0, {0.0, 0.0, 1.0}, 0.0}, {1.0, {0.0, 0.0, 1.0}, 90.0}};
    const MacGrid& grid = kPlane;
    EXPECT_TRUE(bar.placedAt(0.0).contains({1.25, 1.0, 0.0}, grid));
    EXPECT_FALSE(bar.placedAt(0.0).contains({1.0, 1.25, 0.0}, grid));
    EXPECT_TRUE(bar.placedAt(1.0).contains({1.0, 1.25, 0.0}, grid)) << "now along y";
    EXPECT_FALSE(bar.placedAt(1.0).contains({1.25, 1.0, 0.0}, grid));
}

TEST(MovingSource, ItsJetRegionMovesWithIt) {
    SimulationSettings settings;
    SmokeEmitter jet;
    jet.shape = EmitterShape::Box;
    jet.min = {-0.1, -0.1, 0.0};
    jet.max = {0.1, 0.1, 0.0};
    jet.velocity = Vec3{0.0, 2.0, 0.0};
    jet.path = {{0.0, {0.0, 0.0, 0.0}}, {1.0, {0.5, 0.0, 0.0}}};
    settings.emitters = {jet, SmokeEmitter{}};  // the second drives nothing
    const std::vector<MovingObstacle> regions = settings.velocityRegions(0.5);
    ASSERT_EQ(regions.size(), 1u);
    const ObstaclePose pose = regions[0].poseAt(0.5);
    const MacGrid& grid = kPlane;
    EXPECT_TRUE(regions[0].covers({0.3, 0.05, 0.0}, pose, grid));
    EXPECT_FALSE(regions[0].covers({0.0, 0.0, 0.0}, pose, grid));
    EXPECT_EQ(regions[0].velocityOf({0.3, 0.05, 0.0}, pose, grid), (Vec3{0.0, 2.0, 0.0}))
        << "its air moves at the jet's velocity, not the source's";
    jet.end = 0.4;
    settings.emitters = {jet};
    EXPECT_TRUE(settings.velocityRegions(0.5).empty()) << "off: it drives nothing";
}

}  // namespace
}  // namespace modeflow
