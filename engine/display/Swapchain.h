#pragma once
/// @file Swapchain.h
/// The window surface's swapchain: images the Presenter copies finished pictures into. Its
/// images take transfer writes (pictures arrive by vkCmdCopyBufferToImage from a compute
/// kernel's buffer, which every device supports, rather than as storage images, which many
/// swapchain formats are not). 8-bit RGBA or BGRA formats only: the display kernels write their
/// bytes in the format's order (blueFirst()). FIFO presentation (always available, no tearing).

#include <vector>

#include <vulkan/vulkan.h>

namespace modeflow::vulkan {
class VulkanContext;
}

namespace modeflow::display {

class Swapchain {
public:
    /// A swapchain for the context's surface, `wanted` pixels where the surface lets the
    /// application choose.
    /// @throw modeflow::Error when the surface offers no 8-bit RGBA/BGRA format with transfer
    ///        writes, or a call fails.
    Swapchain(const vulkan::VulkanContext& context, VkExtent2D wanted);
    ~Swapchain();
    Swapchain(const Swapchain&) = delete;
    Swapchain& operator=(const Swapchain&) = delete;

    /// Replaces the swapchain (after a resize, or when presentation reports it out of date).
    /// Waits for the device to be idle first.
    void recreate(VkExtent2D wanted);

    VkSwapchainKHR handle() const { return mSwapchain; }
    VkExtent2D extent() const { return mExtent; }
    VkFormat format() const { return mFormat; }
    /// True when the format stores blue in the lowest byte of a pixel.
    bool blueFirst() const { return mBlueFirst; }
    const std::vector<VkImage>& images() const { return mImages; }

private:
    void create(VkExtent2D wanted, VkSwapchainKHR old);

    const vulkan::VulkanContext& mContext;
    VkSwapchainKHR mSwapchain = VK_NULL_HANDLE;
    VkExtent2D mExtent{};
    VkFormat mFormat = VK_FORMAT_UNDEFINED;
    bool mBlueFirst = false;
    std::vector<VkImage> mImages;
};

}  // namespace modeflow::display
