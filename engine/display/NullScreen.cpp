#include "engine/display/NullScreen.h"

#include <algorithm>
#include <cstdint>
#include <vector>

#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::display {

NullScreen::NullScreen(const vulkan::VulkanContext& context, int width, int height, bool blueFirst,
                       bool readsBack)
    : mContext(context), mBlueFirst(blueFirst), mReadsBack(readsBack) {
    resize(width, height);
}

void NullScreen::resize(int width, int height) {
    mExtent = {std::uint32_t(std::max(width, 0)), std::uint32_t(std::max(height, 0))};
}

VkExtent2D NullScreen::nextPictureSize() {
    if (mMinimizedFrames > 0) {
        --mMinimizedFrames;
        return {0, 0};
    }
    return mExtent;
}

void NullScreen::present(const vulkan::DeviceBuffer& pixels) {
    requirePictureBytes(pixels, mExtent);
    ++mPresented;
    if (!mReadsBack) return;
    std::vector<std::uint32_t> words(std::size_t(mExtent.width) * mExtent.height);
    pixels.download<std::uint32_t>(words);
    mLast = preview::unpackImage(words, int(mExtent.width), int(mExtent.height), mBlueFirst);
}

}  // namespace modeflow::display
