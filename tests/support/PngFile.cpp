#include "tests/support/PngFile.h"

#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#define STB_IMAGE_IMPLEMENTATION
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace modeflow::testing {

std::optional<PngPixels> readPng(const std::filesystem::path& file) {
    PngPixels png;
    unsigned char* pixels =
        stbi_load(file.string().c_str(), &png.width, &png.height, &png.channelsInFile, 4);
    if (!pixels) return std::nullopt;
    png.rgba.assign(pixels, pixels + std::size_t(png.width) * png.height * 4);
    stbi_image_free(pixels);
    return png;
}

}  // namespace modeflow::testing
