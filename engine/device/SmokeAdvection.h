#pragma once
/// @file SmokeAdvection.h
/// One smoke advection step of density and temperature (and fuel and flame with fire) on the
/// device, float32 (shaders/SmokeAdvect.glsl; CPU reference and the rules:
/// engine/reference/SmokeAdvection.h).
/// Each step first pairs the velocity faces (shaders/smoke_face_pairs.comp); then
/// semi-Lagrangian is one dispatch, MacCormack two (forward and backward traces with the forward
/// sample, then the backward sample and the clamped correction), over the fluid cells only, both
/// fields in each; with fire the (fuel, flame) pair after the (density, temperature) one,
/// through the same kernels. Emitters are added in the step's last dispatch.
///
/// Its speed on lavapipe, layout by layout: engine/README.md "Speed" (shaders/SmokeAdvect.glsl
/// says what changed and why).

#include <array>
#include <cstdint>
#include <optional>
#include <span>

#include "engine/core/SceneSpec.h"
#include "engine/vulkan/ComputeKernel.h"

namespace modeflow::vulkan {
class CommandSequence;
class DeviceBuffer;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class SmokeState;

class SmokeAdvectionKernels {
public:
    /// `workgroupSize`: any; 128 ran a little faster than 64 on lavapipe, and suits GPUs. The
    /// advection kernels are made when a step first needs them (a run uses two or three of the
    /// twelve variants: stage, dimension, smoke scale 1 or not).
    /// @throw modeflow::Error if the device lacks 64-bit integers in shaders (shaderInt64) or a
    /// pipeline cannot be created.
    explicit SmokeAdvectionKernels(const vulkan::VulkanContext& context,
                                   std::uint32_t workgroupSize = 128);

    /// Records one step of `state` by `velocity` (a float32 face field of state.basisGrid(),
    /// MacGrid::faceIndex order) over `dt`, then the state's emitters, and flips the state so
    /// that its current fields are the step's result once the sequence is submitted. Grids
    /// larger than one dispatch can cover are split over several dispatches.
    /// @throw modeflow::Error when the velocity buffer is smaller than the basis grid's face
    /// count or has no texel view (it is read as texels), dt is not finite, the smoke grid has
    /// 2^32 cells or more, or a kernel's pipeline cannot be created.
    void record(vulkan::CommandSequence& sequence, SmokeState& state,
                const vulkan::DeviceBuffer& velocity, double dt, AdvectionScheme scheme) const;
    /// Records the step's first dispatch alone: the velocity as face pairs
    /// (SmokeState::facePairs, shaders/smoke_face_pairs.comp), which record() does first and
    /// the conservative transport samples too.
    void recordFacePairs(vulkan::CommandSequence& sequence, const SmokeState& state,
                         const vulkan::DeviceBuffer& velocity) const;

private:
    /// The kernel of `stage` (SMOKE_STAGE_*) for a `dim`-dimensional smoke grid, made on first
    /// use; `unitScale`: the smoke grid is the basis grid.
    const vulkan::ComputeKernel& stageKernel(std::uint32_t stage, int dim, bool unitScale) const;

    const vulkan::VulkanContext& mContext;
    /// smoke_face_pairs for a walled x, then for a periodic one (its WRAP_X), made on first use.
    mutable std::array<std::optional<vulkan::ComputeKernel>, 2> mFacePairs;
    std::uint32_t mWorkgroupSize;
    /// By stage (semi-Lagrangian, MacCormack forward, MacCormack correction), 2D then 3D, each
    /// for any smoke scale and for scale 1.
    mutable std::array<std::optional<vulkan::ComputeKernel>, 12> mStages;
};

}  // namespace modeflow::device
