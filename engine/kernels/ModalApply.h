#pragma once
/// @file ModalApply.h
/// The dense structural-coefficient contraction out_k = Σ_ij C[k][i][j] a_i b_j on the device,
/// float32, from the packed k < j layout of engine/dynamics/PackedLayout.h (shaders/
/// modal_apply.comp; CPU reference: DenseCoefficients::apply).

#include <cstdint>
#include <span>
#include <vector>

#include "engine/vulkan/ComputeKernel.h"

namespace modeflow::vulkan {

class CommandSequence;
class DeviceBuffer;
class VulkanContext;

class ModalApply {
public:
    /// @throw modeflow::Error if the pipeline cannot be created.
    explicit ModalApply(const VulkanContext& context, std::uint32_t workgroupSize = 64);

    /// The packed coefficients as float32, ready for upload (same order, N²(N−1)/2 values).
    static std::vector<float> packCoefficients(std::span<const double> packed);

    /// Records out = C(a, b) for N = `n` modes into `sequence` (one workgroup per output).
    /// @throw modeflow::Error if a buffer is smaller than N (or N²(N−1)/2 for `packed`) floats.
    void record(CommandSequence& sequence, std::uint32_t n, const DeviceBuffer& packed, const DeviceBuffer& a,
                const DeviceBuffer& b, const DeviceBuffer& out) const;

    const ComputeKernel& kernel() const { return mKernel; }

private:
    ComputeKernel mKernel;
};

}  // namespace modeflow::vulkan
