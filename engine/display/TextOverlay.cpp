#include "engine/display/TextOverlay.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#include <stb/stb_easy_font.h>
#pragma GCC diagnostic pop

#include "shaders/DisplayParams.h"

namespace modeflow::display {
namespace {

struct Quad {
    float x0, y0, x1, y1;  ///< font pixels, relative to the block's corner
};

/// The glyph quads of `text` (stb_easy_font: four vertices of 16 bytes per quad).
std::vector<Quad> glyphQuads(std::string text) {
    std::vector<char> vertices(text.size() * 300 + 64);
    const int quads = stb_easy_font_print(0.0f, 0.0f, text.data(), nullptr, vertices.data(),
                                          int(vertices.size()));
    std::vector<Quad> out;
    for (int q = 0; q < quads; ++q) {
        float corner[4][2];
        for (int v = 0; v < 4; ++v)
            std::copy_n(reinterpret_cast<const float*>(vertices.data() + (4 * q + v) * 16), 2,
                        corner[v]);
        out.push_back({corner[0][0], corner[0][1], corner[2][0], corner[2][1]});
    }
    return out;
}

void fill(std::vector<std::uint8_t>& codes, int width, int height, int x0, int y0, int x1, int y1,
          std::uint8_t code) {
    for (int y = std::max(y0, 0); y < std::min(y1, height); ++y)
        for (int x = std::max(x0, 0); x < std::min(x1, width); ++x) {
            std::uint8_t& c = codes[std::size_t(y) * std::size_t(width) + std::size_t(x)];
            c = std::max(c, code);
        }
}

}  // namespace

int textWidth(const std::string& text, int scale) {
    std::string copy = text;  // stb_easy_font takes a mutable string
    return stb_easy_font_width(copy.data()) * scale;
}

std::vector<std::uint8_t> rasterizeText(int width, int height, std::span<const TextBlock> blocks,
                                        int scale) {
    std::vector<std::uint8_t> codes(std::size_t(width) * std::size_t(height), DISPLAY_OVERLAY_NONE);
    for (const TextBlock& block : blocks) {
        std::string text = block.text;
        const int w = textWidth(text, scale);
        const int h = stb_easy_font_height(text.data()) * scale;
        const int margin = 4 * scale;
        // Negative corners count from the far edges, so a block can hug the right or bottom.
        const int left = block.x >= 0 ? block.x : width + block.x - w;
        const int top = block.y >= 0 ? block.y : height + block.y - h;
        if (block.panel)
            fill(codes, width, height, left - margin, top - margin, left + w + margin,
                 top + h + margin, DISPLAY_OVERLAY_PANEL);
        const std::vector<Quad> quads = glyphQuads(text);
        for (const std::uint8_t code : {DISPLAY_OVERLAY_SHADOW, DISPLAY_OVERLAY_TEXT}) {
            const int shift = code == DISPLAY_OVERLAY_SHADOW ? std::max(1, scale / 2) : 0;
            for (const Quad& q : quads)
                fill(codes, width, height, left + shift + int(std::lround(q.x0 * scale)),
                     top + shift + int(std::lround(q.y0 * scale)),
                     left + shift + int(std::lround(q.x1 * scale)),
                     top + shift + int(std::lround(q.y1 * scale)), std::uint8_t(code));
        }
    }
    return codes;
}

void TextOverlay::update(int width, int height, std::span<const TextBlock> blocks, int scale) {
    if (mBuffer && width == mWidth && height == mHeight && scale == mScale &&
        std::equal(blocks.begin(), blocks.end(), mBlocks.begin(), mBlocks.end()))
        return;
    std::vector<std::uint8_t> codes = rasterizeText(width, height, blocks, scale);
    // Whole words, so the kernels may read the last pixels' word.
    codes.resize((codes.size() + 3) / 4 * 4 + (codes.empty() ? 4 : 0), DISPLAY_OVERLAY_NONE);
    if (!mBuffer || width != mWidth || height != mHeight)
        mBuffer = std::make_unique<vulkan::DeviceBuffer>(mContext, codes.size(), "text overlay");
    mBuffer->upload<std::uint8_t>(codes);
    mBlocks.assign(blocks.begin(), blocks.end());
    mWidth = width;
    mHeight = height;
    mScale = scale;
}

}  // namespace modeflow::display
