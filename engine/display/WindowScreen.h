#pragma once
/// @file WindowScreen.h
/// The Screen of a real window: a GLFW window (Window.h), a Vulkan context on a device that
/// presents to it, and the swapchain Presenter, declared in that order (the window's surface
/// exists before the context that owns it, and the swapchain goes before the context).

#include <string>

#include "engine/display/Presenter.h"
#include "engine/display/Screen.h"
#include "engine/display/Window.h"
#include "engine/vulkan/VulkanContext.h"

namespace modeflow::display {

class WindowScreen final : public Screen {
public:
    /// Opens a width × height window (screen units) titled `title`, and a context on a device
    /// that can present to it (`options` names the device, the validation layer, ...).
    /// @throw modeflow::Error as Window, VulkanContext and Presenter do (no display, no device
    ///        that presents, ...).
    WindowScreen(int width, int height, const std::string& title,
                 vulkan::VulkanContextOptions options);
    /// Waits for the last presentation, which uses the Presenter's semaphores.
    ~WindowScreen() override;

    const vulkan::VulkanContext& context() const override { return mContext; }
    std::vector<InputEvent> poll() override { return mWindow.poll(); }
    bool closeRequested() const override { return mWindow.closeRequested(); }
    void resize(int width, int height) override { mWindow.resize(width, height); }
    /// Recreates the swapchain when the window's size changed.
    VkExtent2D nextPictureSize() override;
    VkExtent2D extent() const override { return mPresenter.extent(); }
    bool blueFirst() const override { return mPresenter.blueFirst(); }
    void present(const vulkan::DeviceBuffer& pixels) override;

private:
    Window mWindow;
    vulkan::VulkanContext mContext;
    Presenter mPresenter;
};

}  // namespace modeflow::display
