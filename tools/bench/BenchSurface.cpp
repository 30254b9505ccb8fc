/// @file BenchSurface.cpp
/// A surface scene's step on both backends (SurfaceSimulator: the midpoint modal step and the
/// dye carried in the scalar basis, a source emitting), on the 2562-vertex icosphere at N
/// velocity and M scalar modes: wall time per step, host and device together (the reported
/// time), the midpoint iterations, and the device's dye solve's conjugate-gradient iterations;
/// on the device with each step recorded once (the default) and afresh every step.
/// Compare the backends' rows within one run. Run: bench_surface [--device N]
/// [--benchmark_filter=...] (the basis is precomputed first: about 20 s at N = M = 400).

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <utility>

#include <benchmark/benchmark.h>

#include "engine/core/Error.h"
#include "engine/device/SurfaceSimulation.h"
#include "engine/dynamics/InitialConditions.h"
#include "engine/run/Backend.h"
#include "precompute/Precompute.h"
#include "precompute/geometry/MeshGenerator.h"
#include "tools/bench/BenchDevice.h"
#include "tools/compose/RunPreparation.h"

namespace modeflow::bench {
namespace {

/// A folder of this process's own for the mesh, removed at exit.
struct ScratchFolder {
    std::filesystem::path path;
    ScratchFolder() {
        std::string pattern =
            (std::filesystem::temp_directory_path() / "bench_surface-XXXXXX").string();
        if (!mkdtemp(pattern.data())) throw Error("bench_surface: no temporary folder");
        path = pattern;
    }
    ~ScratchFolder() {
        std::error_code ignored;
        std::filesystem::remove_all(path, ignored);
    }
};

/// The icosphere's run with N velocity and M scalar modes, a random flow of energy 1 and a
/// source at the north pole; made once per (N, M).
const RunInputs& sphereRun(int velocityModes, int scalarModes) {
    static std::map<std::pair<int, int>, std::unique_ptr<RunInputs>> runs;
    std::unique_ptr<RunInputs>& run = runs[{velocityModes, scalarModes}];
    if (!run) {
        static const ScratchFolder folder;
        writeObj(folder.path / "sphere.obj", makeIcosphere(4));
        SceneSpec scene;
        scene.name = "sphere";
        scene.surface = SurfaceSpec{folder.path / "sphere.obj"};
        scene.basis.velocityModes = {{1, velocityModes}};
        scene.basis.scalarModes = scalarModes;
        scene.simulation.dt = 0.01;
        SourceSpec source;
        source.shape.center = {0.0, 0.0, 1.0};
        source.shape.radius = 0.25;
        source.density = 1.0;
        scene.sources.push_back(source);
        Progress quiet = Progress::silent();
        run = std::make_unique<RunInputs>(
            prepareRun(scene, computeBasis(scene, quiet), RunParts::Dynamics));
        run->initialVelocity = randomVelocity(run->modeCount(), {0, -1, 1.0, 3});
    }
    return *run;
}

void surfaceStep(benchmark::State& state) {
    const bool device = state.range(0) > 0;
    const RunInputs& run = sphereRun(int(state.range(1)), int(state.range(2)));
    const Backend cpu(BackendKind::CpuReference, benchContext());
    const std::unique_ptr<SurfaceSimulator> simulation =
        device
            ? std::make_unique<device::SurfaceSimulation>(
                  benchContext(), run.cache, *run.coefficients, run.settings, run.initialVelocity,
                  state.range(0) == 1 ? device::StepRecording::Once
                                      : device::StepRecording::EveryStep)
            : cpu.makeSurfaceSimulator(run);
    simulation->advanceSteps(2);  // warm-up
    constexpr int kSteps = 10;
    int iterations = 0;
    for (auto _ : state) {
        const auto start = std::chrono::steady_clock::now();
        const FrameStats stats = simulation->advanceSteps(kSteps);
        const std::chrono::duration<double> took = std::chrono::steady_clock::now() - start;
        state.SetIterationTime(took.count() / kSteps);
        iterations = std::max(iterations, stats.maxIterations);
    }
    state.SetLabel(!device               ? "cpu"
                   : state.range(0) == 1 ? "vulkan, recorded once"
                                         : "vulkan, recorded every step");
    state.counters["iterations"] = iterations;
    if (const auto* onDevice = dynamic_cast<const device::SurfaceSimulation*>(simulation.get()))
        state.counters["dye_iterations"] = onDevice->dyeStatus().iterations;
}

[[maybe_unused]] const bool registered = [] {
    // device 0: the CPU reference; 1: the device, each step recorded once and resubmitted;
    // 2: the device, each step recorded afresh.
    benchmark::RegisterBenchmark("surfaceStep", surfaceStep)
        ->ArgNames({"device", "N", "M"})
        ->ArgsProduct({{0, 1, 2}, {48}, {80}})
        ->ArgsProduct({{0, 1, 2}, {400}, {200, 400}})
        ->Iterations(5)
        ->UseManualTime()
        ->Unit(benchmark::kMillisecond);
    return true;
}();

}  // namespace
}  // namespace modeflow::bench
