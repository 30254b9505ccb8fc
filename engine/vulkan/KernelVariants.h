#pragma once
/// @file KernelVariants.h
/// One shader's pipelines, one per set of specialization constants, each made the first time it
/// is asked for: a shader whose branches fold on many constants (ComputeKernel.h: lavapipe runs
/// both sides of a run-time branch) compiles only the variants a run records.

#include <cstdint>
#include <map>
#include <vector>

#include "engine/vulkan/ComputeKernel.h"

namespace modeflow::vulkan {

class KernelVariants {
public:
    /// Pipelines of `spec` (whose own constants are ignored) on `context`, which must outlive
    /// this object.
    KernelVariants(const VulkanContext& context, ComputeKernelSpec spec);

    /// The pipeline with specialization constants 1…k = `constants`, made on first use.
    /// Recording, like CommandSequence, is for one thread at a time.
    /// @throw modeflow::Error as ComputeKernel's constructor.
    const ComputeKernel& with(const std::vector<std::uint32_t>& constants) const;

private:
    const VulkanContext& mContext;
    ComputeKernelSpec mSpec;
    mutable std::map<std::vector<std::uint32_t>, ComputeKernel> mKernels;
};

}  // namespace modeflow::vulkan
