#pragma once
/// @file Image.h
/// An 8-bit RGBA picture in memory: what the preview renderers return and writePng() stores.
/// Rows run from the top of the picture down (row 0 is the top row), pixels left to right, four
/// bytes per pixel (red, green, blue, alpha), no padding between rows.

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace modeflow::preview {

/// An sRGB-encoded colour, alpha last.
using Rgba = std::array<std::uint8_t, 4>;

struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgba;  ///< width · height · 4 bytes

    Image() = default;
    /// A width × height picture filled with `fill`.
    Image(int w, int h, Rgba fill = {0, 0, 0, 255})
        : width(w), height(h), rgba(std::size_t(w) * std::size_t(h) * 4) {
        for (std::size_t p = 0; p < rgba.size(); p += 4)
            for (int c = 0; c < 4; ++c) rgba[p + c] = fill[c];
    }

    /// Offset of pixel (x, y)'s red byte in rgba.
    std::size_t offset(int x, int y) const { return (std::size_t(y) * std::size_t(width) + x) * 4; }
    Rgba pixel(int x, int y) const {
        const std::size_t o = offset(x, y);
        return {rgba[o], rgba[o + 1], rgba[o + 2], rgba[o + 3]};
    }
    void setPixel(int x, int y, Rgba c) {
        const std::size_t o = offset(x, y);
        for (int k = 0; k < 4; ++k) rgba[o + k] = c[k];
    }
};

/// A width × height picture from packed 8-bit pixels as kernels write them: red in the lowest
/// byte, or blue there with `blueFirst` (B8G8R8A8 swapchains); alpha made opaque. Unpacked byte
/// by byte, so it is right on any host.
inline Image unpackImage(std::span<const std::uint32_t> words, int width, int height,
                         bool blueFirst = false) {
    Image image(width, height);
    for (std::size_t p = 0; p < words.size() && p < std::size_t(width) * std::size_t(height); ++p) {
        const std::uint32_t w = words[p];
        const std::uint8_t low = std::uint8_t(w), high = std::uint8_t(w >> 16);
        image.rgba[4 * p + 0] = blueFirst ? high : low;
        image.rgba[4 * p + 1] = std::uint8_t(w >> 8);
        image.rgba[4 * p + 2] = blueFirst ? low : high;
        image.rgba[4 * p + 3] = 255;
    }
    return image;
}

}  // namespace modeflow::preview
