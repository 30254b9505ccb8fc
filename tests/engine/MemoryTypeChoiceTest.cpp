// Memory types chosen for each use on the type tables real devices report: a discrete GPU's
// readbacks must land in host-cached system memory, never in the uncached BAR window.

#include <gtest/gtest.h>

#include <initializer_list>

#include "engine/vulkan/MemoryTypeChoice.h"

namespace modeflow::vulkan {
namespace {

constexpr VkMemoryPropertyFlags kLocal = VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
constexpr VkMemoryPropertyFlags kVisible =
    VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
constexpr VkMemoryPropertyFlags kCached = VK_MEMORY_PROPERTY_HOST_CACHED_BIT;
constexpr std::uint32_t kAll = ~0u;

VkPhysicalDeviceMemoryProperties types(std::initializer_list<VkMemoryPropertyFlags> flags) {
    VkPhysicalDeviceMemoryProperties memory{};
    for (VkMemoryPropertyFlags f : flags)
        memory.memoryTypes[memory.memoryTypeCount++].propertyFlags = f;
    return memory;
}

// A discrete GPU's usual table (NVIDIA's drivers list this layout): plain VRAM, system memory
// in two kinds, and VRAM mapped through the BAR.
TEST(MemoryTypeChoice, DiscreteGpuStagesThroughCachedSystemMemory) {
    const auto nvidia = types({0, kLocal, kVisible, kVisible | kCached, kLocal | kVisible});
    EXPECT_EQ(chooseMemoryType(nvidia, kAll, MemoryUse::DeviceOnly), 1u);
    EXPECT_EQ(chooseMemoryType(nvidia, kAll, MemoryUse::Staging), 3u);
    EXPECT_EQ(chooseMemoryType(nvidia, kAll, MemoryUse::Shared), 4u);
    // Without a cached type, staging takes system memory rather than the BAR window.
    EXPECT_EQ(chooseMemoryType(nvidia, kAll & ~(1u << 3), MemoryUse::Staging), 2u);
    // Device-only buffers take VRAM outside the BAR even when listed after it.
    const auto barFirst = types({kLocal | kVisible, kLocal});
    EXPECT_EQ(chooseMemoryType(barFirst, kAll, MemoryUse::DeviceOnly), 1u);
}

TEST(MemoryTypeChoice, SharedMemoryDevicesMapTheirDeviceLocalCachedType) {
    const auto lavapipe = types({kLocal | kVisible | kCached});
    for (MemoryUse use : {MemoryUse::DeviceOnly, MemoryUse::Shared, MemoryUse::Staging})
        EXPECT_EQ(chooseMemoryType(lavapipe, kAll, use), 0u);
    const auto integrated = types({kLocal, kLocal | kVisible, kLocal | kVisible | kCached});
    EXPECT_EQ(chooseMemoryType(integrated, kAll, MemoryUse::Shared), 2u);
    EXPECT_EQ(chooseMemoryType(integrated, kAll, MemoryUse::Staging), 2u);
}

TEST(MemoryTypeChoice, OnlyAllowedTypesWithTheRequiredPropertiesQualify) {
    const auto nvidia = types({0, kLocal, kVisible, kVisible | kCached, kLocal | kVisible});
    EXPECT_FALSE(chooseMemoryType(nvidia, 1u << 0 | 1u << 1, MemoryUse::Staging));
    EXPECT_FALSE(chooseMemoryType(nvidia, 1u << 2 | 1u << 3, MemoryUse::DeviceOnly));
    EXPECT_EQ(chooseMemoryType(nvidia, 1u << 4, MemoryUse::DeviceOnly), 4u);
    EXPECT_FALSE(chooseMemoryType(types({}), kAll, MemoryUse::Shared));
}

}  // namespace
}  // namespace modeflow::vulkan
