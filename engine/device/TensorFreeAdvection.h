#pragma once
/// @file TensorFreeAdvection.h
/// The structural-coefficient contractions on the device without a tensor (CPU reference:
/// engine/dynamics/TensorFreeCoefficients.h), float32:
///
///     C(a, b):       reconstruct a and b to face fields (ReconstructionKernel)
///                    → per vorticity element (ω(a) q(b), −ω(a) p(b))   (advection_samples.comp)
///                    → per DOF the transposed quadrature, g              (advection_gather.comp)
///                    → Ψᵀ g                                              (ForceProjectionKernel)
///     advect(u, x):  the same with per element p(u) q(x) − q(u) p(x) and the curl's transpose.
///
/// Two passes over the basis per contraction (the reconstructions read it once each, the
/// projection once more), O(N·V); the quadrature tables are a few floats per element and DOF.
/// Every dispatch can take its group counts from an IndirectArguments buffer.

#include <cstdint>
#include <optional>
#include <vector>

#include "engine/device/ForceProjection.h"
#include "engine/device/IndirectArguments.h"
#include "engine/device/ModeBuffer.h"
#include "engine/device/VelocityReconstruction.h"
#include "engine/format/BasisCache.h"
#include "engine/vulkan/ComputeKernel.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::vulkan {
class CommandSequence;
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

class TensorFreeAdvection {
public:
    /// For the modes, DOFs and quadrature of `cache`. `modes`: the basis already on the device in
    /// float32 (engine/device/Simulation's), or null to upload it here; it must outlive this.
    /// @throw modeflow::Error when the quadrature has no element, an element has more samples
    /// than the kernels take (4 for the curl, 2 per velocity component), `modes` is not this
    /// basis in float32, or a device call fails.
    TensorFreeAdvection(const vulkan::VulkanContext& context, const BasisCache& cache,
                        const ModeBuffer* modes = nullptr);

    int size() const { return int(mModes->modeCount()); }
    /// Bytes one contraction of a vector with itself reads (C(v, v): the basis twice, and the
    /// tables); two vectors read the basis once more.
    std::size_t streamedBytes() const;

    /// Group counts of recordApply's and recordAdvect's dispatches, in order. `sameVectors`:
    /// recordApply's a and b are one buffer, reconstructed once.
    std::vector<std::uint32_t> dispatchGroups(bool sameVectors = false) const;

    /// out = C(a, b); a and b hold the modal vectors padded as ModeBuffer::paddedModeCount says
    /// (one buffer for both: one reconstruction).
    void recordApply(vulkan::CommandSequence& sequence, const vulkan::DeviceBuffer& a,
                     const vulkan::DeviceBuffer& b, const vulkan::DeviceBuffer& out,
                     IndirectArguments indirect = {}) const;
    /// out_k = Σ_ij C[j][k][i] x_i u_j (StructuralCoefficients::advect).
    void recordAdvect(vulkan::CommandSequence& sequence, const vulkan::DeviceBuffer& u,
                      const vulkan::DeviceBuffer& x, const vulkan::DeviceBuffer& out,
                      IndirectArguments indirect = {}) const;

private:
    /// A transposed part of the quadrature, per DOF: row starts and (sample slot, coefficient).
    struct Gather {
        vulkan::DeviceBuffer rowStart;
        vulkan::DeviceBuffer entries;
    };
    void record(vulkan::CommandSequence& sequence, bool apply, const vulkan::DeviceBuffer& a,
                const vulkan::DeviceBuffer& b, const vulkan::DeviceBuffer& out,
                IndirectArguments indirect) const;

    const vulkan::VulkanContext& mContext;
    std::optional<ModeBuffer> mOwnModes;
    const ModeBuffer* mModes = nullptr;
    ReconstructionKernel mReconstruction;
    ForceProjectionKernel mProjection;
    std::uint32_t mElementCount = 0;
    std::uint32_t mDofCount = 0;
    vulkan::DeviceBuffer mElements;
    Gather mApplyGather, mAdvectGather;
    vulkan::DeviceBuffer mFieldA, mFieldB, mSamples, mProjected;
    vulkan::ComputeKernel mApplySamples, mAdvectSamples, mGatherKernel;
};

}  // namespace modeflow::device
