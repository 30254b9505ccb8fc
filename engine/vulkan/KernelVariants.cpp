#include "engine/vulkan/KernelVariants.h"

#include <utility>

namespace modeflow::vulkan {

KernelVariants::KernelVariants(const VulkanContext& context, ComputeKernelSpec spec)
    : mContext(context), mSpec(std::move(spec)) {}

const ComputeKernel& KernelVariants::with(const std::vector<std::uint32_t>& constants) const {
    auto found = mKernels.find(constants);
    if (found == mKernels.end()) {
        ComputeKernelSpec spec = mSpec;
        spec.constants = constants;
        found = mKernels.try_emplace(constants, mContext, spec).first;
    }
    return found->second;
}

}  // namespace modeflow::vulkan
