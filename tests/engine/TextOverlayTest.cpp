/// Text over the stir window's picture, rasterized on the CPU.

#include <gtest/gtest.h>

#include "engine/display/TextOverlay.h"
#include "shaders/DisplayParams.h"

namespace modeflow::display {
namespace {

/// The bounding box of the pixels with `code`: {x0, y0, x1, y1}, x1/y1 exclusive.
std::array<int, 4> extent(const std::vector<std::uint8_t>& codes, int width, std::uint8_t code) {
    std::array<int, 4> box{1 << 30, 1 << 30, -1, -1};
    for (std::size_t p = 0; p < codes.size(); ++p)
        if (codes[p] == code) {
            const int x = int(p % std::size_t(width)), y = int(p / std::size_t(width));
            box = {std::min(box[0], x), std::min(box[1], y), std::max(box[2], x + 1),
                   std::max(box[3], y + 1)};
        }
    return box;
}

TEST(TextOverlayTest, DrawsGlyphsWithShadowsWhereTheBlockIs) {
    const TextBlock block{10, 20, "fps 60", false};
    const auto codes = rasterizeText(200, 100, std::span(&block, 1), 2);
    ASSERT_EQ(codes.size(), 200u * 100u);
    const auto text = extent(codes, 200, DISPLAY_OVERLAY_TEXT);
    EXPECT_GE(text[0], 10);
    EXPECT_GE(text[1], 20);
    EXPECT_LT(text[3], 20 + 2 * 12 + 2) << "one line of a 12-pixel font at scale 2";
    EXPECT_GT(text[2], text[0] + 40) << "six characters";
    const auto shadow = extent(codes, 200, DISPLAY_OVERLAY_SHADOW);
    EXPECT_GT(shadow[2], text[2] - 1);
    EXPECT_EQ(extent(codes, 200, DISPLAY_OVERLAY_PANEL)[2], -1) << "no panel asked for";
}

TEST(TextOverlayTest, NegativeCornersHugTheFarEdgesAndPanelsDarkenBehind) {
    const TextBlock block{-5, -5, "help\nkeys", true};
    const auto codes = rasterizeText(300, 200, std::span(&block, 1), 1);
    const auto text = extent(codes, 300, DISPLAY_OVERLAY_TEXT);
    EXPECT_LE(text[2], 295);
    EXPECT_GT(text[2], 280);
    EXPECT_LE(text[3], 195);
    const auto panel = extent(codes, 300, DISPLAY_OVERLAY_PANEL);
    EXPECT_LT(panel[0], text[0]);
    EXPECT_LT(panel[1], text[1]);
    // Clipped at the window's edges, never outside the buffer.
    const TextBlock off{290, 190, "clipped text", true};
    EXPECT_NO_THROW(rasterizeText(300, 200, std::span(&off, 1), 3));
}

}  // namespace
}  // namespace modeflow::display
