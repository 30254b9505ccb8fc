#include "engine/vulkan/DeviceBuffer.h"

#include <cstring>
#include <optional>

#include "engine/vulkan/SyncObjects.h"
#include "engine/vulkan/VulkanContext.h"
#include "engine/vulkan/VulkanError.h"

namespace modeflow::vulkan {
namespace {

/// A memory type allowed by `typeBits` with all of `required`, preferring device-local ones
/// (lavapipe, integrated GPUs and resizable BAR put host-visible memory there too).
std::optional<std::uint32_t> memoryType(const VkPhysicalDeviceMemoryProperties& memory,
                                        std::uint32_t typeBits, VkMemoryPropertyFlags required) {
    std::optional<std::uint32_t> found;
    for (std::uint32_t t = 0; t < memory.memoryTypeCount; ++t) {
        const VkMemoryPropertyFlags flags = memory.memoryTypes[t].propertyFlags;
        if (!(typeBits & (1u << t)) || (flags & required) != required) continue;
        if (flags & VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT) return t;
        if (!found) found = t;
    }
    return found;
}

}  // namespace

DeviceBuffer::DeviceBuffer(const VulkanContext& context, VkDeviceSize bytes, std::string name,
                           Placement placement)
    : mContext(&context), mName(std::move(name)), mBytes(bytes) {
    const VkDeviceSize limit = context.storageBufferLimit();
    if (bytes == 0)
        throw Error("DeviceBuffer \"" + mName + "\": size 0 (Vulkan buffers cannot be empty)");
    if (bytes > limit)
        throw Error("DeviceBuffer \"" + mName + "\": " + std::to_string(bytes) +
                    " bytes exceed maxStorageBufferRange (" + std::to_string(limit) +
                    " bytes) of " + context.deviceName() +
                    "; split the array over several buffers");
    const VkDevice device = context.device();
    const VkBuffer buffer = createBuffer(bytes);

    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device, buffer, &requirements);
    const bool mapped = placement == Placement::HostVisible || !context.usesStaging();
    const VkMemoryPropertyFlags required =
        mapped ? VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT
               : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    const auto type = memoryType(context.memoryProperties(), requirements.memoryTypeBits, required);
    if (!type)
        throw Error("DeviceBuffer \"" + mName + "\": " + context.deviceName() + " has no " +
                    (mapped ? "host-visible, host-coherent" : "device-local") +
                    " memory type for storage buffers");
    VkMemoryAllocateInfo allocate{};
    allocate.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    allocate.allocationSize = requirements.size;
    allocate.memoryTypeIndex = *type;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    check(vkAllocateMemory(device, &allocate, nullptr, &memory), "vkAllocateMemory");
    mMemory = DeviceHandle<VkDeviceMemory>(device, memory, vkFreeMemory);
    mMemoryHandle = memory;
    check(vkBindBufferMemory(device, buffer, memory, 0), "vkBindBufferMemory");
    if (mapped) check(vkMapMemory(device, memory, 0, VK_WHOLE_SIZE, 0, &mMapped), "vkMapMemory");
    createTexelView(bytes);
}

DeviceBuffer::DeviceBuffer(const DeviceBuffer& whole, VkDeviceSize offset, VkDeviceSize bytes,
                           std::string name)
    : mContext(whole.mContext), mName(std::move(name)), mBytes(bytes) {
    if (bytes == 0 || offset > whole.mBytes || bytes > whole.mBytes - offset)
        throw Error("DeviceBuffer \"" + mName + "\": bytes " + std::to_string(offset) + " to " +
                    std::to_string(offset + bytes) + " are not inside \"" + whole.mName + "\" (" +
                    std::to_string(whole.mBytes) + " bytes)");
    if (offset % kViewAlignment != 0)
        throw Error("DeviceBuffer \"" + mName + "\": a view must start at a multiple of " +
                    std::to_string(kViewAlignment) + " bytes, not " + std::to_string(offset));
    const VkBuffer buffer = createBuffer(bytes);
    mMemoryHandle = whole.mMemoryHandle;
    check(vkBindBufferMemory(mContext->device(), buffer, mMemoryHandle, offset),
          "vkBindBufferMemory (view)");
    if (whole.mMapped) mMapped = static_cast<std::byte*>(whole.mMapped) + offset;
    createTexelView(bytes);
}

VkBuffer DeviceBuffer::createBuffer(VkDeviceSize bytes) {
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = bytes;
    const bool texels = bytes >= kTexelBytes && bytes <= mContext->texelBufferLimit();
    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                 VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                 (texels ? VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT : 0);
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    check(vkCreateBuffer(mContext->device(), &info, nullptr, &buffer), "vkCreateBuffer");
    mBuffer = DeviceHandle<VkBuffer>(mContext->device(), buffer, vkDestroyBuffer);
    return buffer;
}

void DeviceBuffer::createTexelView(VkDeviceSize bytes) {
    if (bytes < kTexelBytes || bytes > mContext->texelBufferLimit()) return;
    // RGBA32UI texel buffers are mandatory in Vulkan; shaders reinterpret the bits.
    VkBufferViewCreateInfo view{};
    view.sType = VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO;
    view.buffer = mBuffer.get();
    view.format = VK_FORMAT_R32G32B32A32_UINT;
    view.range = bytes / kTexelBytes * kTexelBytes;
    VkBufferView texelView = VK_NULL_HANDLE;
    check(vkCreateBufferView(mContext->device(), &view, nullptr, &texelView), "vkCreateBufferView");
    mTexelView = DeviceHandle<VkBufferView>(mContext->device(), texelView, vkDestroyBufferView);
}

void DeviceBuffer::write(const void* source, VkDeviceSize offset, VkDeviceSize bytes) {
    checkRange("upload", offset, bytes);
    if (bytes == 0) return;
    if (mMapped) {
        std::memcpy(static_cast<std::byte*>(mMapped) + offset, source, bytes);
        return;
    }
    DeviceBuffer staging(*mContext, bytes, mName + " (staging)", Placement::HostVisible);
    std::memcpy(staging.mMapped, source, bytes);
    copyWithStaging(staging, offset, bytes, true);
}

void DeviceBuffer::read(void* destination, VkDeviceSize offset, VkDeviceSize bytes) const {
    checkRange("download", offset, bytes);
    if (bytes == 0) return;
    if (mMapped) {
        std::memcpy(destination, static_cast<const std::byte*>(mMapped) + offset, bytes);
        return;
    }
    DeviceBuffer staging(*mContext, bytes, mName + " (staging)", Placement::HostVisible);
    copyWithStaging(staging, offset, bytes, false);
    std::memcpy(destination, staging.mMapped, bytes);
}

void DeviceBuffer::copyWithStaging(const DeviceBuffer& staging, VkDeviceSize offset,
                                   VkDeviceSize bytes, bool toThis) const {
    const VkDevice device = mContext->device();
    const CommandPool pool = makeCommandPool(*mContext, VK_COMMAND_POOL_CREATE_TRANSIENT_BIT);
    const VkCommandBuffer commands = pool.buffer;
    const DeviceHandle<VkFence> fence = makeFence(device);

    VkCommandBufferBeginInfo begin{};
    begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
    begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
    check(vkBeginCommandBuffer(commands, &begin), "vkBeginCommandBuffer");
    const VkBufferCopy region{toThis ? 0 : offset, toThis ? offset : 0, bytes};
    vkCmdCopyBuffer(commands, toThis ? staging.handle() : handle(),
                    toThis ? handle() : staging.handle(), 1, &region);
    // The copy's writes must reach the kernels (upload) or the host (download) that come next.
    VkMemoryBarrier barrier{};
    barrier.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
    barrier.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
    barrier.dstAccessMask =
        toThis ? VK_ACCESS_SHADER_READ_BIT | VK_ACCESS_SHADER_WRITE_BIT : VK_ACCESS_HOST_READ_BIT;
    vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT,
                         toThis ? VK_PIPELINE_STAGE_COMPUTE_SHADER_BIT : VK_PIPELINE_STAGE_HOST_BIT,
                         0, 1, &barrier, 0, nullptr, 0, nullptr);
    check(vkEndCommandBuffer(commands), "vkEndCommandBuffer");
    VkSubmitInfo submit{};
    submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
    submit.commandBufferCount = 1;
    submit.pCommandBuffers = &commands;
    const VkFence rawFence = fence.get();
    check(vkQueueSubmit(mContext->queue(), 1, &submit, rawFence), "vkQueueSubmit (staging copy)");
    check(vkWaitForFences(device, 1, &rawFence, VK_TRUE, UINT64_MAX),
          "vkWaitForFences (staging copy)");
}

void DeviceBuffer::checkRange(const char* what, VkDeviceSize offset, VkDeviceSize bytes) const {
    if (offset > mBytes || bytes > mBytes - offset)
        throw Error("DeviceBuffer \"" + mName + "\": " + what + " of " + std::to_string(bytes) +
                    " bytes at offset " + std::to_string(offset) + " exceeds its " +
                    std::to_string(mBytes) + " bytes");
}

}  // namespace modeflow::vulkan
