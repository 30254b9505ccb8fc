#pragma once
/// @file SyncObjects.h
/// The small objects every submission needs, made in one call each: a command pool with its one
/// primary command buffer, fences and semaphores, owned by DeviceHandles.

#include <string>

#include <vulkan/vulkan.h>

#include "engine/vulkan/DeviceHandle.h"

namespace modeflow::vulkan {

class VulkanContext;

/// A command pool on the context's queue family and the one primary buffer it frees with it.
struct CommandPool {
    DeviceHandle<VkCommandPool> pool;
    VkCommandBuffer buffer = VK_NULL_HANDLE;
};

/// @throw modeflow::Error naming the call that failed.
CommandPool makeCommandPool(const VulkanContext& context, VkCommandPoolCreateFlags flags);
DeviceHandle<VkFence> makeFence(VkDevice device, bool signaled = false);
DeviceHandle<VkSemaphore> makeSemaphore(VkDevice device);

/// Submits `commands` (ended) on the context's queue, waits for `fence` (unsignaled), then
/// unsignals it again for the next submission.
/// @throw modeflow::Error naming the call that failed, with `what` after it.
void submitAndWait(const VulkanContext& context, VkCommandBuffer commands, VkFence fence,
                   const std::string& what = {});

}  // namespace modeflow::vulkan
