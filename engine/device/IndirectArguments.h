#pragma once
/// @file IndirectArguments.h
/// Where a recording takes its group counts from: fixed counts, or a buffer of
/// VkDispatchIndirectCommand that the device may zero to switch dispatches off without a host
/// round trip (the implicit integrators' iterations, engine/device/ModalStepper.h). A recording of
/// several dispatches takes entries first, first + 1, … in order; the stage that records them
/// says their fixed counts (its dispatchGroups()).

#include <cstdint>
#include <span>

#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"

namespace modeflow::device {

struct IndirectArguments {
    const vulkan::DeviceBuffer* buffer = nullptr;  ///< null: fixed counts
    std::uint32_t first = 0;

    /// The arguments of the dispatch `index` places later.
    IndirectArguments after(std::uint32_t index) const { return {buffer, first + index}; }

    /// Records one dispatch with `groups` workgroups, or with the counts of entry `first`.
    template <typename Params>
    void dispatch(vulkan::CommandSequence& sequence, const vulkan::ComputeKernel& kernel,
                  std::span<const vulkan::DeviceBuffer* const> buffers, const Params& params,
                  std::uint32_t groups) const {
        if (buffer)
            sequence.dispatchIndirect(kernel, buffers, params, *buffer,
                                      VkDeviceSize(first) * sizeof(VkDispatchIndirectCommand));
        else
            sequence.dispatch(kernel, buffers, params, groups);
    }
};

}  // namespace modeflow::device
