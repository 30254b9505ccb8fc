/// @file BenchDynamics.cpp
/// Speed of the reduced dynamics (issue 3): single contractions and explicit / midpoint steps at
/// N = 50…400, with dense coefficients and with sparse ones at 10% density. The counter GB/s is
/// coefficient bytes streamed per second (one pass per apply, iterations + 1 passes per midpoint
/// step, each a linearization or, once Newton reuses its Jacobian, a plain apply); Newton and
/// Jacobians are mean counts per step. States take steps with h·|R(v)|/|v| = 0.3, the large step
/// of the conservation tests. The second argument is the OpenMP thread count.
/// Run: bench_dynamics [--benchmark_filter=...].

#include <benchmark/benchmark.h>

#include <map>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "engine/dynamics/SparseCoefficients.h"
#include "engine/dynamics/ThreadCount.h"
#include "tests/support/RandomCoefficients.h"

namespace {

using namespace modeflow;

enum class Storage { Dense, Sparse };

constexpr double kSparseDensity = 0.1;

/// Random coefficients (tests/support/RandomCoefficients.h), built once per (N, storage); the
/// sparse ones keep a random 10% of the entries.
const StructuralCoefficients& coefficients(int n, Storage storage) {
    static std::map<std::pair<int, Storage>, std::unique_ptr<StructuralCoefficients>> cache;
    auto& slot = cache[{n, storage}];
    if (!slot) {
        const std::uint64_t seed = std::uint64_t(n) * 7919 + int(storage);
        if (storage == Storage::Dense)
            slot = std::make_unique<DenseCoefficients>(testing::randomDense(n, seed));
        else
            slot = std::make_unique<SparseCoefficients>(
                SparseCoefficients::fromDense(testing::randomDense(n, seed, kSparseDensity)));
    }
    return *slot;
}

Eigen::VectorXd randomState(int n) {
    return testing::randomVector(n, 12345);
}

void contraction(benchmark::State& state, Storage storage, bool withJacobian) {
    const ThreadCount threads(int(state.range(1)));
    const int n = int(state.range(0));
    const StructuralCoefficients& c = coefficients(n, storage);
    const Eigen::VectorXd a = randomState(n);
    Eigen::VectorXd out;
    Eigen::MatrixXd byI, byJ;
    for (auto _ : state) {
        if (withJacobian) {
            c.linearize(a, a, byI, byJ);
            benchmark::DoNotOptimize(byJ.data());
        } else {
            c.apply(a, a, out);
            benchmark::DoNotOptimize(out.data());
        }
    }
    state.counters["GB/s"] = benchmark::Counter(double(c.storedBytes()) * 1e-9,
                                                benchmark::Counter::kIsIterationInvariantRate);
    state.counters["MB"] = double(c.storedBytes()) * 1e-6;
}

void step(benchmark::State& state, Storage storage, Integrator scheme) {
    const int n = int(state.range(0));
    const StructuralCoefficients& c = coefficients(n, storage);
    const FluidSystem system(c);
    IntegratorSettings settings;
    settings.scheme = scheme;
    settings.threads = int(state.range(1));
    ModalIntegrator integrator(system, settings);
    Eigen::VectorXd v = randomState(n), r;
    c.apply(v, v, r);
    const double h = 0.3 * v.norm() / r.norm();
    double passes = 0.0, iterations = 0.0, jacobians = 0.0;
    for (auto _ : state) {
        const StepReport report = integrator.step(v, h);
        iterations += report.iterations;
        jacobians += report.jacobians;
        passes += scheme == Integrator::Midpoint ? report.iterations + 1 : 1;
    }
    state.counters["GB/s"] =
        benchmark::Counter(passes * double(c.storedBytes()) * 1e-9, benchmark::Counter::kIsRate);
    state.counters["Newton"] = iterations / double(state.iterations());
    state.counters["Jacobians"] = jacobians / double(state.iterations());
}

void sizes(benchmark::internal::Benchmark* b) {
    b->ArgNames({"N", "threads"});
    for (int threads : {1, 2})
        for (int n : {50, 100, 200, 400}) b->Args({n, threads});
    b->Unit(benchmark::kMillisecond)->UseRealTime();
}

BENCHMARK_CAPTURE(contraction, apply_dense, Storage::Dense, false)->Apply(sizes);
BENCHMARK_CAPTURE(contraction, apply_sparse, Storage::Sparse, false)->Apply(sizes);
BENCHMARK_CAPTURE(contraction, linearize_dense, Storage::Dense, true)->Apply(sizes);
BENCHMARK_CAPTURE(contraction, linearize_sparse, Storage::Sparse, true)->Apply(sizes);
BENCHMARK_CAPTURE(step, explicit_dense, Storage::Dense, Integrator::Explicit)->Apply(sizes);
BENCHMARK_CAPTURE(step, explicit_sparse, Storage::Sparse, Integrator::Explicit)->Apply(sizes);
BENCHMARK_CAPTURE(step, midpoint_dense, Storage::Dense, Integrator::Midpoint)->Apply(sizes);
BENCHMARK_CAPTURE(step, midpoint_sparse, Storage::Sparse, Integrator::Midpoint)->Apply(sizes);

}  // namespace

BENCHMARK_MAIN();
