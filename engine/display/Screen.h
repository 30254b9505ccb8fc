#pragma once
/// @file Screen.h
/// Where an interactive loop (`modeflow stir`) shows its pictures and gets its input: window
/// events in, finished pictures out, on the Vulkan device that draws them. Two implementations:
/// WindowScreen (a GLFW window and its swapchain) and NullScreen (no window and no display: a
/// size the loop sets, and the last picture kept), so the loop's logic runs in tests without an
/// X server.

#include <vector>

#include <vulkan/vulkan.h>

#include "engine/display/InputEvent.h"

namespace modeflow::vulkan {
class DeviceBuffer;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::display {

class Screen {
public:
    virtual ~Screen() = default;

    /// The device that draws the pictures and presents them; it outlives the screen's users.
    virtual const vulkan::VulkanContext& context() const = 0;

    /// The input since the last call.
    virtual std::vector<InputEvent> poll() = 0;
    /// True once the user asked to close the screen.
    virtual bool closeRequested() const = 0;
    /// Asks for a new size in screen units (a script's resize event, a default size);
    /// nextPictureSize() follows.
    virtual void resize(int width, int height) = 0;

    /// Gets ready for the next picture at the screen's size now and returns that size in pixels:
    /// the size of the buffer present() takes next. 0 × 0 while nothing can be shown (minimized).
    virtual VkExtent2D nextPictureSize() = 0;
    /// The size of the pictures shown now, in pixels (pointer fractions are fractions of it).
    virtual VkExtent2D extent() const = 0;
    /// True when a picture's words store blue in their lowest byte (the display kernels write
    /// the screen's byte order: DisplayTarget::blueFirst).
    virtual bool blueFirst() const = 0;
    /// Shows `pixels`: extent() packed 8-bit words, rows from the top, written by an earlier
    /// submission that the host waited for.
    /// @throw modeflow::Error when the buffer is smaller than the picture or presenting fails.
    virtual void present(const vulkan::DeviceBuffer& pixels) = 0;
};

/// Checks that `pixels` holds a picture of `extent`.
/// @throw modeflow::Error naming the buffer and both sizes when it is smaller.
void requirePictureBytes(const vulkan::DeviceBuffer& pixels, VkExtent2D extent);

}  // namespace modeflow::display
