#include "engine/kernels/ModalApply.h"

#include <array>
// The generated header uses uint32_t without including <cstdint>.
#include <cstdint>

#include "engine/dynamics/PackedLayout.h"
#include "engine/format/Error.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "shaders/ModalApplyParams.h"
#include "shaders/modal_apply.spv.h"

namespace modeflow::vulkan {
namespace {

void requireFloats(const DeviceBuffer& buffer, std::size_t count) {
    if (buffer.bytes() < count * sizeof(float))
        throw Error("modal_apply: buffer \"" + buffer.name() + "\" holds " + std::to_string(buffer.bytes()) +
                    " bytes, " + std::to_string(count * sizeof(float)) + " needed");
}

}  // namespace

ModalApply::ModalApply(const VulkanContext& context, std::uint32_t workgroupSize)
    : mKernel(context, ComputeKernelSpec{"modal_apply", modal_apply_spv, 4,
                                         sizeof(shaders::ModalApplyParams), workgroupSize}) {}

std::vector<float> ModalApply::packCoefficients(std::span<const double> packed) {
    return std::vector<float>(packed.begin(), packed.end());
}

void ModalApply::record(CommandSequence& sequence, std::uint32_t n, const DeviceBuffer& packed,
                        const DeviceBuffer& a, const DeviceBuffer& b, const DeviceBuffer& out) const {
    if (n < 2) throw Error("modal_apply: needs at least 2 modes, got " + std::to_string(n));
    requireFloats(packed, packedSize(n));
    requireFloats(a, n);
    requireFloats(b, n);
    requireFloats(out, n);
    const shaders::ModalApplyParams params{n, std::uint32_t(pairCount(n)), 0, 0};
    const std::array<const DeviceBuffer*, 4> buffers{&packed, &a, &b, &out};
    sequence.dispatch(mKernel, buffers, params, n);
}

}  // namespace modeflow::vulkan
