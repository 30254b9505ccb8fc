/// @file FluidMaskTest.cpp
/// fluidMask: the smoke grid's fluid cells follow the basis's cells and the domain at any scale.

#include <algorithm>
#include <numbers>
#include <numeric>

#include <gtest/gtest.h>

#include "engine/core/MacGrid.h"
#include "precompute/geometry/FluidMask.h"
#include "tests/support/TestScenes.h"

namespace modeflow {
namespace {

/// A BasisCache with only the grid and cell fractions filled in: all fluidMask reads.
BasisCache fractionsOnly(const SceneSpec& scene, std::vector<double> fractions) {
    BasisCache cache;
    cache.grid = scene.grid;
    cache.cellFraction = std::move(fractions);
    return cache;
}

TEST(FluidMask, WholeBoxIsAllFluid) {
    const SceneSpec scene = testing::gridScene({8, 6, 4}, {0, 0, 0}, {1, 1, 1}, 3);
    const std::vector<std::uint8_t> mask =
        fluidMask(scene, fractionsOnly(scene, std::vector<double>(192, 1.0)), 2);
    EXPECT_EQ(mask.size(), 16u * 12u * 8u);
    EXPECT_TRUE(std::all_of(mask.begin(), mask.end(), [](std::uint8_t m) { return m == 1; }));
}

TEST(FluidMask, FollowsBasisCellsAtScaleOneAndTheDomainOnFinerGrids) {
    SceneSpec scene = testing::gridScene({32, 32, 1}, {-1.1, -1.1, 0}, {1.1, 1.1, 0}, 2);
    scene.domain = {testing::ball({0.3, 0.0, 0.0}, 0.6)};
    const MacGrid basis = MacGrid::fromSpec(scene.grid);
    // Fractions of a disk by sub-sampling: what the precompute's cut cells give, near enough.
    std::vector<double> fractions(std::size_t(basis.cellCount()), 0.0);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 32; ++x) {
            int inside = 0;
            for (int sy = 0; sy < 8; ++sy)
                for (int sx = 0; sx < 8; ++sx) {
                    const double px =
                        basis.origin[0] + (x + (sx + 0.5) / 8) * basis.spacing[0] - 0.3;
                    const double py = basis.origin[1] + (y + (sy + 0.5) / 8) * basis.spacing[1];
                    inside += px * px + py * py < 0.36;
                }
            fractions[std::size_t(basis.cellIndex(x, y, 0))] = inside / 64.0;
        }
    const BasisCache cache = fractionsOnly(scene, fractions);
    const std::vector<std::uint8_t> coarse = fluidMask(scene, cache, 1);
    for (std::size_t c = 0; c < coarse.size(); ++c)
        EXPECT_EQ(coarse[c], fractions[c] > 0.0 ? 1 : 0) << c;
    for (const int scale : {2, 3}) {
        const MacGrid grid = basis.refined(scale);
        const std::vector<std::uint8_t> mask = fluidMask(scene, cache, scale);
        const double area = std::accumulate(mask.begin(), mask.end(), 0.0) * grid.cellVolume();
        EXPECT_NEAR(area, std::numbers::pi * 0.36, 0.03) << "scale " << scale;
        EXPECT_EQ(mask[0], 0);
    }
}

}  // namespace
}  // namespace modeflow
