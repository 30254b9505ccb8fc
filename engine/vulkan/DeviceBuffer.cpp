#include "engine/vulkan/DeviceBuffer.h"

#include <optional>

#include "engine/vulkan/VulkanContext.h"
#include "engine/vulkan/VulkanError.h"

namespace modeflow::vulkan {
namespace {

/// A memory type allowed by `typeBits` with HOST_VISIBLE | HOST_COHERENT; device-local ones
/// first (lavapipe, integrated GPUs, resizable BAR), since kernels then read it at full speed.
std::optional<std::uint32_t> hostVisibleType(const VkPhysicalDeviceMemoryProperties& memory,
                                             std::uint32_t typeBits) {
    const VkMemoryPropertyFlags required =
        VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
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

DeviceBuffer::DeviceBuffer(const VulkanContext& context, VkDeviceSize bytes, std::string name)
    : mName(std::move(name)), mBytes(bytes) {
    const VkDeviceSize limit = context.storageBufferLimit();
    if (bytes == 0) throw Error("DeviceBuffer \"" + mName + "\": size 0 (Vulkan buffers cannot be empty)");
    if (bytes > limit)
        throw Error("DeviceBuffer \"" + mName + "\": " + std::to_string(bytes) +
                    " bytes exceed maxStorageBufferRange (" + std::to_string(limit) + " bytes) of " +
                    context.deviceName() + "; split the array over several buffers");
    const VkDevice device = context.device();

    VkBufferCreateInfo info{};
    info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
    info.size = bytes;
    info.usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT |
                 VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
    info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
    VkBuffer buffer = VK_NULL_HANDLE;
    check(vkCreateBuffer(device, &info, nullptr, &buffer), "vkCreateBuffer");
    mBuffer = DeviceHandle<VkBuffer>(device, buffer, vkDestroyBuffer);

    VkMemoryRequirements requirements;
    vkGetBufferMemoryRequirements(device, buffer, &requirements);
    const auto type = hostVisibleType(context.memoryProperties(), requirements.memoryTypeBits);
    if (!type)
        throw Error("DeviceBuffer \"" + mName + "\": " + context.deviceName() +
                    " has no host-visible, host-coherent memory type for storage buffers");
    VkMemoryAllocateInfo allocate{};
    allocate.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    allocate.allocationSize = requirements.size;
    allocate.memoryTypeIndex = *type;
    VkDeviceMemory memory = VK_NULL_HANDLE;
    check(vkAllocateMemory(device, &allocate, nullptr, &memory), "vkAllocateMemory");
    mMemory = DeviceHandle<VkDeviceMemory>(device, memory, vkFreeMemory);
    check(vkBindBufferMemory(device, buffer, memory, 0), "vkBindBufferMemory");
    check(vkMapMemory(device, memory, 0, VK_WHOLE_SIZE, 0, &mMapped), "vkMapMemory");
}

void DeviceBuffer::checkRange(const char* what, VkDeviceSize offset, VkDeviceSize bytes) const {
    if (offset > mBytes || bytes > mBytes - offset)
        throw Error("DeviceBuffer \"" + mName + "\": " + what + " of " + std::to_string(bytes) +
                    " bytes at offset " + std::to_string(offset) + " exceeds its " +
                    std::to_string(mBytes) + " bytes");
}

}  // namespace modeflow::vulkan
