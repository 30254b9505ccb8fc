/// @file BenchRuntimeStages.cpp
/// The whole runtime step on the device (the Simulator the pipeline's Backend makes: forces,
/// midpoint step, reconstruction, MacCormack advection at smoke scale 1, buoyancy and one
/// emitter) on synthetic bases (BenchGrids.h): GPU ms per stage and per step (the reported time),
/// the midpoint iterations, and the reconstruction's GB/s over the float32 basis against Eigen's
/// GEMV Ψv on the same data (EigenReference.h: paired and warm).
/// Run: bench_runtime_stages [--device N] [--benchmark_filter=...] (5 steps each).

#include <algorithm>
#include <memory>
#include <vector>

#include <benchmark/benchmark.h>

#include "engine/run/Backend.h"
#include "tests/support/RandomCoefficients.h"
#include "tools/bench/BenchDevice.h"
#include "tools/bench/BenchGrids.h"
#include "tools/bench/EigenReference.h"
#include "tools/compose/RunPreparation.h"

namespace modeflow::bench {
namespace {

/// The run of a box scene whose whole grid is fluid, with buoyancy and one emitter at the centre.
RunInputs syntheticRun(int dim, int cells, int modes) {
    const BasisCache& cache = syntheticBasisFor(dim, cells, modes);
    SceneSpec scene;
    scene.grid = cache.grid;
    scene.smoke.buoyancy = 1.0;
    SourceSpec source;  // a ball at the origin
    source.shape.radius = 0.2;
    source.density = source.temperature = 1.0;
    scene.sources = {source};
    return prepareRun(scene, cache);
}

void runtimeStep(benchmark::State& state) {
    const RunInputs run =
        syntheticRun(int(state.range(0)), int(state.range(1)), int(state.range(2)));
    const std::unique_ptr<Simulator> simulation = benchBackend().makeSimulator(run, true);
    // A twentieth of a turnover per step.
    Eigen::VectorXd v = testing::randomVector(run.modeCount(), 3), r;
    run.coefficients->apply(v, v, r);
    v *= 0.05 / (run.settings.dt * r.norm() / v.norm());
    simulation->setVelocity(v);
    simulation->advanceFrame();  // warm-up
    BasisGemv gemv(run.cache.velocity.modes, false);
    DeviceAgainstEigen reconstruction(gemv);
    std::vector<double> forces, modal, advection, step;
    int iterations = 0;
    for (auto _ : state) {
        const FrameStats stats = simulation->advanceFrame();
        const double total =
            stats.forcesMs + stats.modalMs + stats.reconstructionMs + stats.advectionMs;
        state.SetIterationTime(total * 1e-3);
        forces.push_back(stats.forcesMs);
        modal.push_back(stats.modalMs);
        advection.push_back(stats.advectionMs);
        step.push_back(total);
        iterations = std::max(iterations, stats.maxIterations);
        reconstruction.add(stats.reconstructionMs);
    }
    reconstruction.report(state, double(run.cache.faces.size()) * run.modeCount() * sizeof(float),
                          "recon_ms");
    setMedian(state, "forces_ms", forces);
    setMedian(state, "modal_ms", modal);
    setMedian(state, "advect_ms", advection);
    setMedian(state, "step_ms", step);
    state.counters["iterations"] = iterations;
    state.counters["DOFs"] = double(run.cache.faces.size());
}

[[maybe_unused]] const bool registered = [] {
    registerOnGrids({{"runtime_step", runtimeStep}}, [](benchmark::internal::Benchmark* b) {
        b->Iterations(5)->UseManualTime()->Unit(benchmark::kMillisecond);
    });
    return true;
}();

}  // namespace
}  // namespace modeflow::bench
