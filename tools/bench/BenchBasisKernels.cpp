/// @file BenchBasisKernels.cpp
/// The two basis kernels alone on synthetic bases (BenchGrids.h): reconstruction Ψv (one
/// dispatch) and force projection Ψᵀ(w q) (both passes), float32 and float16 modes, GPU ms (the
/// reported time) and GB/s over the float32 basis bytes against Eigen's float GEMVs Ψv and Ψᵀx on
/// the same data (EigenReference.h: paired and warm).
/// Run: bench_basis_kernels [--device N] [--benchmark_filter=...] (5 rounds each).

#include <vector>

#include <benchmark/benchmark.h>

#include "engine/device/ForceProjection.h"
#include "engine/device/ModeBuffer.h"
#include "engine/device/VelocityReconstruction.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "tools/bench/BenchDevice.h"
#include "tools/bench/BenchGrids.h"
#include "tools/bench/EigenReference.h"

namespace modeflow::bench {
namespace {

enum class Kernel { Reconstruction, Projection };

void basisKernel(benchmark::State& state, Kernel kernel, ModePrecision precision) {
    const vulkan::VulkanContext& context = benchContext();
    const int n = int(state.range(2));
    const BasisCache& cache = syntheticBasisFor(int(state.range(0)), int(state.range(1)), n);
    const device::ModeBuffer modes(context, cache.velocity.modes, precision);
    const device::ReconstructionKernel reconstruction(context, cache);
    const device::ForceProjectionKernel projection(context, cache, FaceQuantity::Density);
    const vulkan::DeviceBuffer v = vulkan::DeviceBuffer::fromValues<float>(
        context, std::vector<float>(std::size_t((n + 3) / 4 * 4), 1.0f), "v");
    const vulkan::DeviceBuffer field = reconstruction.makeFaceField();
    const vulkan::DeviceBuffer q = vulkan::DeviceBuffer::fromValues<float>(
        context, std::vector<float>(cache.faces.size(), 1.0f), "q");
    const vulkan::DeviceBuffer f(context, std::size_t(n) * sizeof(float), "f");
    BasisGemv gemv(cache.velocity.modes, kernel == Kernel::Projection);
    DeviceAgainstEigen timing(gemv);
    const auto run = [&](vulkan::CommandSequence& sequence) {
        if (kernel == Kernel::Reconstruction)
            reconstruction.record(sequence, modes, v, field);
        else
            projection.record(sequence, modes, q, f);
        sequence.submitAndWait();
    };
    vulkan::CommandSequence warmUp(context);  // the first submission pays one-time costs
    run(warmUp);
    for (auto _ : state) {
        vulkan::CommandSequence sequence(context, true, 64);
        run(sequence);
        double ms = 0.0;
        for (const double t : sequence.dispatchTimesMs()) ms += t;
        state.SetIterationTime(ms * 1e-3);
        timing.add(ms);
    }
    timing.report(state, double(cache.faces.size()) * n * sizeof(float));
    state.counters["DOFs"] = double(cache.faces.size());
}

[[maybe_unused]] const bool registered = [] {
    using P = ModePrecision;
    registerOnGrids(
        {{"reconstruction_float32",
          [](benchmark::State& s) { basisKernel(s, Kernel::Reconstruction, P::Float32); }},
         {"reconstruction_float16",
          [](benchmark::State& s) { basisKernel(s, Kernel::Reconstruction, P::Float16); }},
         {"projection_float32",
          [](benchmark::State& s) { basisKernel(s, Kernel::Projection, P::Float32); }},
         {"projection_float16",
          [](benchmark::State& s) { basisKernel(s, Kernel::Projection, P::Float16); }}},
        [](benchmark::internal::Benchmark* b) {
            b->Iterations(5)->UseManualTime()->Unit(benchmark::kMillisecond);
        });
    return true;
}();

}  // namespace
}  // namespace modeflow::bench
