#pragma once
/// @file WindField.h
/// A wind's held base flow on the device (shaders/add_wind.comp): U added to the reconstructed
/// face field after each reconstruction, as the CPU reference's addWind
/// (engine/simulation/WindTransport.h) does, so the obstacles, the smoke and the particles see
/// the whole air velocity U + Ψ v.

#include <cstdint>

#include "engine/core/GridSpec.h"
#include "engine/core/MacGrid.h"
#include "engine/vulkan/ComputeKernel.h"

namespace modeflow::vulkan {
class CommandSequence;
class DeviceBuffer;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class WindField {
public:
    /// @throw modeflow::Error for a non-finite wind, or a creation call that fails.
    WindField(const vulkan::VulkanContext& context, const MacGrid& grid, const Vec3& wind);

    /// Records faceField += U on every face normal to each axis of `grid`.
    /// @throw modeflow::Error when `faceField` is not one float per face.
    void record(vulkan::CommandSequence& sequence, const vulkan::DeviceBuffer& faceField) const;

private:
    MacGrid mGrid;
    Vec3 mWind;
    std::uint32_t mGroups = 1;
    vulkan::ComputeKernel mKernel;
};

}  // namespace modeflow::device
