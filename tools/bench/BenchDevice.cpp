/// The device and main() of the runtime benchmarks (BenchDevice.h): `--device X` or
/// `--device=X`, then Google Benchmark's flags; an unknown flag or a bad device ends with a
/// message and status 1.

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <benchmark/benchmark.h>

#include "engine/core/Error.h"
#include "tools/bench/BenchDevice.h"

namespace modeflow::bench {
namespace {

std::unique_ptr<Backend>& openedBackend() {
    static std::unique_ptr<Backend> backend;
    return backend;
}

bool& kernelsWanted() {
    static bool wanted = false;
    return wanted;
}

/// Removes `--device X` / `--device=X` (and `--kernels`) from argv and returns X; empty when
/// absent.
/// @throw modeflow::Error when the value is missing.
std::optional<std::string> takeDeviceFlag(int& argc, char** argv) {
    std::optional<std::string> value;
    int kept = 1;
    for (int i = 1; i < argc; ++i) {
        if (!std::strcmp(argv[i], "--device")) {
            if (i + 1 == argc)
                throw Error("--device needs a value: a Vulkan device index or vulkan");
            value = argv[++i];
        } else if (!std::strncmp(argv[i], "--device=", 9)) {
            value = argv[i] + 9;
        } else if (!std::strcmp(argv[i], "--kernels")) {
            kernelsWanted() = true;
        } else {
            argv[kept++] = argv[i];
        }
    }
    argc = kept;
    argv[argc] = nullptr;
    return value;
}

}  // namespace

const Backend& benchBackend() {
    if (!openedBackend())
        throw Error("benchmark: the device is opened by main() before the benchmarks run");
    return *openedBackend();
}

const vulkan::VulkanContext& benchContext() {
    return *benchBackend().vulkanContext();
}

void KernelProfile::add(const FrameStats& stats) {
    for (const auto& [kernel, ms] : stats.kernelMs) mTotalMs[kernel] += ms;
    mSteps += stats.timedSteps;
}

void KernelProfile::report(const std::string& title) const {
    if (!kernelsWanted() || mSteps <= 0) return;
    std::vector<std::pair<double, std::string>> rows;
    double sum = 0.0;
    for (const auto& [kernel, ms] : mTotalMs) {
        rows.emplace_back(ms / mSteps, kernel);
        sum += ms / mSteps;
    }
    std::sort(rows.rbegin(), rows.rend());
    std::fprintf(stderr, "%s: device time per step by kernel (%d steps)\n", title.c_str(), mSteps);
    for (const auto& [ms, kernel] : rows)
        std::fprintf(stderr, "  %9.3f ms  %5.1f%%  %s\n", ms, sum > 0 ? 100.0 * ms / sum : 0.0,
                     kernel.c_str());
    std::fprintf(stderr, "  %9.3f ms  total\n", sum);
}

}  // namespace modeflow::bench

int main(int argc, char** argv) {
    using namespace modeflow;
    const std::string program = argv[0];
    try {
        const std::optional<std::string> device = bench::takeDeviceFlag(argc, argv);
        const BackendChoice choice = parseDeviceOption(device.value_or("vulkan"));
        if (choice.kind != BackendKind::Vulkan)
            throw Error("--device " + *device +
                        ": the runtime benchmarks measure a Vulkan device; give its index");
        benchmark::Initialize(&argc, argv);
        if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
        bench::openedBackend() = std::make_unique<Backend>(choice);
        if (bench::benchContext().timestampValidBits() == 0)
            throw Error(
                "the device's queue writes no timestamps, and the runtime benchmarks report GPU "
                "times");
        std::fprintf(stderr, "%s", bench::benchBackend().describe().c_str());
        benchmark::AddCustomContext("device", bench::benchContext().deviceName());
        benchmark::RunSpecifiedBenchmarks();
        benchmark::Shutdown();
    } catch (const std::exception& e) {
        std::fprintf(stderr, "%s: error: %s\n", program.c_str(), e.what());
        return 1;
    }
    return 0;
}
