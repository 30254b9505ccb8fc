#pragma once
/// @file BenchDevice.h
/// The Vulkan device the runtime benchmarks run on, and their main(): `--device N` (a Vulkan
/// device index, `vulkaninfo --summary`) or `--device vulkan` (the first suitable device, the
/// default) is taken from the command line before Google Benchmark reads the rest, which refuses
/// any flag it does not know (exit status 1).

#include "engine/run/Backend.h"
#include "engine/vulkan/VulkanContext.h"

namespace modeflow::bench {

/// The backend opened from `--device` (the bench's main opens it before any benchmark runs).
const Backend& benchBackend();

/// Its Vulkan context.
const vulkan::VulkanContext& benchContext();

}  // namespace modeflow::bench
