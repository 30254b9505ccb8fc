#pragma once
/// @file DofFaces.h
/// What the per-DOF kernels (reconstruction, force field, force projection) share: the table of
/// the velocity DOFs' face numbers on the device, their launch size, and buffer size checks.

#include <cstdint>
#include <string>

#include "engine/format/BasisCache.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::vulkan {
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

/// cache.faces as uint32 face numbers (MacGrid numbering), in DOF order.
/// @throw modeflow::Error when there are no DOFs or the grid has 2^32 faces or more.
vulkan::DeviceBuffer uploadDofFaces(const vulkan::VulkanContext& context, const BasisCache& cache);

/// The inverse table: per grid face its DOF, `none` where it has none (a wall, a solid face).
/// @throw modeflow::Error as uploadDofFaces.
vulkan::DeviceBuffer uploadFaceDofs(const vulkan::VulkanContext& context, const BasisCache& cache,
                                    std::uint32_t none);

/// The most workgroups a dispatch of a grid-stride kernel takes: the device's group count
/// limit, and on a CPU device a few per CPU thread.
std::uint32_t groupCap(const vulkan::VulkanContext& context);

/// Workgroups for one invocation per item, at most groupCap (the shaders loop with a grid
/// stride over what is left).
std::uint32_t groupsFor(const vulkan::VulkanContext& context, std::uint64_t items,
                        std::uint32_t workgroupSize);

/// @throw modeflow::Error naming `kernel` and the buffer when it holds fewer than `count` 32-bit
/// values.
void requireWords(const std::string& kernel, const vulkan::DeviceBuffer& buffer,
                  std::uint64_t count);

}  // namespace modeflow::device
