#pragma once
/// @file BenchDevice.h
/// The Vulkan device the runtime benchmarks run on, and their main(): `--device N` (a Vulkan
/// device index, `vulkaninfo --summary`) or `--device vulkan` (the first suitable device, the
/// default) is taken from the command line before Google Benchmark reads the rest, which refuses
/// any flag it does not know (exit status 1). `--kernels` has the benchmarks that step a
/// simulation print where its device time went, kernel by kernel (reportKernels).

#include <map>
#include <string>

#include "engine/run/Backend.h"
#include "engine/simulation/FrameStats.h"
#include "engine/vulkan/VulkanContext.h"

namespace modeflow::bench {

/// The backend opened from `--device` (the bench's main opens it before any benchmark runs).
const Backend& benchBackend();

/// Its Vulkan context.
const vulkan::VulkanContext& benchContext();

/// A benchmark's device time by kernel over the steps it measured (FrameStats::kernelMs).
class KernelProfile {
public:
    void add(const FrameStats& stats);
    /// With `--kernels`: prints to stderr, under `title`, each kernel's time per timed step,
    /// longest first, with its share.
    void report(const std::string& title) const;

private:
    std::map<std::string, double> mTotalMs;
    int mSteps = 0;
};

}  // namespace modeflow::bench
