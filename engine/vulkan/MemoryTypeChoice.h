#pragma once
/// @file MemoryTypeChoice.h
/// Which of a device's memory types a buffer lives in. On a discrete GPU the choice decides
/// speed by orders of magnitude: a host read of device-local memory mapped through the PCIe BAR
/// is uncached (tens of MB/s), while host-cached system memory reads at memcpy speed; and kernels
/// read device-local memory at full bandwidth. Where device and host share memory (lavapipe,
/// integrated GPUs) every mapped type is device-local too.

#include <cstdint>
#include <optional>

#include <vulkan/vulkan.h>

namespace modeflow::vulkan {

enum class MemoryUse {
    /// Kernels only; the host reaches it through staging copies (discrete GPUs).
    DeviceOnly,
    /// Kernels and host both, mapped (no staging: lavapipe, integrated GPUs): device-local first,
    /// then host-cached, since the host reads results back from it directly.
    Shared,
    /// A staging buffer or a small host-read result: host-cached system memory first, so that host
    /// reads are fast, and not the BAR's device-local window (small on GPUs without resizable BAR).
    Staging,
};

/// The memory type among `typeBits` (VkMemoryRequirements::memoryTypeBits) that `use` needs,
/// the preferred one first, then the lowest index; empty when none qualifies.
std::optional<std::uint32_t> chooseMemoryType(const VkPhysicalDeviceMemoryProperties& memory,
                                              std::uint32_t typeBits, MemoryUse use);

}  // namespace modeflow::vulkan
