/// @file FluidMaskTest.cpp
/// fluidMask: the smoke grid's fluid cells follow the domain at any resolution scale.

#include <cmath>
#include <numbers>
#include <numeric>

#include <gtest/gtest.h>

#include "precompute/geometry/FluidMask.h"
#include "tests/precompute/TestScenes.h"

namespace modeflow {
namespace {

TEST(FluidMask, WholeBoxIsAllFluid) {
    const SceneSpec scene = test::gridScene({8, 6, 4}, {0, 0, 0}, {1, 1, 1}, 3);
    const std::vector<std::uint8_t> mask = fluidMask(scene, MacGrid::fromSpec(scene.grid).refined(2));
    EXPECT_EQ(mask.size(), 16u * 12u * 8u);
    EXPECT_TRUE(std::all_of(mask.begin(), mask.end(), [](std::uint8_t m) { return m == 1; }));
}

TEST(FluidMask, DiskAreaAndPlacementAtEveryScale) {
    SceneSpec scene = test::gridScene({32, 32, 1}, {-1.1, -1.1, 0}, {1.1, 1.1, 0}, 2);
    scene.domain = {test::ball({0.3, 0.0, 0.0}, 0.6)};
    for (const int scale : {1, 2, 3}) {
        const MacGrid grid = MacGrid::fromSpec(scene.grid).refined(scale);
        const std::vector<std::uint8_t> mask = fluidMask(scene, grid);
        const double area = std::accumulate(mask.begin(), mask.end(), 0.0) * grid.cellVolume();
        EXPECT_NEAR(area, std::numbers::pi * 0.36, 0.03) << "scale " << scale;
        // The cell holding the centre is fluid, a corner cell is not.
        const int cx = int((0.3 + 1.1) / grid.spacing[0]), cy = int(1.1 / grid.spacing[1]);
        EXPECT_EQ(mask[std::size_t(grid.cellIndex(cx, cy, 0))], 1);
        EXPECT_EQ(mask[0], 0);
    }
}

}  // namespace
}  // namespace modeflow
