#pragma once
/// @file ObstacleLattices.h
/// The mesh obstacles' level sets on the device, one after the other in one buffer
/// (SolidLevelSet::depth as float32; read through shaders/ObstacleShape.glsl), uploaded when
/// the set of level sets changes. ObstacleCorrection and SmokeDisplacement each keep one.

#include <cstdint>
#include <span>
#include <vector>

#include "engine/simulation/MovingObstacle.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::vulkan {
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class ObstacleLattices {
public:
    explicit ObstacleLattices(const vulkan::VulkanContext& context);

    /// Uploads the obstacles' lattices unless they are those already there; returns where each
    /// obstacle's starts (0 for the other shapes).
    /// @throw modeflow::Error when they hold 2^32 samples or more.
    std::vector<std::uint32_t> update(std::span<const MovingObstacle> obstacles);
    const vulkan::DeviceBuffer& buffer() const { return mBuffer; }

private:
    const vulkan::VulkanContext& mContext;
    vulkan::DeviceBuffer mBuffer;
    std::vector<const SolidLevelSet*> mUploaded;
};

}  // namespace modeflow::device
