#pragma once
/// @file ObstacleLattices.h
/// The mesh obstacles' level sets on the device, one after the other in one buffer
/// (SolidLevelSet::depth, then a deforming file's velocity, as float32; read through
/// shaders/ObstacleShape.glsl through the buffer's R32UI texel view, so padded to whole 16-byte
/// texels), uploaded when the set of level sets changes. ObstacleCorrection and
/// SmokeDisplacement each keep one.

#include <cstdint>
#include <span>
#include <unordered_map>
#include <vector>

#include "engine/simulation/MovingObstacle.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::vulkan {
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

/// Where a level set lies in the buffer: its depth samples from `depth`, its velocity samples
/// (x, y, z each) from `velocity`, kNoVelocity when rigid.
struct LatticePlace {
    static constexpr std::uint32_t kNoVelocity = 0xffffffffu;
    std::uint32_t depth = 0;
    std::uint32_t velocity = kNoVelocity;
};

class ObstacleLattices {
public:
    explicit ObstacleLattices(const vulkan::VulkanContext& context);

    /// Uploads every level set of the obstacles (a deforming one's every file) unless they are
    /// those already there.
    /// @throw modeflow::Error when they hold more values than the device's texel buffers take.
    void update(std::span<const MovingObstacle> obstacles);
    /// Where `set` lies (one of the last update's; null: {0, kNoVelocity}).
    LatticePlace placeOf(const SolidLevelSet* set) const;
    const vulkan::DeviceBuffer& buffer() const { return mBuffer; }
    /// Counts the buffers made: a recording that bound buffer() holds a stale one once it grows.
    std::uint64_t generation() const { return mGeneration; }

private:
    const vulkan::VulkanContext& mContext;
    vulkan::DeviceBuffer mBuffer;
    std::vector<const SolidLevelSet*> mUploaded;
    std::uint64_t mGeneration = 0;
    std::unordered_map<const SolidLevelSet*, LatticePlace> mPlaces;
};

}  // namespace modeflow::device
