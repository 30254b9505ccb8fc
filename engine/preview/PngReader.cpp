#include "engine/preview/PngReader.h"

#include <memory>
#include <string>

#include "engine/core/Error.h"

// The one translation unit with stb_image's definitions; static, so they cannot clash with
// another copy of stb linked into the same program.
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb/stb_image.h>
#pragma GCC diagnostic pop

namespace modeflow::preview {

Image readPng(const std::filesystem::path& file) {
    int width = 0, height = 0, channels = 0;
    const std::unique_ptr<unsigned char, void (*)(void*)> pixels(
        stbi_load(file.string().c_str(), &width, &height, &channels, 4), stbi_image_free);
    if (!pixels)
        throw Error("picture \"" + file.string() + "\" cannot be read: " + stbi_failure_reason());
    Image image;
    image.width = width;
    image.height = height;
    image.rgba.assign(pixels.get(), pixels.get() + std::size_t(width) * std::size_t(height) * 4);
    return image;
}

}  // namespace modeflow::preview
