/// @file BenchPreview.cpp
/// The 3D preview (engine/preview/VolumeRenderer) of a 64³ grid at 512 × 512, the picture
/// PreviewTest writes (a mushroom cloud in a ball): wall time per picture, read-back included
/// (the reported time), and the GPU ms of its two passes, light and ray march.
/// Run: bench_preview [--device N] [--benchmark_filter=...] (5 pictures).

#include <vector>

#include <benchmark/benchmark.h>

#include "engine/preview/VolumeRenderer.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "tests/support/SmokeTestFields.h"
#include "tools/bench/BenchDevice.h"
#include "tools/bench/EigenReference.h"

namespace modeflow::bench {
namespace {

void volumePreview(benchmark::State& state) {
    const vulkan::VulkanContext& context = benchContext();
    const MacGrid grid = testing::smokeTestGrid(3, int(state.range(0)));
    const int size = int(state.range(1));
    preview::VolumeRenderer renderer(context, grid, testing::ballMask(grid, 0.95), size, size);
    const vulkan::DeviceBuffer density =
        vulkan::DeviceBuffer::fromValues<float>(context, testing::mushroomCloud(grid), "density");
    renderer.render(density, 15.0f);  // the first submission pays one-time costs
    std::vector<double> lightMs, marchMs;
    for (auto _ : state) {
        const preview::Image picture = renderer.render(density, 15.0f);
        benchmark::DoNotOptimize(picture.rgba.data());
        state.PauseTiming();
        vulkan::CommandSequence timed(context, true);
        renderer.record(timed, density, 15.0f);
        timed.submitAndWait();
        lightMs.push_back(timed.dispatchTimesMs()[0]);
        marchMs.push_back(timed.dispatchTimesMs()[1]);
        state.ResumeTiming();
    }
    setMedian(state, "light_ms", lightMs);
    setMedian(state, "march_ms", marchMs);
}

BENCHMARK(volumePreview)
    ->ArgNames({"cells", "pixels"})
    ->Args({64, 512})
    ->Iterations(5)
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace modeflow::bench
