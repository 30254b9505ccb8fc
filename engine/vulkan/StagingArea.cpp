#include "engine/vulkan/StagingArea.h"

#include <algorithm>
#include <cstddef>

#include "engine/vulkan/DeviceBuffer.h"
#include "engine/vulkan/VulkanContext.h"
#include "engine/vulkan/VulkanError.h"

namespace modeflow::vulkan {

StagingArea::StagingArea(const VulkanContext& context)
    : mContext(context),
      mPool(makeCommandPool(context, VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT)),
      mFence(makeFence(context.device())) {}

StagingArea::~StagingArea() = default;

VkDeviceSize StagingArea::chunkBytes() const {
    return std::min(kChunkBytes, mContext.storageBufferLimit());
}

DeviceBuffer& StagingArea::buffer(VkDeviceSize bytes) {
    if (!mBuffer || mBuffer->bytes() < bytes) {
        // Grow by doubling so that a run's rising sizes reallocate a few times only.
        const VkDeviceSize size =
            std::min(chunkBytes(), std::max(bytes, mBuffer ? 2 * mBuffer->bytes() : bytes));
        mBuffer.reset();  // free before allocating: the old one is never needed again
        mBuffer = std::make_unique<DeviceBuffer>(mContext, size, "staging",
                                                 DeviceBuffer::Placement::HostVisible);
    }
    return *mBuffer;
}

void StagingArea::upload(const DeviceBuffer& target, VkDeviceSize offset, const void* source,
                         VkDeviceSize bytes) {
    const auto* from = static_cast<const std::byte*>(source);
    for (VkDeviceSize done = 0; done < bytes;) {
        const VkDeviceSize piece = std::min(bytes - done, chunkBytes());
        buffer(piece).upload(std::span(from + done, piece));
        copy(target, offset + done, piece, true);
        done += piece;
    }
}

void StagingArea::download(const DeviceBuffer& source, VkDeviceSize offset, void* destination,
                           VkDeviceSize bytes) {
    auto* to = static_cast<std::byte*>(destination);
    for (VkDeviceSize done = 0; done < bytes;) {
        const VkDeviceSize piece = std::min(bytes - done, chunkBytes());
        DeviceBuffer& staging = buffer(piece);
        copy(source, offset + done, piece, false);
        staging.download(std::span(to + done, piece));
        done += piece;
    }
}

void StagingArea::copy(const DeviceBuffer& device, VkDeviceSize offset, VkDeviceSize bytes,
                       bool toDevice) {
    const VkCommandBuffer commands = mPool.buffer;
    check(vkResetCommandBuffer(commands, 0), "vkResetCommandBuffer (staging copy)");
    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(commands, &begin), "vkBeginCommandBuffer");
    const VkBufferCopy region{toDevice ? 0 : offset, toDevice ? offset : 0, bytes};
    vkCmdCopyBuffer(commands, toDevice ? mBuffer->handle() : device.handle(),
                    toDevice ? device.handle() : mBuffer->handle(), 1, &region);
    // The copy's writes must reach the kernels (upload) or the host (download) that come next.
    VkMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask =
        toDevice ? VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT : VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(
        commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
        toDevice ? VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT : VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
        &barrier, 0, nullptr, 0, nullptr);
    check(vkEndCommandBuffer(commands), "vkEndCommandBuffer");
    submitAndWait(mContext, commands, mFence.get(), "staging copy");
}

}  // namespace modeflow::vulkan
