#include "engine/preview/PngWriter.h"

#include <string>
#include <vector>

#include "engine/core/AtomicFile.h"
#include "engine/core/Error.h"

// The one translation unit with stb_image_write's definitions; static, so they cannot clash with
// another copy of stb linked into the same program.
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#include <stb/stb_image_write.h>
#pragma GCC diagnostic pop

namespace modeflow::preview {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& file) {
    return "\"" + file.string() + "\"";
}

/// The PNG file's bytes, encoded in memory so that file errors and encoder errors stay apart.
std::vector<unsigned char> encodePng(const Image& image) {
    std::vector<unsigned char> bytes;
    const auto append = [](void* context, void* data, int size) {
        auto* out = static_cast<std::vector<unsigned char>*>(context);
        const auto* begin = static_cast<const unsigned char*>(data);
        out->insert(out->end(), begin, begin + size);
    };
    if (stbi_write_png_to_func(append, &bytes, image.width, image.height, 4, image.rgba.data(),
                               image.width * 4) == 0)
        bytes.clear();
    return bytes;
}

}  // namespace

void writePng(const fs::path& file, const Image& image) {
    const auto fail = [&](const std::string& why) {
        return Error("cannot write PNG " + quoted(file) + ": " + why);
    };
    if (image.width <= 0 || image.height <= 0)
        throw fail("the image is empty (" + std::to_string(image.width) + " × " +
                   std::to_string(image.height) + " pixels)");
    if (image.rgba.size() != std::size_t(image.width) * std::size_t(image.height) * 4)
        throw fail("the image holds " + std::to_string(image.rgba.size()) + " bytes, " +
                   std::to_string(image.width) + " × " + std::to_string(image.height) +
                   " RGBA pixels need " +
                   std::to_string(std::size_t(image.width) * std::size_t(image.height) * 4));
    const std::vector<unsigned char> png = encodePng(image);
    if (png.empty()) throw fail("the PNG encoder failed (out of memory?)");

    writeFileAtomically(
        file, std::string_view(reinterpret_cast<const char*>(png.data()), png.size()), "PNG");
}

}  // namespace modeflow::preview
