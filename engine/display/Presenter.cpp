#include "engine/display/Presenter.h"

#include "engine/display/Screen.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "engine/vulkan/SyncObjects.h"
#include "engine/vulkan/VulkanContext.h"
#include "engine/vulkan/VulkanError.h"

namespace modeflow::display {
namespace {

void transition(VkCommandBuffer commands, VkImage image, VkImageLayout from, VkImageLayout to,
                VkAccessFlags srcAccess, VkAccessFlags dstAccess, VkPipelineStageFlags srcStage,
                VkPipelineStageFlags dstStage) {
    VkImageMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
    barrier.srcAccessMask = srcAccess;
    barrier.dstAccessMask = dstAccess;
    barrier.oldLayout = from;
    barrier.newLayout = to;
    barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
    barrier.image = image;
    barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdPipelineBarrier(commands, srcStage, dstStage, 0, 0, nullptr, 0, nullptr, 1, &barrier);
}

bool isOutOfDate(VkResult result) {
    return result == VK_ERROR_OUT_OF_DATE_KHR || result == VK_SUBOPTIMAL_KHR;
}

}  // namespace

Presenter::Presenter(const vulkan::VulkanContext& context, VkExtent2D wanted)
    : mContext(context), mSwapchain(context, wanted) {
    const VkDevice device = context.device();
    vulkan::CommandPool commands =
        vulkan::makeCommandPool(context, VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT);
    mPool = std::move(commands.pool);
    mCommands = commands.buffer;
    mAcquired = vulkan::makeSemaphore(device);
    makeImageSemaphores();
    mInFlight = vulkan::makeFence(device, true);
}

void Presenter::makeImageSemaphores() {
    mCopied.clear();
    for (std::size_t i = 0; i < mSwapchain.images().size(); ++i)
        mCopied.push_back(vulkan::makeSemaphore(mContext.device()));
}

void Presenter::resize(VkExtent2D wanted) {
    mSwapchain.recreate(wanted);
    makeImageSemaphores();
}

bool Presenter::present(const vulkan::DeviceBuffer& pixels, VkExtent2D wanted) {
    const VkExtent2D size = mSwapchain.extent();
    requirePictureBytes(pixels, size);
    const VkDevice device = mContext.device();
    const VkFence fence = mInFlight.get();
    vulkan::check(vkWaitForFences(device, 1, &fence, VK_TRUE, UINT64_MAX), "vkWaitForFences");

    std::uint32_t index = 0;
    const VkResult acquired = vkAcquireNextImageKHR(device, mSwapchain.handle(), UINT64_MAX,
                                                    mAcquired.get(), VK_NULL_HANDLE, &index);
    if (acquired == VK_ERROR_OUT_OF_DATE_KHR) {
        resize(wanted);
        return false;
    }
    if (acquired != VK_SUBOPTIMAL_KHR) vulkan::check(acquired, "vkAcquireNextImageKHR");
    vulkan::check(vkResetFences(device, 1, &fence), "vkResetFences");

    const VkImage image = mSwapchain.images()[index];
    vulkan::check(vkResetCommandBuffer(mCommands, 0), "vkResetCommandBuffer");
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    vulkan::check(vkBeginCommandBuffer(mCommands, &begin), "vkBeginCommandBuffer");
    // The picture's kernels ran in an earlier submission that the host waited on; their writes
    // become visible to the copy through this barrier's source scope.
    transition(mCommands, image, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 0,
               VK_ACCESS_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
               VK_PIPELINE_STAGE_TRANSFER_BIT);
    VkMemoryBarrier computeWrites{};
    computeWrites.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    computeWrites.srcAccessMask = VK_ACCESS_SHADER_WRITE_BIT;
    computeWrites.dstAccessMask = VK_ACCESS_TRANSFER_READ_BIT;
    vkCmdPipelineBarrier(mCommands, VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT,
                         VK_PIPELINE_STAGE_TRANSFER_BIT, 0, 1, &computeWrites, 0, nullptr, 0,
                         nullptr);
    VkBufferImageCopy region{};
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {size.width, size.height, 1};
    vkCmdCopyBufferToImage(mCommands, pixels.handle(), image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                           1, &region);
    transition(mCommands, image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
               VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_ACCESS_TRANSFER_WRITE_BIT, 0,
               VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_BOTTOM_OF_PIPE_BIT);
    vulkan::check(vkEndCommandBuffer(mCommands), "vkEndCommandBuffer");

    const VkSemaphore acquiredSemaphore = mAcquired.get(), copied = mCopied[index].get();
    const VkPipelineStageFlags waitStage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.waitSemaphoreCount = 1;
    submit.pWaitSemaphores = &acquiredSemaphore;
    submit.pWaitDstStageMask = &waitStage;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &mCommands;
    submit.signalSemaphoreCount = 1;
    submit.pSignalSemaphores = &copied;
    vulkan::check(vkQueueSubmit(mContext.queue(), 1, &submit, fence), "vkQueueSubmit");

    const VkSwapchainKHR swapchain = mSwapchain.handle();
    VkPresentInfoKHR presentInfo{};
    presentInfo.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR;
    presentInfo.waitSemaphoreCount = 1;
    presentInfo.pWaitSemaphores = &copied;
    presentInfo.swapchainCount = 1;
    presentInfo.pSwapchains = &swapchain;
    presentInfo.pImageIndices = &index;
    const VkResult presented = vkQueuePresentKHR(mContext.queue(), &presentInfo);
    if (isOutOfDate(presented) || isOutOfDate(acquired)) {
        resize(wanted);
        return !isOutOfDate(presented);
    }
    vulkan::check(presented, "vkQueuePresentKHR");
    return true;
}

}  // namespace modeflow::display
