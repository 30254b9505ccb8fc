#pragma once
/// @file Presenter.h
/// Shows finished pictures in the window: acquires a swapchain image, copies a buffer of packed
/// 8-bit pixels into it and presents it, one frame in flight. The picture is computed by the
/// caller's kernels into a buffer of extent() pixels (DisplayKernels), in an earlier submission.

#include <vector>

#include <vulkan/vulkan.h>

#include "engine/display/Swapchain.h"
#include "engine/vulkan/DeviceHandle.h"

namespace modeflow::vulkan {
class DeviceBuffer;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::display {

class Presenter {
public:
    /// @throw modeflow::Error when the swapchain or a synchronization object cannot be made.
    Presenter(const vulkan::VulkanContext& context, VkExtent2D wanted);

    /// Makes the swapchain `wanted` pixels (after the window's size changed).
    void resize(VkExtent2D wanted);
    /// Copies `pixels` (extent().width · extent().height packed words, rows from the top) to the
    /// next swapchain image and presents it. Returns false when the swapchain turned out of date
    /// (it is then recreated at `wanted`, and nothing was shown).
    /// @throw modeflow::Error when the buffer is smaller than the picture or a call fails.
    bool present(const vulkan::DeviceBuffer& pixels, VkExtent2D wanted);

    VkExtent2D extent() const { return mSwapchain.extent(); }
    bool blueFirst() const { return mSwapchain.blueFirst(); }

private:
    /// One "picture copied" semaphore per swapchain image: presentation may still wait on an
    /// image's semaphore while the next frame is recorded.
    void makeImageSemaphores();

    const vulkan::VulkanContext& mContext;
    Swapchain mSwapchain;
    vulkan::DeviceHandle<VkCommandPool> mPool;  // frees its command buffer with it
    VkCommandBuffer mCommands = VK_NULL_HANDLE;
    vulkan::DeviceHandle<VkSemaphore> mAcquired;
    std::vector<vulkan::DeviceHandle<VkSemaphore>> mCopied;
    vulkan::DeviceHandle<VkFence> mInFlight;
};

}  // namespace modeflow::display
