#pragma once
/// @file ForceProjection.h
/// Grid forces → modal forces on the device (shaders/project_force.comp and
/// project_force_sum.comp; CPU reference: engine/reference/ForceProjection.h):
/// f_k = Σ_d Ψ_k[d] w_d q_d, float32, deterministic (no atomics).
///
/// Pass 1 splits the DOFs into blocks and gives each workgroup up to 64 modes × one block, writing
/// one partial sum per mode and block (one dispatch per chunk of the ModeBuffer); pass 2 adds each
/// mode's partial sums in a fixed order and applies the mode's scale. Blocks keep a projection
/// parallel across a GPU however few modes there are: a 64³ basis (~750k DOFs) with 100 modes
/// makes ~760 workgroups of 2048 DOFs. f stays on the device for the next modal step. The modes,
/// weights and density are read as texels (shaders/TexelAccess.glsl).

#include <cstdint>
#include <vector>

#include "engine/core/ModePrecision.h"
#include "engine/device/IndirectArguments.h"
#include "engine/format/BasisCache.h"
#include "engine/simulation/ProjectionWeights.h"
#include "engine/vulkan/ComputeKernel.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "engine/vulkan/KernelVariants.h"

namespace modeflow::vulkan {
class CommandSequence;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class ModeBuffer;

struct ForceProjectionOptions {
    std::uint32_t workgroupSize = 64;
    /// DOFs per workgroup of pass 1 (rounded up to whole tiles and units, raised when the group
    /// count would pass the device limit); 0: 2048 on a GPU, on a CPU device 4096 to 32768 for
    /// about 16 workgroups (ForceProjection.cpp).
    std::uint32_t dofsPerGroup = 0;
    /// FaceQuantity::FaceField given as the face field's values at the DOFs (DOF order), not as
    /// a whole-grid face field: no gather (a moving obstacle's mismatch is written so).
    bool dofOrder = false;
};

class ForceProjectionKernel {
public:
    /// For the DOFs, grid and mode count of `cache`. `quantity` says what the input is:
    /// Density: one force density per DOF (ForceFieldKernel's output), weights h_axis;
    /// FaceField: a whole-grid face field (ReconstructionKernel's layout) read at the DOF faces,
    /// or its values at the DOFs with options.dofOrder, weights area × ⋆ (the exact inverse of
    /// the reconstruction).
    /// @throw modeflow::Error if there are more modes than the
    /// device's group count limit, the workgroup needs more shared memory than the device has
    /// (64 floats per invocation), or a creation call fails.
    ForceProjectionKernel(const vulkan::VulkanContext& context, const BasisCache& cache,
                          FaceQuantity quantity, const ForceProjectionOptions& options = {});

    /// Records f = Ψᵀ (w ∘ q) (N floats) with the modes in `modes`.
    /// @throw modeflow::Error if `modes` is not a basis of this kernel's DOFs and mode count, or a
    /// buffer is too small.
    void record(vulkan::CommandSequence& sequence, const ModeBuffer& modes,
                const vulkan::DeviceBuffer& q, const vulkan::DeviceBuffer& f,
                IndirectArguments indirect = {}) const;
    /// The group counts of record's dispatches (one per chunk of `modes`, then the sums).
    std::vector<std::uint32_t> dispatchGroups(const ModeBuffer& modes) const;

    std::uint32_t blockCount() const { return mBlockCount; }
    std::uint32_t blockSize() const { return mBlockSize; }

private:
    /// Pass 1's pipeline for `precision` and `slots` modes per workgroup (specialization
    /// constants), built on first use: a basis's chunks need one or two.
    const vulkan::ComputeKernel& partialKernel(ModePrecision precision, std::uint32_t slots) const;

    bool mGather = false;  ///< q is a whole-grid face field read at the DOF faces
    std::uint32_t mDofCount = 0;
    std::uint32_t mModeCount = 0;
    std::uint64_t mFaceTotal = 0;
    std::uint32_t mBlockSize = 0;
    std::uint32_t mBlockCount = 0;
    vulkan::DeviceBuffer mFaces;
    vulkan::DeviceBuffer mWeights;
    vulkan::DeviceBuffer mPartials;
    const vulkan::VulkanContext& mContext;
    std::uint32_t mWorkgroupSize = 64;
    /// By (float16, gather, slots).
    vulkan::KernelVariants mPartialKernels;
    vulkan::ComputeKernel mSumKernel;
};

}  // namespace modeflow::device
