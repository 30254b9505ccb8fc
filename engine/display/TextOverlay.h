#pragma once
/// @file TextOverlay.h
/// Text over the window's picture (statistics, the key help): blocks of lines rasterized on the
/// CPU with stb_easy_font into one byte per window pixel (DisplayParams.h's overlay codes: text,
/// its shadow, a darkened panel behind it), uploaded to the device only when the text or the
/// window size changes. The display kernels blend it in.

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::display {

struct TextBlock {
    int x = 0, y = 0;    ///< top-left corner in window pixels; negative: from the right/bottom edge
    std::string text;    ///< lines separated by '\n'
    bool panel = false;  ///< darken a rectangle behind the text
    bool operator==(const TextBlock&) const = default;
};

/// The width in pixels of `text`'s widest line drawn with `scale`.
int textWidth(const std::string& text, int scale);

/// The overlay codes of `blocks` in a width × height window, one byte per pixel (rows from the
/// top), glyphs drawn `scale` pixels per font pixel.
std::vector<std::uint8_t> rasterizeText(int width, int height, std::span<const TextBlock> blocks,
                                        int scale);

class TextOverlay {
public:
    explicit TextOverlay(const vulkan::VulkanContext& context) : mContext(context) {}

    /// Makes the device overlay show `blocks` in a width × height window.
    void update(int width, int height, std::span<const TextBlock> blocks, int scale);
    /// The overlay bytes, four to a word (valid after update()).
    const vulkan::DeviceBuffer& buffer() const { return *mBuffer; }

private:
    const vulkan::VulkanContext& mContext;
    // What the device holds, so an unchanged overlay costs nothing.
    std::vector<TextBlock> mBlocks;
    int mWidth = 0, mHeight = 0, mScale = 0;
    std::unique_ptr<vulkan::DeviceBuffer> mBuffer;
};

}  // namespace modeflow::display
