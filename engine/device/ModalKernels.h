#pragma once
/// @file ModalKernels.h
/// The pipelines of the modal step (shaders/modal_*.comp), built once per context and shared by
/// DeviceCoefficients and ModalStepper. They use subgroup arithmetic, which every desktop GPU and
/// lavapipe offer; a device without it is refused with a clear message.

#include <cstdint>

#include "engine/vulkan/ComputeKernel.h"
#include "engine/vulkan/KernelVariants.h"

namespace modeflow::vulkan {
class VulkanContext;
}  // namespace modeflow::vulkan

namespace modeflow::device {

struct ModalKernels {
    /// @throw modeflow::Error if the device lacks subgroup arithmetic in compute shaders or a
    /// pipeline cannot be created.
    explicit ModalKernels(const vulkan::VulkanContext& context);

    vulkan::ComputeKernel
        pairSums;  ///< dense: sums[p] = Σ_i C_p[i] a_i, a tile of pairs per 8 invocations
    vulkan::ComputeKernel sparsePairSums;  ///< sparse rows: one invocation per stored pair
    vulkan::ComputeKernel combine;         ///< out = U b from the pair sums U, a subgroup per k
    vulkan::ComputeKernel combineColumns;  ///< then out -= Uᵀ b, an invocation per 4 outputs
    vulkan::ComputeKernel pairWeights;     ///< dense advection: w(k,j) = u_k x_j − u_j x_k
    vulkan::ComputeKernel advectDense;     ///< dense advection: partial sums over groups of tiles
    vulkan::ComputeKernel advectSum;       ///< dense advection: the partial sums added
    vulkan::ComputeKernel advectSparse;    ///< sparse advection: one gather per mode
    vulkan::ComputeKernel linear;  ///< out += D b, D dense (a wind's term), a subgroup per k

    /// The integrators' state update `op` (MODAL_OP_*; one workgroup), with the linearized rule's
    /// frozen point (`frozen`) and MHD's Lorentz force (`lorentz`) fixed at compile time: made on
    /// first use (shaders/modal_update.comp has why). Not for concurrent use.
    /// @throw modeflow::Error if the pipeline cannot be created.
    const vulkan::ComputeKernel& update(std::uint32_t op, bool frozen, bool lorentz) const;

private:
    vulkan::KernelVariants mUpdates;
};

}  // namespace modeflow::device
