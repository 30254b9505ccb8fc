/// @file BenchSmokeAdvection.cpp
/// One smoke advection step on the device (shaders/smoke_*.comp: emission, the advection of
/// density and temperature, and MacCormack's correction), 2D 128², 256² and 3D 32³, 48³, 64³ at
/// smoke scale 1 with the whole box fluid, a swirl of max |u| = 1 and the tests' two emitters
/// (tests/support/SmokeTestFields.h): GPU ms per step (the reported time) and the process's CPU
/// ms per step (on lavapipe the device is this process's threads; CPU time is steadier than wall
/// time on a busy machine).
/// Run: bench_smoke_advection [--device N] [--benchmark_filter=...] (8 steps each).

#include <ctime>
#include <vector>

#include <benchmark/benchmark.h>

#include "engine/device/SmokeAdvection.h"
#include "engine/device/SmokeState.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "tests/support/SmokeTestFields.h"
#include "tools/bench/BenchDevice.h"
#include "tools/bench/EigenReference.h"

namespace modeflow::bench {
namespace {

std::vector<float> toFloat(const std::vector<double>& values) {
    return {values.begin(), values.end()};
}

void smokeStep(benchmark::State& state, AdvectionScheme scheme) {
    const vulkan::VulkanContext& context = benchContext();
    const MacGrid grid = testing::smokeTestGrid(int(state.range(0)), int(state.range(1)));
    const std::vector<float> blob = toFloat(testing::gaussianBlob(grid, {0.2, -0.1, 0.05}, 0.2));
    const device::SmokeAdvectionKernels kernels(context);
    device::SmokeState smoke(context, grid, 1, testing::wholeMask(grid));
    smoke.upload(blob, blob);
    smoke.setEmitters(testing::smokeTestEmitters());
    const vulkan::DeviceBuffer velocity = vulkan::DeviceBuffer::fromValues<float>(
        context, toFloat(testing::unitSwirlVelocity(grid, 0.8, 5)), "velocity");
    {
        vulkan::CommandSequence warmUp(context);  // the first submission pays one-time costs
        kernels.record(warmUp, smoke, velocity, 0.02, scheme);
        warmUp.submitAndWait();
    }
    std::vector<double> cpuMs;
    for (auto _ : state) {
        vulkan::CommandSequence sequence(context, true, 16);
        kernels.record(sequence, smoke, velocity, 0.02, scheme);
        const std::clock_t start = std::clock();
        sequence.submitAndWait();
        cpuMs.push_back(1000.0 * double(std::clock() - start) / CLOCKS_PER_SEC);
        double ms = 0.0;
        for (const double t : sequence.dispatchTimesMs()) ms += t;
        state.SetIterationTime(ms * 1e-3);
    }
    setMedian(state, "cpu_ms", cpuMs);
    state.counters["cells"] = double(grid.cellCount());
}

void grids(benchmark::internal::Benchmark* b) {
    b->ArgNames({"dim", "cells"});
    for (const auto& [dim, cells] : {std::pair{2, 128}, {2, 256}, {3, 32}, {3, 48}, {3, 64}})
        b->Args({dim, cells});
    b->Iterations(8)->UseManualTime()->Unit(benchmark::kMillisecond);
}

BENCHMARK_CAPTURE(smokeStep, semi_lagrangian, AdvectionScheme::SemiLagrangian)->Apply(grids);
BENCHMARK_CAPTURE(smokeStep, maccormack, AdvectionScheme::MacCormack)->Apply(grids);

}  // namespace
}  // namespace modeflow::bench
