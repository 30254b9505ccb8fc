/// @file DisplayKernelTest.cpp
/// The stir window's 2D picture (DisplayKernels::recordSmoke2D, shaders/display_smoke_2d.comp)
/// along periodic axes: the smoke is drawn across the seam and the box has no wall on that side
/// (nor on the sides a wind flows through); flames glow.

#include <array>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "engine/display/DisplayKernels.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "shaders/DisplayParams.h"
#include "tests/support/VulkanTestContext.h"

namespace modeflow::display {
namespace {

using vulkan::DeviceBuffer;

enum class SidesX { Walls, Periodic, Wind, OpenRight };

/// An 8 × 4 grid of [0, 2] × [0, 1] whose only smoke is a density of 1 in the last column.
MacGrid stripeGrid(SidesX sides) {
    MacGrid grid;
    grid.dim = 2;
    grid.cells = {8, 4, 1};
    grid.spacing = {0.25, 0.25, 1.0};
    grid.periodic = {sides == SidesX::Periodic, false, false};
    grid.flowThrough = {sides == SidesX::Wind, false, false};
    grid.open[1] = sides == SidesX::OpenRight;  // x_max
    return grid;
}

/// The picture of stripeGrid in a window of `width` × 80 pixels, its viewport 160 × 80 in the
/// middle (20 pixels a cell): packed RGBA8 words, red in the low byte; `flame` (per cell,
/// empty: none) glows with `flameScale`.
std::vector<std::uint32_t> drawStripe(const vulkan::VulkanContext& context, SidesX sides, int width,
                                      const std::vector<float>& flame = {},
                                      float flameScale = 0.0f) {
    const MacGrid grid = stripeGrid(sides);
    std::vector<float> smoke(2 * std::size_t(grid.cellCount()), 0.0f);
    for (int y = 0; y < grid.cells[1]; ++y) smoke[2 * std::size_t(grid.cellIndex(7, y, 0))] = 1.0f;
    const DeviceBuffer smokeBuffer = DeviceBuffer::fromValues<float>(context, smoke, "smoke");
    const DeviceBuffer mask = DeviceBuffer::fromValues<std::uint8_t>(
        context, std::vector<std::uint8_t>(std::size_t(grid.cellCount()), 1), "mask");
    const DeviceBuffer velocity = DeviceBuffer::fromValues<float>(
        context, std::vector<float>(std::size_t(grid.faceTotal()), 0.0f), "velocity");
    const std::size_t pixelCount = std::size_t(width) * 80;
    const DeviceBuffer overlay = DeviceBuffer::fromValues<std::uint8_t>(
        context, std::vector<std::uint8_t>(pixelCount, DISPLAY_OVERLAY_NONE), "overlay");
    const DeviceBuffer pixels(context, pixelCount * 4, "pixels");
    DisplayTarget target;
    target.width = width;
    target.height = 80;
    target.viewport = Viewport::letterbox(width, 80, 2.0);
    const DisplayKernels kernels(context);
    vulkan::CommandSequence sequence(context);
    const DeviceBuffer flameBuffer = DeviceBuffer::fromValues<float>(
        context, flame.empty() ? std::vector<float>(1, 0.0f) : flame, "flame");
    Smoke2DLook look;
    look.flameScale = flameScale;
    kernels.recordSmoke2D(sequence,
                          FieldBuffers{smokeBuffer, mask, velocity, grid, grid,
                                       flame.empty() ? nullptr : &flameBuffer},
                          look, overlay, target, pixels);
    sequence.submitAndWait();
    std::vector<std::uint32_t> words(pixelCount);
    pixels.download<std::uint32_t>(words);
    return words;
}

int red(std::uint32_t word) {
    return int(word & 0xffu);
}

class DisplayKernelTest : public testing::VulkanTest {};

TEST_P(DisplayKernelTest, TheSmokeOfTheLastColumnShowsAtTheFirstAcrossAPeriodicSeam) {
    // The leftmost pixels lie a quarter cell left of the first cell's centre: along a periodic x
    // they blend in the last column (about half of it), between walls they hold the first's 0.
    const int background = int(DISPLAY_BACKGROUND_R * 255.0 + 0.5);
    const std::vector<std::uint32_t> periodic = drawStripe(context(), SidesX::Periodic, 160);
    const std::vector<std::uint32_t> walled = drawStripe(context(), SidesX::Walls, 160);
    const std::size_t leftmost = 40 * 160, rightmost = leftmost + 159;
    EXPECT_GT(red(periodic[leftmost]), background + 60) << "periodic: smoke across the seam";
    EXPECT_EQ(red(walled[leftmost]), background) << "walled: no smoke at the first column";
    EXPECT_GT(red(walled[rightmost]), background + 60) << "the last column itself";
}

TEST_P(DisplayKernelTest, NoWallIsDrawnBesideAPeriodicAxis) {
    // A 200-pixel-wide window: the 160-pixel viewport has 20 pixels of margin left and right, a
    // wall frame 3 pixels wide in them between walls, none along a periodic x.
    const int wall = int(DISPLAY_WALL_R * 255.0 + 0.5);
    const std::size_t besideLeft = 40 * 200 + 18;
    EXPECT_EQ(red(drawStripe(context(), SidesX::Walls, 200)[besideLeft]), wall);
    EXPECT_LT(red(drawStripe(context(), SidesX::Periodic, 200)[besideLeft]), wall - 30);
}

TEST_P(DisplayKernelTest, NoWallIsDrawnBesideTheSidesAWindFlowsThrough) {
    // The sides a wind crosses (MacGrid::flowThrough, the stir window's air grid) are open as a
    // periodic axis's are; the top and bottom keep their walls.
    const int wall = int(DISPLAY_WALL_R * 255.0 + 0.5);
    const std::vector<std::uint32_t> windy = drawStripe(context(), SidesX::Wind, 200);
    EXPECT_LT(red(windy[40 * 200 + 18]), wall - 30) << "left side";
    EXPECT_LT(red(windy[40 * 200 + 181]), wall - 30) << "right side";
    // An open side ([grid] open) has no wall; the other side of its axis keeps its own.
    const std::vector<std::uint32_t> open = drawStripe(context(), SidesX::OpenRight, 200);
    EXPECT_EQ(red(open[40 * 200 + 18]), wall) << "left side, a wall";
    EXPECT_LT(red(open[40 * 200 + 181]), wall - 30) << "right side, open";
}

TEST_P(DisplayKernelTest, FlamesGlowInProportionToTheirScale) {
    // A flame of 4 in the first column. Pixel 10 samples a fortieth of a cell right of its
    // centre: a flame of 3.9, 0.975 of full glow at scale 4, half that at scale 8; without flame
    // values, the smoke alone.
    const MacGrid grid = stripeGrid(SidesX::Walls);
    std::vector<float> flame(std::size_t(grid.cellCount()), 0.0f);
    for (int y = 0; y < grid.cells[1]; ++y) flame[std::size_t(grid.cellIndex(0, y, 0))] = 4.0f;
    const std::size_t middle = 40 * 160 + 10;
    const int background = int(DISPLAY_BACKGROUND_R * 255.0 + 0.5);
    const int full = int(DISPLAY_FLAME_R * 255.0 + 0.5);
    const auto glowing = [&](double fraction) {
        return background + fraction * (full - background);
    };
    EXPECT_NEAR(red(drawStripe(context(), SidesX::Walls, 160, flame, 4.0f)[middle]), glowing(0.975),
                1.0);
    EXPECT_NEAR(red(drawStripe(context(), SidesX::Walls, 160, flame, 8.0f)[middle]),
                glowing(0.4875), 1.0);
    EXPECT_EQ(red(drawStripe(context(), SidesX::Walls, 160)[middle]), background);
}

INSTANTIATE_TEST_SUITE_P(Vulkan, DisplayKernelTest, ::testing::Bool(), testing::validationName);

}  // namespace
}  // namespace modeflow::display
