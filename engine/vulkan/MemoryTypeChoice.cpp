#include "engine/vulkan/MemoryTypeChoice.h"

namespace modeflow::vulkan {
namespace {

constexpr VkMemoryPropertyFlags kDeviceLocal = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
constexpr VkMemoryPropertyFlags kMapped =
    VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
constexpr VkMemoryPropertyFlags kCached = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;

/// Higher is better; the first preference outweighs the second.
int preference(VkMemoryPropertyFlags flags, MemoryUse use) {
    const bool local = flags & kDeviceLocal;
    const bool cached = flags & kCached;
    const bool visible = flags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
    switch (use) {
        case MemoryUse::DeviceOnly:
            return visible ? 0 : 1;  // leave the BAR window to what the host maps
        case MemoryUse::Shared:
            return 2 * local + cached;
        case MemoryUse::Staging:
            return 2 * cached + !local;
    }
    return 0;
}

VkMemoryPropertyFlags requiredMemoryProperties(MemoryUse use) {
    return use == MemoryUse::DeviceOnly ? kDeviceLocal : kMapped;
}

}  // namespace

std::optional<std::uint32_t> chooseMemoryType(const VkPhysicalDeviceMemoryProperties& memory,
                                              std::uint32_t typeBits, MemoryUse use) {
    const VkMemoryPropertyFlags required = requiredMemoryProperties(use);
    std::optional<std::uint32_t> best;
    int bestPreference = -1;
    for (std::uint32_t t = 0; t < memory.memoryTypeCount && t < 32; ++t) {
        const VkMemoryPropertyFlags flags = memory.memoryTypes[t].propertyFlags;
        if (!(typeBits & (1u << t)) || (flags & required) != required) continue;
        if (const int p = preference(flags, use); p > bestPreference) {
            best = t;
            bestPreference = p;
        }
    }
    return best;
}

}  // namespace modeflow::vulkan
