#include "engine/display/WindowScreen.h"

namespace modeflow::display {
namespace {

vulkan::VulkanContextOptions presentingTo(const Window& window,
                                          vulkan::VulkanContextOptions options) {
    options.instanceExtensions = window.requiredInstanceExtensions();
    options.createSurface = [&window](VkInstance instance) {
        return window.createSurface(instance);
    };
    return options;
}

}  // namespace

WindowScreen::WindowScreen(int width, int height, const std::string& title,
                           vulkan::VulkanContextOptions options)
    : mWindow(width, height, title),
      mContext(presentingTo(mWindow, std::move(options))),
      mPresenter(mContext, mWindow.framebufferSize()) {}

WindowScreen::~WindowScreen() {
    // Not waitIdle(): a destructor must not throw, and there is nothing to do about a failure.
    vkDeviceWaitIdle(mContext.device());
}

VkExtent2D WindowScreen::nextPictureSize() {
    const VkExtent2D wanted = mWindow.framebufferSize();
    if (wanted.width == 0 || wanted.height == 0) return {0, 0};
    const VkExtent2D shown = mPresenter.extent();
    if (wanted.width != shown.width || wanted.height != shown.height) mPresenter.resize(wanted);
    return mPresenter.extent();
}

void WindowScreen::present(const vulkan::DeviceBuffer& pixels) {
    // A swapchain found out of date is recreated at the window's size; the next frame shows.
    mPresenter.present(pixels, mWindow.framebufferSize());
}

}  // namespace modeflow::display
