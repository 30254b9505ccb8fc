#include "engine/vulkan/DeviceBuffer.h"

#include <cstring>
#include <optional>

#include "engine/vulkan/MemoryTypeChoice.h"
#include "engine/vulkan/StagingArea.h"
#include "engine/vulkan/VulkanContext.h"
#include "engine/vulkan/VulkanError.h"

namespace modeflow::vulkan {
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
    const MemoryUse use = placement == Placement::HostVisible ? MemoryUse::Staging
                          : context.usesStaging()             ? MemoryUse::DeviceOnly
                                                              : MemoryUse::Shared;
    const bool mapped = use != MemoryUse::DeviceOnly;
    const auto type =
        chooseMemoryType(context.memoryProperties(), requirements.memoryTypeBits, use);
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
    createTexelViews(bytes);
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
    createTexelViews(bytes);
}

VkBuffer DeviceBuffer::createBuffer(VkDeviceSize bytes) {
    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = bytes;
    const bool texels = bytes >= kFloatBytes && bytes <= mContext->storageBufferLimit();
    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                 VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT |
                 (texels ? VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT : 0);
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    check(vkCreateBuffer(mContext->device(), &info, nullptr, &buffer), "vkCreateBuffer");
    mBuffer = DeviceHandle<VkBuffer>(mContext->device(), buffer, vkDestroyBuffer);
    return buffer;
}

DeviceHandle<VkBufferView> DeviceBuffer::createView(VkFormat format, VkDeviceSize texelBytes,
                                                    VkDeviceSize bytes) const {
    const VkDeviceSize texels = bytes / texelBytes;
    if (texels == 0 || texels > mContext->properties().limits.maxTexelBufferElements ||
        bytes > mContext->storageBufferLimit())
        return {};
    VkBufferViewCreateInfo view{};
    view.sType = VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO;
    view.buffer = mBuffer.get();
    view.format = format;
    view.range = texels * texelBytes;
    VkBufferView handle = VK_NULL_HANDLE;
    check(vkCreateBufferView(mContext->device(), &view, nullptr, &handle), "vkCreateBufferView");
    return DeviceHandle<VkBufferView>(mContext->device(), handle, vkDestroyBufferView);
}

void DeviceBuffer::createTexelViews(VkDeviceSize bytes) {
    // RGBA32UI, RG32UI and R32UI uniform texel buffers are mandatory in Vulkan; shaders
    // reinterpret the bits.
    mTexelView = createView(VK_FORMAT_R32G32B32A32_UINT, kTexelBytes, bytes);
    mWordView = createView(VK_FORMAT_R32G32_UINT, kWordBytes, bytes);
    mFloatView = createView(VK_FORMAT_R32_UINT, kFloatBytes, bytes);
}

void DeviceBuffer::write(const void* source, VkDeviceSize offset, VkDeviceSize bytes) {
    checkRange("upload", offset, bytes);
    if (bytes == 0) return;
    if (mMapped) {
        std::memcpy(static_cast<std::byte*>(mMapped) + offset, source, bytes);
        return;
    }
    mContext->staging().upload(*this, offset, source, bytes);
}

void DeviceBuffer::read(void* destination, VkDeviceSize offset, VkDeviceSize bytes) const {
    checkRange("download", offset, bytes);
    if (bytes == 0) return;
    if (mMapped) {
        std::memcpy(destination, static_cast<const std::byte*>(mMapped) + offset, bytes);
        return;
    }
    mContext->staging().download(*this, offset, destination, bytes);
}

void DeviceBuffer::checkRange(const char* what, VkDeviceSize offset, VkDeviceSize bytes) const {
    if (offset > mBytes || bytes > mBytes - offset)
        throw Error("DeviceBuffer \"" + mName + "\": " + what + " of " + std::to_string(bytes) +
                    " bytes at offset " + std::to_string(offset) + " exceeds its " +
                    std::to_string(mBytes) + " bytes");
}

}  // namespace modeflow::vulkan
