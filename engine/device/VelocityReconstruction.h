#pragma once
/// @file VelocityReconstruction.h
/// Modal velocity → face field on the device (shaders/reconstruct_velocity.comp; CPU reference:
/// engine/reference/VelocityReconstruction.h): field[face(d)] = (Σ_i v_i Ψ_i)[d] / area(axis), one
/// dispatch per chunk of the ModeBuffer (all but the last leave their sums in the kernel's scratch
/// buffer; CommandSequence's barrier between dispatches orders its reuse by later reconstructions).
/// v stays on the device, so a modal step's output can be reconstructed in the same submission.
/// The kernel reads 64-bit words: the device needs shaderInt64.

#include <cstdint>
#include <string>
#include <vector>

#include "engine/core/MacGrid.h"
#include "engine/device/IndirectArguments.h"
#include "engine/format/BasisCache.h"
#include "engine/vulkan/ComputeKernel.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "engine/vulkan/KernelVariants.h"

namespace modeflow::vulkan {
class CommandSequence;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class ModeBuffer;

class ReconstructionKernel {
public:
    /// For the DOFs and grid of `cache` (uploads the DOF → face table).
    /// @throw modeflow::Error if the device lacks shaderInt64, the grid has 2^32 faces or more, or
    /// a creation call fails.
    ReconstructionKernel(const vulkan::VulkanContext& context, const BasisCache& cache,
                         std::uint32_t workgroupSize = 64);

    /// A face field for this grid (one float per face), zero-filled: the kernel writes only the
    /// DOF faces, so the others stay 0 as the face-field convention wants.
    vulkan::DeviceBuffer makeFaceField(std::string name = "face field") const;

    /// Records faceField = the face field of Σ v_i Ψ_i. v holds modes.paddedModeCount() floats
    /// (N values, then anything: the kernel reads them four at a time but uses only the first N).
    /// @throw modeflow::Error if `modes` is not a basis on this kernel's DOFs, or a buffer is too
    /// small.
    void record(vulkan::CommandSequence& sequence, const ModeBuffer& modes,
                const vulkan::DeviceBuffer& v, const vulkan::DeviceBuffer& faceField,
                IndirectArguments indirect = {}) const;
    /// The group counts of record's dispatches (one per chunk of `modes`).
    std::vector<std::uint32_t> dispatchGroups(const ModeBuffer& modes) const;

    const MacGrid& grid() const { return mGrid; }
    std::uint32_t dofCount() const { return mDofCount; }

private:
    const vulkan::VulkanContext& mContext;
    MacGrid mGrid;
    std::uint32_t mDofCount = 0;
    vulkan::DeviceBuffer mFaces;
    vulkan::DeviceBuffer
        mScratch;  ///< the sums of the chunks so far, in DOF order (as many floats as mFaces)
    std::uint32_t mWorkgroupSize = 64;
    /// By the specialization constants (float16 modes, a chunk after the first, the last chunk,
    /// the chunk's mode count, its first mode % 4).
    vulkan::KernelVariants mKernels;
};

}  // namespace modeflow::device
