#include "engine/vulkan/SyncObjects.h"

#include "engine/vulkan/VulkanContext.h"
#include "engine/vulkan/VulkanError.h"

namespace modeflow::vulkan {

CommandPool makeCommandPool(const VulkanContext& context, VkCommandPoolCreateFlags flags) {
    const VkDevice device = context.device();
    VkCommandPoolCreateInfo poolInfo{};
    poolInfo.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    poolInfo.flags = flags;
    poolInfo.queueFamilyIndex = context.queueFamily();
    VkCommandPool pool = VK_NULL_HANDLE;
    check(vkCreateCommandPool(device, &poolInfo, nullptr, &pool), "vkCreateCommandPool");
    CommandPool out{DeviceHandle<VkCommandPool>(device, pool, vkDestroyCommandPool)};
    VkCommandBufferAllocateInfo allocate{};
    allocate.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    allocate.commandPool = pool;
    allocate.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocate.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(device, &allocate, &out.buffer), "vkAllocateCommandBuffers");
    return out;
}

DeviceHandle<VkFence> makeFence(VkDevice device, bool signaled) {
    VkFenceCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    info.flags = signaled ? VK_FENCE_CREATE_SIGNALED_BIT : 0;
    VkFence fence = VK_NULL_HANDLE;
    check(vkCreateFence(device, &info, nullptr, &fence), "vkCreateFence");
    return {device, fence, vkDestroyFence};
}

DeviceHandle<VkSemaphore> makeSemaphore(VkDevice device) {
    VkSemaphoreCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO;
    VkSemaphore semaphore = VK_NULL_HANDLE;
    check(vkCreateSemaphore(device, &info, nullptr, &semaphore), "vkCreateSemaphore");
    return {device, semaphore, vkDestroySemaphore};
}

void submitAndWait(const VulkanContext& context, VkCommandBuffer commands, VkFence fence,
                   const std::string& what) {
    const std::string suffix = what.empty() ? "" : " (" + what + ")";
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    check(vkQueueSubmit(context.queue(), 1, &submit, fence), ("vkQueueSubmit" + suffix).c_str());
    check(vkWaitForFences(context.device(), 1, &fence, VK_TRUE, UINT64_MAX),
          ("vkWaitForFences" + suffix).c_str());
    check(vkResetFences(context.device(), 1, &fence), ("vkResetFences" + suffix).c_str());
}

}  // namespace modeflow::vulkan
