#pragma once
/// @file PngFile.h
/// PNG files read back in tests (stb_image): the pictures the previews, screenshots and the stir
/// window write.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace modeflow::testing {

struct PngPixels {
    int width = 0, height = 0;
    int channelsInFile = 0;
    std::vector<std::uint8_t> rgba;  ///< width × height × 4, rows top to bottom
};

/// The picture in `file` as RGBA, or nothing when it is missing or not a PNG stb can read.
std::optional<PngPixels> readPng(const std::filesystem::path& file);

}  // namespace modeflow::testing
