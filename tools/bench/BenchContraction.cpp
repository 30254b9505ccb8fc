/// @file BenchContraction.cpp
/// The contraction out = C(a, b) on the device (float32): GPU time of the pair-sum pass (the
/// bandwidth-bound GEMV over the packed coefficients, the reported time) and of the combine pass,
/// and its GB/s over the coefficient bytes against Eigen's float GEMV over the same stored values
/// (EigenReference.h: paired and warm); sparse coefficients (10% of the entries; bytes counted as
/// stored, values and indices) against Eigen's sparse row-major GEMV.
/// Run: bench_contraction [--device N] [--benchmark_filter=...] (20 rounds each).

#include <memory>
#include <vector>

#include <benchmark/benchmark.h>

#include "engine/device/DeviceCoefficients.h"
#include "engine/device/ModalKernels.h"
#include "engine/dynamics/SparseCoefficients.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "tests/support/RandomCoefficients.h"
#include "tools/bench/BenchDevice.h"
#include "tools/bench/EigenReference.h"

namespace modeflow::bench {
namespace {

void contraction(benchmark::State& state, bool sparse) {
    const vulkan::VulkanContext& context = benchContext();
    const int n = int(state.range(0));
    const DenseCoefficients dense =
        testing::randomDense(n, std::uint64_t(n) * 7919, sparse ? 0.1 : 1.0);
    std::unique_ptr<StructuralCoefficients> c;
    std::unique_ptr<EigenGemv> gemv;
    if (sparse) {
        auto s = std::make_unique<SparseCoefficients>(SparseCoefficients::fromDense(dense));
        gemv = std::make_unique<SparseGemv>(*s);
        c = std::move(s);
    } else {
        gemv = std::make_unique<PackedGemv>(dense);
        c = std::make_unique<DenseCoefficients>(dense);
    }
    const device::ModalKernels kernels(context);
    const device::DeviceCoefficients coefficients(context, *c);
    const std::vector<float> ones(device::paddedSize(n), 1.0f);
    const vulkan::DeviceBuffer a = vulkan::DeviceBuffer::fromValues<float>(context, ones, "a");
    vulkan::DeviceBuffer out(context, std::size_t(n) * sizeof(float), "out");
    DeviceAgainstEigen timing(*gemv);
    std::vector<double> combineMs;
    const auto apply = [&](vulkan::CommandSequence& sequence) {
        coefficients.recordApply(sequence, kernels, a, a, out);
        sequence.submitAndWait();
    };
    vulkan::CommandSequence warmUp(context);  // the first submission pays one-time costs
    apply(warmUp);
    for (auto _ : state) {
        // Pair sums, then the combine's two passes (rows, then columns of the triangle).
        vulkan::CommandSequence sequence(context, true, 3);
        apply(sequence);
        const std::vector<double>& ms = sequence.dispatchTimesMs();
        state.SetIterationTime(ms[0] * 1e-3);
        combineMs.push_back(ms[1] + ms[2]);
        timing.add(ms[0]);
    }
    const double bytes = double(coefficients.streamedBytes());
    timing.report(state, bytes);
    setMedian(state, "combine_ms", combineMs);
    state.counters["MB"] = bytes * 1e-6;
}

BENCHMARK_CAPTURE(contraction, dense, false)
    ->ArgName("N")
    ->Arg(50)
    ->Arg(100)
    ->Arg(200)
    ->Iterations(20)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(contraction, sparse, true)
    ->ArgName("N")
    ->Arg(100)
    ->Arg(200)
    ->Iterations(20)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace modeflow::bench
