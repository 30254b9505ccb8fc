#pragma once
/// @file WindField.h
/// A wind's held base flow on the device (shaders/add_wind.comp): B (windBaseFlow's face field,
/// engine/simulation/WindTransport.h, uploaded once) added to the reconstructed face field
/// after each reconstruction, as the CPU reference does, so the obstacles, the smoke and the
/// particles see the whole air velocity B + Ψ v.

#include <cstdint>
#include <span>

#include "engine/core/MacGrid.h"
#include "engine/vulkan/ComputeKernel.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::vulkan {
class CommandSequence;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class WindField {
public:
    /// `base`: B, one face-normal velocity a face of `grid`.
    /// @throw modeflow::Error when it is not, or a creation call fails.
    WindField(const vulkan::VulkanContext& context, const MacGrid& grid,
              std::span<const double> base);

    /// Records faceField += B (the box's sides, which a reconstruction leaves alone, set to B).
    /// @throw modeflow::Error when `faceField` is not one float per face.
    void record(vulkan::CommandSequence& sequence, const vulkan::DeviceBuffer& faceField) const;

private:
    MacGrid mGrid;
    vulkan::DeviceBuffer mBase;  ///< B, one float a face
    std::uint32_t mGroups = 1;
    vulkan::ComputeKernel mKernel;
};

}  // namespace modeflow::device
