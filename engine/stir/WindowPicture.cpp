/// @file WindowPicture.cpp

#include "engine/stir/WindowPicture.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/Error.h"
#include "engine/preview/PngWriter.h"
#include "engine/stir/StirKeys.h"
#include "engine/vulkan/VulkanContext.h"

namespace modeflow::stir {
namespace {

std::vector<display::TextBlock> overlayText(const PictureExtras& extras, int scale) {
    std::vector<display::TextBlock> blocks;
    if (!extras.statistics.empty()) blocks.push_back({8, 8, extras.statistics, false});
    if (extras.help) {
        // Bottom right, clear of the statistics: actions flush right, keys in a column before.
        const HelpColumns help = helpColumns();
        const int margin = 8 * scale;
        blocks.push_back({-margin, -margin, help.actions, true});
        blocks.push_back({-(margin + display::textWidth(help.actions, scale) + 6 * scale), -margin,
                          help.keys, true});
    }
    return blocks;
}

}  // namespace

void requirePictureFits(const vulkan::VulkanContext& context, int width, int height,
                        const std::string& what) {
    constexpr double kBytesPerPixel = 4.0;  // packed RGBA
    const VkDeviceSize limit = context.storageBufferLimit();
    const double bytes = kBytesPerPixel * double(width) * double(height);
    if (bytes <= double(limit)) return;
    // The same shape shrunk until it fits.
    const double shrink = std::sqrt(double(limit) / bytes);
    const int w = std::max(1, int(std::floor(width * shrink))),
              h = std::max(1, int(std::floor(height * shrink)));
    throw Error(what + ": a picture of " + std::to_string(width) + " × " + std::to_string(height) +
                " pixels takes " + std::to_string(std::uint64_t(bytes)) +
                " bytes, more than the largest storage buffer of this device (" +
                std::to_string(limit) + " bytes); at this shape it takes at most " +
                std::to_string(w) + " × " + std::to_string(h));
}

WindowPicture::WindowPicture(const vulkan::VulkanContext& context)
    : mContext(context), mKernels(context), mOverlay(context), mSequence(context) {}

display::DisplayTarget WindowPicture::begin(const PictureExtras& extras, VkExtent2D size,
                                            const display::Viewport& viewport, bool blueFirst) {
    if (!mPixels || size.width != mExtent.width || size.height != mExtent.height) {
        requirePictureFits(mContext, int(size.width), int(size.height), "the window");
        mPixels = std::make_unique<vulkan::DeviceBuffer>(
            mContext, VkDeviceSize(size.width) * size.height * 4, "window picture");
        mExtent = size;
    }
    mBlueFirst = blueFirst;
    const int width = int(size.width), height = int(size.height);
    const int scale = height >= 600 ? 2 : 1;
    mOverlay.update(width, height, overlayText(extras, scale), scale);
    return {width, height, viewport, blueFirst};
}

preview::Image WindowPicture::picture() const {
    const int width = int(mExtent.width), height = int(mExtent.height);
    std::vector<std::uint32_t> words(std::size_t(width) * std::size_t(height));
    mPixels->download<std::uint32_t>(words);
    return preview::unpackImage(words, width, height, mBlueFirst);
}

void WindowPicture::saveScreenshot(const std::filesystem::path& file) const {
    if (!mPixels) throw Error("no frame was drawn, so there is no screenshot for " + file.string());
    preview::writePng(file, picture());
}

}  // namespace modeflow::stir
