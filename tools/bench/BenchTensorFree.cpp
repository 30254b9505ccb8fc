/// @file BenchTensorFree.cpp
/// The modal step with a stored dense tensor against the tensor-free advection
/// (engine/dynamics/TensorFreeCoefficients, engine/device/TensorFreeAdvection) at N = 250, 500,
/// 1000 on a 48³ box, on the CPU reference (double, one thread) and the Vulkan device (float32):
/// time of one RK4 step, four evaluations of R(v) = C(v, v) — the unit every scheme repeats (an
/// explicit step is one, a fixed-point midpoint iteration one, a Newton–Krylov product two) —
/// and the bytes each evaluation streams. The modes are synthetic (tests/support/SyntheticBases:
/// random ⋆-orthonormal fields on every interior face, 325k of them), the dense coefficients
/// random (RandomCoefficients' randomPackedDense), the quadrature the box's own
/// (precompute/coefficients/CoefficientAssembly): a step's cost depends on the sizes only, and a
/// 1000-mode eigenbasis of a 48³ domain takes hours to compute. CPU rows: wall time; device rows:
/// GPU time from timestamps. Memory: N = 1000 holds 2.6 GB of modes and, for the dense rows, a
/// 4 GB tensor (2 GB more on the device).
/// Run: bench_tensor_free [--device N] [--benchmark_filter=...].

#include <benchmark/benchmark.h>

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "engine/core/Error.h"
#include "engine/device/ModalStepper.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "engine/dynamics/TensorFreeCoefficients.h"
#include "engine/vulkan/CommandSequence.h"
#include "precompute/coefficients/CoefficientAssembly.h"
#include "precompute/dec/CutCellDec.h"
#include "precompute/dec/CutCellMeasures.h"
#include "precompute/geometry/Domain.h"
#include "tests/support/RandomCoefficients.h"
#include "tests/support/SyntheticBases.h"
#include "tools/bench/BenchDevice.h"
#include "tools/bench/EigenReference.h"

namespace modeflow::bench {
namespace {

constexpr int kCells = 48;

/// The whole box's vorticity quadrature on the face DOFs of syntheticModes (the faces not on the
/// box, in the same order).
BasisCache::Quadrature boxQuadrature(const GridSpec& grid, const std::vector<std::int64_t>& faces) {
    const CubicalComplex complex(grid);
    const Domain box({}, grid.dim, grid.spacing(0));
    const CutCellMeasures measures = measureCutCells(complex, box, BoundaryTreatment::CutCell, 1);
    const CutCellDec dec = buildCutCellDec(complex, measures, WallKind::FreeSlip);
    if (dec.faces.toGlobal != faces)
        throw Error("bench_tensor_free: the box's face DOFs are not the synthetic basis's");
    return vorticityQuadrature(complex, measures, dec);
}

/// The synthetic basis of `modes` modes with the box's quadrature, kept until another N is asked
/// for (the benchmarks of one N run one after another).
const BasisCache& basisFor(int modes) {
    static int current = 0;
    static std::unique_ptr<BasisCache> cache;
    if (!cache || current != modes) {
        cache.reset();
        const GridSpec grid = testing::boxGrid(3, kCells);
        cache = std::make_unique<BasisCache>(testing::syntheticModes(grid, modes, 7));
        cache->quadrature = boxQuadrature(grid, cache->faces);
        current = modes;
    }
    return *cache;
}

enum class Storage { Dense, TensorFree };

std::unique_ptr<StructuralCoefficients> coefficientsFor(const BasisCache& cache, Storage storage) {
    const int n = int(cache.velocity.modes.cols());
    if (storage == Storage::Dense)
        return std::make_unique<DenseCoefficients>(
            testing::randomPackedDense(n, std::uint64_t(n) * 7919));
    return std::make_unique<TensorFreeCoefficients>(cache.velocity.modes, cache.quadrature);
}

void report(benchmark::State& state, const std::vector<double>& stepMs, std::size_t streamedBytes) {
    setMedian(state, "step_ms", stepMs);
    state.counters["evaluation_ms"] = state.counters["step_ms"] / 4.0;
    state.counters["GB_per_evaluation"] = double(streamedBytes) * 1e-9;
}

void cpuStep(benchmark::State& state, Storage storage) {
    const BasisCache& cache = basisFor(int(state.range(0)));
    const std::unique_ptr<StructuralCoefficients> c = coefficientsFor(cache, storage);
    const FluidSystem system(*c);
    ModalIntegrator rk4(system, {Integrator::Rk4});
    Eigen::VectorXd v = testing::randomVector(c->size(), 5);
    std::vector<double> stepMs;
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        rk4.step(v, 1e-3);
        const double seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        state.SetIterationTime(seconds);
        stepMs.push_back(seconds * 1e3);
    }
    report(state, stepMs, c->storedBytes());
}

void deviceStep(benchmark::State& state, Storage storage) {
    const vulkan::VulkanContext& context = benchContext();
    const BasisCache& cache = basisFor(int(state.range(0)));
    const int n = int(cache.velocity.modes.cols());
    std::unique_ptr<device::ModalStepper> stepper;
    {
        // The host's tensor is only needed for the upload.
        const std::unique_ptr<StructuralCoefficients> c = coefficientsFor(cache, storage);
        stepper = std::make_unique<device::ModalStepper>(
            context, *c, FluidParameters{}, device::DeviceStepSettings{Integrator::Rk4}, &cache);
    }
    stepper->setState(testing::randomVector(n, 5));
    stepper->setForce(Eigen::VectorXd::Zero(n));
    const auto step = [&](vulkan::CommandSequence& sequence) {
        stepper->recordStep(sequence, 1e-3);
        sequence.submitAndWait();
    };
    vulkan::CommandSequence warmUp(context);  // the first submission pays one-time costs
    step(warmUp);
    std::vector<double> stepMs;
    for (auto _ : state) {
        vulkan::CommandSequence sequence(context, true,
                                         std::uint32_t(stepper->dispatchesPerStep()));
        step(sequence);
        double total = 0.0;
        for (const double t : sequence.dispatchTimesMs()) total += t;
        state.SetIterationTime(total * 1e-3);
        stepMs.push_back(total);
    }
    report(state, stepMs, stepper->coefficients().streamedBytes());
}

/// For each N: both storages on the CPU, then on the device (one basis per N).
[[maybe_unused]] const bool registered = [] {
    for (const int n : {250, 500, 1000}) {
        for (const auto& [name, storage] :
             {std::pair{"dense", Storage::Dense}, std::pair{"tensor_free", Storage::TensorFree}}) {
            benchmark::RegisterBenchmark((std::string("cpu_") + name).c_str(), cpuStep, storage)
                ->ArgName("N")
                ->Arg(n)
                ->Iterations(3)
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond);
            benchmark::RegisterBenchmark((std::string("vulkan_") + name).c_str(), deviceStep,
                                         storage)
                ->ArgName("N")
                ->Arg(n)
                ->Iterations(3)
                ->UseManualTime()
                ->Unit(benchmark::kMillisecond);
        }
    }
    return true;
}();

}  // namespace
}  // namespace modeflow::bench
