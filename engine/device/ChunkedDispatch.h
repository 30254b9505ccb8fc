#pragma once
/// @file ChunkedDispatch.h
/// One kernel over `count` invocations in as many dispatches as the device's group count limit
/// (maxComputeWorkGroupCount[0]) needs, each told its first invocation in a push constant.

#include <algorithm>
#include <cstdint>
#include <span>

#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/ComputeKernel.h"
#include "engine/vulkan/VulkanContext.h"

namespace modeflow::device {

/// Dispatches `kernel` over `count` invocations, setting params.*first to each chunk's first
/// invocation times `firstScale`.
template <typename Params>
void dispatchInChunks(const vulkan::VulkanContext& context, vulkan::CommandSequence& sequence,
                      const vulkan::ComputeKernel& kernel,
                      std::span<const vulkan::DeviceBuffer* const> buffers, Params& params,
                      std::uint32_t Params::*first, std::int64_t count,
                      std::uint32_t firstScale = 1) {
    const std::int64_t groupSize = kernel.workgroupSize();
    const std::int64_t perDispatch =
        std::int64_t(context.properties().limits.maxComputeWorkGroupCount[0]) * groupSize;
    for (std::int64_t start = 0; start < count; start += perDispatch) {
        params.*first = std::uint32_t(start) * firstScale;
        const std::int64_t chunk = std::min(perDispatch, count - start);
        sequence.dispatch(kernel, buffers, params,
                          std::uint32_t((chunk + groupSize - 1) / groupSize));
    }
}

}  // namespace modeflow::device
