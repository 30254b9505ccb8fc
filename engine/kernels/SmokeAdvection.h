#pragma once
/// @file SmokeAdvection.h
/// One smoke advection step of density and temperature on the device, float32
/// (shaders/smoke_advect.comp; CPU reference and the rules: engine/field/SmokeAdvection.h).
/// Semi-Lagrangian is one dispatch; MacCormack two (forward, then backward + clamped
/// correction), both fields in each. Emitters are added in the step's last dispatch.

#include <cstdint>

#include "engine/field/SmokeAdvection.h"
#include "engine/vulkan/ComputeKernel.h"

namespace modeflow::vulkan {

class CommandSequence;
class DeviceBuffer;
class SmokeState;
class VulkanContext;

class SmokeAdvectionKernels {
public:
    /// @throw modeflow::Error if the pipeline cannot be created.
    explicit SmokeAdvectionKernels(const VulkanContext& context, std::uint32_t workgroupSize = 64);

    /// Records one step of `state` by `velocity` (a float32 face field of state.basisGrid(),
    /// MacGrid::faceIndex order) over `dt`, then the state's emitters, and flips the state so
    /// that its current fields are the step's result once the sequence is submitted. Grids
    /// larger than one dispatch can cover are split over several dispatches.
    /// @throw modeflow::Error when the velocity buffer is smaller than the basis grid's face
    /// count, dt is not finite, or the smoke grid has 2^32 cells or more.
    void record(CommandSequence& sequence, SmokeState& state, const DeviceBuffer& velocity, double dt,
                AdvectionScheme scheme) const;

    const ComputeKernel& kernel() const { return mKernel; }

private:
    const VulkanContext& mContext;
    ComputeKernel mKernel;
};

}  // namespace modeflow::vulkan
