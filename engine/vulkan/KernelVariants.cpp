#include "engine/vulkan/KernelVariants.h"

#include <string>
#include <utility>

namespace modeflow::vulkan {

KernelVariants::KernelVariants(const VulkanContext& context, ComputeKernelSpec spec)
    : mContext(context), mSpec(std::move(spec)) {}

const ComputeKernel& KernelVariants::with(const std::vector<std::uint32_t>& constants) const {
    auto found = mKernels.find(constants);
    if (found == mKernels.end()) {
        ComputeKernelSpec spec = mSpec;
        spec.constants = constants;
        // Named with its constants, so that errors and dispatch labels tell the variants apart.
        for (std::size_t c = 0; c < constants.size(); ++c) {
            spec.name += c == 0 ? '(' : ',';
            spec.name += std::to_string(constants[c]);
        }
        if (!constants.empty()) spec.name += ')';
        found = mKernels.try_emplace(constants, mContext, spec).first;
    }
    return found->second;
}

}  // namespace modeflow::vulkan
