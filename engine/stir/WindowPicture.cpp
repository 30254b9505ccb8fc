/// @file WindowPicture.cpp

#include "engine/stir/WindowPicture.h"

#include <vector>

#include "engine/core/Error.h"
#include "engine/preview/PngWriter.h"
#include "engine/stir/StirKeys.h"

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

WindowPicture::WindowPicture(const vulkan::VulkanContext& context)
    : mContext(context), mKernels(context), mOverlay(context), mSequence(context) {}

display::DisplayTarget WindowPicture::begin(const PictureExtras& extras, VkExtent2D size,
                                            const display::Viewport& viewport, bool blueFirst) {
    if (!mPixels || size.width != mExtent.width || size.height != mExtent.height) {
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
