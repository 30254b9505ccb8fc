/// @file BenchModalSteps.cpp
/// Whole modal steps on the device: GPU time per step (all its dispatches) of explicit Euler,
/// RK4 and the midpoint rule, and the midpoint rule's iterations per step, with random dense
/// coefficients and a step of a tenth of a turnover (h·|R(v)|/|v| = 0.1).
/// Run: bench_modal_steps [--device N] [--benchmark_filter=...] (20 steps each).

#include <benchmark/benchmark.h>

#include <vector>

#include "engine/device/ModalStepper.h"
#include "engine/vulkan/CommandSequence.h"
#include "tests/support/RandomCoefficients.h"
#include "tools/bench/BenchDevice.h"
#include "tools/bench/EigenReference.h"

namespace modeflow::bench {
namespace {

void modalStep(benchmark::State& state, Integrator scheme) {
    const vulkan::VulkanContext& context = benchContext();
    const int n = int(state.range(0));
    const DenseCoefficients c = testing::randomDense(n, std::uint64_t(n) * 7919);
    const Eigen::VectorXd v = testing::randomVector(n, 5);
    Eigen::VectorXd r;
    c.apply(v, v, r);
    const double h = 0.1 * v.norm() / r.norm();
    device::ModalStepper stepper(context, c, {}, {scheme});
    stepper.setState(v);
    const auto step = [&](vulkan::CommandSequence& sequence) {
        stepper.recordStep(sequence, h);
        sequence.submitAndWait();
    };
    vulkan::CommandSequence warmUp(context);  // the first submission pays one-time costs
    step(warmUp);
    std::vector<double> stepMs;
    for (auto _ : state) {
        vulkan::CommandSequence sequence(context, true, std::uint32_t(stepper.dispatchesPerStep()));
        step(sequence);
        double total = 0.0;
        for (const double t : sequence.dispatchTimesMs()) total += t;
        state.SetIterationTime(total * 1e-3);
        stepMs.push_back(total);
    }
    setMedian(state, "ms", stepMs);
    if (scheme == Integrator::Midpoint) state.counters["iterations"] = stepper.status().iterations;
}

void sizes(benchmark::internal::Benchmark* b) {
    b->ArgName("N")->Arg(50)->Arg(100)->Arg(200)->Iterations(20)->UseManualTime()->Unit(
        benchmark::kMillisecond);
}

BENCHMARK_CAPTURE(modalStep, explicit, Integrator::Explicit)->Apply(sizes);
BENCHMARK_CAPTURE(modalStep, rk4, Integrator::Rk4)->Apply(sizes);
BENCHMARK_CAPTURE(modalStep, midpoint, Integrator::Midpoint)->Apply(sizes);

}  // namespace
}  // namespace modeflow::bench
