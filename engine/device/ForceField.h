#pragma once
/// @file ForceField.h
/// The force density g on the velocity DOFs on the device (shaders/force_field.comp; CPU
/// reference and definitions: engine/reference/ForceField.h): buoyancy from the smoke temperature
/// (a smoke-grid buffer, e.g. SmokeState::temperature(), with its packed fluid mask) plus
/// stirring splats. The result feeds ForceProjectionKernel with FaceQuantity::Density.

#include <cstdint>
#include <span>

#include "engine/core/MacGrid.h"
#include "engine/format/BasisCache.h"
#include "engine/simulation/ForceSplat.h"
#include "engine/vulkan/ComputeKernel.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "engine/vulkan/KernelVariants.h"

namespace modeflow::vulkan {
class CommandSequence;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class ForceFieldKernel {
public:
    /// For the DOFs and grid of `cache`, a smoke grid of `scale` cells per basis cell and axis,
    /// and up to `maxSplats` splats at once.
    /// @throw modeflow::Error if scale < 1, maxSplats < 1, or a creation call fails.
    ForceFieldKernel(const vulkan::VulkanContext& context, const BasisCache& cache, int scale,
                     std::uint32_t maxSplats = maxForceSplats, std::uint32_t workgroupSize = 64);

    /// The splats of the following submissions (float32 on the device). Between submissions only.
    /// @throw modeflow::Error on more than maxSplats splats or a radius that is not positive.
    void setSplats(std::span<const ForceSplat> splats);
    std::uint32_t splatCount() const { return mSplatCount; }

    /// Records g = buoyancy × dual-cell temperature (up faces) + splats, one float per DOF.
    /// `temperature`: one float per smoke cell; `fluidMask`: null, or one byte per smoke cell
    /// packed four to a word (SmokeState's mask), then only fluid cells enter the mean.
    /// `upDofsOnly`: the caller reads g at the up DOFs alone (a projection of the up component,
    /// SeparableTransformKernels::recordComponentProjection); without splats the other DOFs
    /// are then left as they were, not zeroed.
    /// @throw modeflow::Error if a buffer is too small.
    void record(vulkan::CommandSequence& sequence, double buoyancy,
                const vulkan::DeviceBuffer& temperature, const vulkan::DeviceBuffer* fluidMask,
                const vulkan::DeviceBuffer& g, bool upDofsOnly = false) const;

    std::uint32_t dofCount() const { return mDofCount; }

private:
    /// force_field.comp's pipeline for `stage` (FORCE_STAGE_*), with or without the fluid mask;
    /// the buoyancy adding to g (after splats) or assigning it. Made on first use.
    const vulkan::ComputeKernel& kernel(std::uint32_t stage, bool useMask, bool accumulate) const;

    MacGrid mGrid;
    MacGrid mSmoke;
    int mScale;
    std::uint32_t mDofCount = 0;
    std::uint32_t mMaxSplats = 0;
    std::uint32_t mSplatCount = 0;
    std::uint32_t mGroups = 1;    ///< workgroups over every DOF (splats)
    std::uint32_t mUpGroups = 1;  ///< over the up DOFs (buoyancy)
    vulkan::DeviceBuffer mFaces;
    struct UpDofs {
        vulkan::DeviceBuffer
            buffer;  ///< per up-facing DOF: the DOF and its face position (4 uints)
        std::uint32_t count = 0;
    };
    static UpDofs uploadUpDofs(const vulkan::VulkanContext& context, const MacGrid& grid,
                               const BasisCache& cache);
    UpDofs mUp;
    vulkan::DeviceBuffer mSplats;
    vulkan::KernelVariants mKernels;
};

}  // namespace modeflow::device
