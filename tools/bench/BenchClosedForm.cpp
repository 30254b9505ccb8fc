/// @file BenchClosedForm.cpp
/// The shipped closed-form scenes stage by stage, on the CPU reference and on the Vulkan device
/// (--device N): the 64³ box (scenes/box_closed_form_3d.toml: a whole box with free-slip walls,
/// buoyant smoke from a hot ball near the floor, MacCormack) at N = 1000 and 2000 modes, and the
/// 256² torus (scenes/torus_closed_form_2d.toml, the real-time goal) at N = 500, each with the
/// midpoint rule and (`_linearized`) the linearized rule:
///   precompute        computeBasis (closed-form bases, sparse coefficients by selection rules)
///   cpu_step          one reference::Simulation step (wall ms, the reported time), and alone:
///                     contraction_ms (one C(v, v), SparseCoefficients, one thread),
///                     recon_ms and proj_ms (the separable transforms, FFTW),
///                     advect_ms (MacCormack on the 64³ smoke grid)
///   device_step       one device::Simulation step (GPU ms from timestamps, the reported time):
///                     forces_ms (force field + projection), modal_ms (the implicit step),
///                     recon_ms, advect_ms; and alone: contraction_ms (one C(v, v), sliced
///                     ELLPACK), proj_ms (the transposed transforms)
///   device_wall       the same step as a run takes it, without timestamps: the wall time of
///                     advanceSteps(1), submission, waiting and the host's status reads included
///                     (lavapipe flushes its work at every timestamp, so device_step's sum of
///                     dispatch times is not the time a run sees), with the step recorded once
///                     and resubmitted (recorded_once:1, as runs do) or afresh every step
///   device_obstacle   device_step of the box with a rigid mesh obstacle of 10 000 triangles (a
///                     torus, makeTorus(100, 50, ...), turning once a second) and 100 000 tracer
///                     particles, its box as the scene leaves it (smoke_filled:0) or full of
///                     smoke (1): obstacles_ms (the velocity the mismatch reads on the solid's
///                     box, the mismatch on its level set, projection, correction, smoke pushed
///                     out), particles_ms, and solids_particles_share, the two's part of the
///                     whole step
/// The state is the torus scene's initial vortices, and for the box (which starts at rest) a swirl
/// of a twentieth of a turnover per step, so the midpoint rule iterates as in a run. Run:
/// bench_closed_form [--device N] [--benchmark_filter=...].

#include <algorithm>
#include <chrono>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <benchmark/benchmark.h>

#include "engine/basis/VelocityBasis.h"
#include "engine/device/DeviceCoefficients.h"
#include "engine/device/ModalKernels.h"
#include "engine/device/SeparableTransform.h"
#include "engine/device/Simulation.h"
#include "engine/reference/ForceProjection.h"
#include "engine/reference/Simulation.h"
#include "engine/reference/SmokeAdvection.h"
#include "engine/reference/VelocityReconstruction.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/DeviceBuffer.h"
#include "precompute/Precompute.h"
#include "precompute/geometry/MeshGenerator.h"
#include "precompute/scene/SceneLoader.h"
#include "tests/support/RandomCoefficients.h"
#include "tools/bench/BenchDevice.h"
#include "tools/bench/EigenReference.h"
#include "tools/compose/RunPreparation.h"

namespace modeflow::bench {
namespace {

using Clock = std::chrono::steady_clock;

double msSince(Clock::time_point start) {
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

SceneSpec shippedScene(const char* file, int modes) {
    SceneSpec scene = loadScene(std::filesystem::path(MODEFLOW_SOURCE_DIR) / "scenes" / file);
    scene.basis.velocityModes = {{1, modes}};
    return scene;
}

/// The run of a scene at `modes` modes, kept until another is asked for.
const RunInputs& sceneRun(const char* file, int modes) {
    static std::map<std::pair<std::string, int>, std::unique_ptr<RunInputs>> runs;
    const std::pair<std::string, int> key(file, modes);
    if (!runs.count(key)) {
        runs.clear();
        const SceneSpec scene = shippedScene(file, modes);
        Progress quiet = Progress::silent();
        runs[key] = std::make_unique<RunInputs>(prepareRun(scene, computeBasis(scene, quiet)));
    }
    return *runs[key];
}

/// The state a step starts from: the scene's own initial velocity (the torus's vortex pairs: as
/// energetic as the run), or for a scene starting at rest (the box) a swirl of a twentieth of a
/// turnover per step.
Eigen::VectorXd startingVelocity(const RunInputs& run) {
    if (run.initialVelocity.squaredNorm() > 0.0) return run.initialVelocity;
    Eigen::VectorXd v = testing::randomVector(run.modeCount(), 3), r;
    run.coefficients->apply(v, v, r);
    return v * (0.05 / (run.settings.dt * r.norm() / v.norm()));
}

void precompute(benchmark::State& state, const char* file) {
    const SceneSpec scene = shippedScene(file, int(state.range(0)));
    std::size_t nonZeros = 0;
    for (auto _ : state) {
        Progress quiet = Progress::silent();
        nonZeros = computeBasis(scene, quiet).coefficients.value.size();
    }
    state.counters["nnz"] = double(nonZeros);
}

void cpuStep(benchmark::State& state, const char* file, Integrator integrator) {
    const RunInputs& run = sceneRun(file, int(state.range(0)));
    reference::Simulation simulation(run.cache, *run.coefficients, run.settings, run.smokeMask);
    simulation.setIntegrator(integrator);
    simulation.setVelocity(startingVelocity(run));
    simulation.advanceSteps(3);  // smoke to carry
    const VelocityBasis basis(run.cache);
    std::vector<double> contraction, recon, proj, advect;
    for (auto _ : state) {
        const Eigen::VectorXd v = simulation.velocity();
        auto start = Clock::now();
        Eigen::VectorXd r;
        run.coefficients->apply(v, v, r);
        contraction.push_back(msSince(start));
        start = Clock::now();
        const std::vector<double> field = reference::reconstructFaceField(basis, v);
        recon.push_back(msSince(start));
        start = Clock::now();
        benchmark::DoNotOptimize(reference::projectFaceField(basis, field));
        proj.push_back(msSince(start));
        reference::SmokeAdvection advection(MacGrid::fromSpec(run.cache.grid),
                                            run.settings.smokeScale, run.smokeMask);
        SmokeFields smoke = simulation.smoke();
        start = Clock::now();
        advection.step(std::span<const double>(field), run.settings.dt, run.settings.advection, {},
                       smoke);
        advect.push_back(msSince(start));
        start = Clock::now();
        simulation.advanceSteps(1);
        state.SetIterationTime(msSince(start) * 1e-3);
    }
    setMedian(state, "contraction_ms", contraction);
    setMedian(state, "recon_ms", recon);
    setMedian(state, "proj_ms", proj);
    setMedian(state, "advect_ms", advect);
    state.counters["DOFs"] = double(run.cache.faces.size());
}

void deviceStep(benchmark::State& state, const char* file, Integrator integrator) {
    const RunInputs& run = sceneRun(file, int(state.range(0)));
    const vulkan::VulkanContext& context = benchContext();
    const std::unique_ptr<Simulator> simulation = benchBackend().makeSimulator(run, true);
    simulation->setIntegrator(integrator);
    simulation->setVelocity(startingVelocity(run));
    simulation->advanceSteps(3);
    // The contraction and the projection alone.
    const device::ModalKernels kernels(context);
    const device::DeviceCoefficients coefficients(context, *run.coefficients);
    const device::SeparableTransformKernels transforms(context, run.cache);
    const std::vector<float> ones(device::paddedSize(run.modeCount()), 1.0f);
    const vulkan::DeviceBuffer a = vulkan::DeviceBuffer::fromValues<float>(context, ones, "a");
    vulkan::DeviceBuffer out(context, ones.size() * sizeof(float), "out");
    const std::vector<float> density(run.cache.faces.size(), 1.0f);
    const vulkan::DeviceBuffer q = vulkan::DeviceBuffer::fromValues<float>(context, density, "q");
    std::vector<double> forces, modal, recon, advect, contraction, proj;
    KernelProfile profile;
    int iterations = 0;
    for (auto _ : state) {
        const FrameStats stats = simulation->advanceSteps(1);
        profile.add(stats);
        const double total =
            stats.forcesMs + stats.modalMs + stats.reconstructionMs + stats.advectionMs;
        state.SetIterationTime(total * 1e-3);
        forces.push_back(stats.forcesMs);
        modal.push_back(stats.modalMs);
        recon.push_back(stats.reconstructionMs);
        advect.push_back(stats.advectionMs);
        iterations = std::max(iterations, stats.maxIterations);
        vulkan::CommandSequence sequence(context, true, 64);
        coefficients.recordApply(sequence, kernels, a, a, out);
        const std::size_t applyDispatches = sequence.dispatchCount();
        transforms.recordProjection(sequence, q, out);
        sequence.submitAndWait();
        const std::vector<double>& ms = sequence.dispatchTimesMs();
        double c = 0.0, p = 0.0;
        for (std::size_t d = 0; d < ms.size(); ++d) (d < applyDispatches ? c : p) += ms[d];
        contraction.push_back(c);
        proj.push_back(p);
    }
    setMedian(state, "forces_ms", forces);
    setMedian(state, "modal_ms", modal);
    setMedian(state, "recon_ms", recon);
    setMedian(state, "advect_ms", advect);
    setMedian(state, "contraction_ms", contraction);
    setMedian(state, "proj_ms", proj);
    state.counters["iterations"] = iterations;
    profile.report(std::string("deviceStep/") + file + "/N:" + std::to_string(state.range(0)));
}

/// Wall time per step, with steps recorded once (recorded:1) or afresh every step (recorded:0).
void deviceWall(benchmark::State& state, const char* file, Integrator integrator) {
    const RunInputs& run = sceneRun(file, int(state.range(0)));
    device::Simulation simulation(
        benchContext(), run.cache, *run.coefficients, run.settings, run.smokeMask, false,
        state.range(1) != 0 ? device::StepRecording::Once : device::StepRecording::EveryStep);
    simulation.setIntegrator(integrator);
    simulation.setVelocity(startingVelocity(run));
    simulation.advanceSteps(3);
    int iterations = 0;
    for (auto _ : state) {
        const auto start = Clock::now();
        const FrameStats stats = simulation.advanceSteps(1);
        state.SetIterationTime(msSince(start) * 1e-3);
        iterations = std::max(iterations, stats.maxIterations);
    }
    state.counters["iterations"] = iterations;
}

/// The box at `modes` with a turning 10 000-triangle torus mesh in its middle and 100 000 tracer
/// particles throughout.
const RunInputs& boxWithMeshObstacle(int modes) {
    static std::map<int, std::unique_ptr<RunInputs>> runs;
    if (!runs.count(modes)) {
        runs.clear();
        SceneSpec scene = shippedScene("box_closed_form_3d.toml", modes);
        ObstacleSpec torus;
        torus.shape = ObstacleShape::Mesh;
        torus.meshFile = std::filesystem::temp_directory_path() / "modeflow_bench_torus.obj";
        writeObj(torus.meshFile, makeTorus(100, 50, 0.2, 0.06));
        torus.path = {{0.0, {0.5, 0.5, 0.5}}};
        torus.rotation = {{0.0, {1.0, 0.0, 0.0}, 0.0}, {100.0, {1.0, 0.0, 0.0}, 36000.0}};
        scene.obstacles = {torus};
        ParticleSetSpec tracers;
        tracers.region.kind = ShapeKind::Box;
        tracers.region.min = {0.05, 0.05, 0.05};
        tracers.region.max = {0.95, 0.95, 0.95};
        tracers.count = 100000;
        scene.particles = {tracers};
        Progress quiet = Progress::silent();
        runs[modes] = std::make_unique<RunInputs>(prepareRun(scene, computeBasis(scene, quiet)));
    }
    return *runs[modes];
}

void deviceObstacleStep(benchmark::State& state) {
    const RunInputs& run = boxWithMeshObstacle(int(state.range(0)));
    const std::unique_ptr<Simulator> simulation = benchBackend().makeSimulator(run, true);
    if (state.range(1) != 0) {
        // The box full of smoke: every cell a solid covers holds some for the displacement.
        const std::size_t cells = std::size_t(simulation->smokeGrid().cellCount());
        simulation->restore(
            0.0, startingVelocity(run),
            SmokeFields{std::vector<double>(cells, 1.0), std::vector<double>(cells, 0.5), {}, {}});
    } else {
        simulation->setVelocity(startingVelocity(run));
    }
    simulation->advanceSteps(3);
    std::vector<double> obstacles, particles, shares;
    KernelProfile kernels;
    for (auto _ : state) {
        const FrameStats stats = simulation->advanceSteps(1);
        kernels.add(stats);
        const double total = stats.forcesMs + stats.modalMs + stats.reconstructionMs +
                             stats.obstaclesMs + stats.advectionMs + stats.particlesMs;
        state.SetIterationTime(total * 1e-3);
        obstacles.push_back(stats.obstaclesMs);
        particles.push_back(stats.particlesMs);
        shares.push_back((stats.obstaclesMs + stats.particlesMs) / total);
    }
    setMedian(state, "obstacles_ms", obstacles);
    setMedian(state, "particles_ms", particles);
    setMedian(state, "solids_particles_share", shares);
    kernels.report("deviceObstacleStep/smoke_filled:" + std::to_string(state.range(1)));
}

constexpr const char* kBox = "box_closed_form_3d.toml";
constexpr const char* kTorus = "torus_closed_form_2d.toml";

/// The mode counts each scene is measured at, in milliseconds.
void boxSizes(benchmark::internal::Benchmark* b) {
    b->ArgName("N")->Arg(1000)->Arg(2000)->Unit(benchmark::kMillisecond);
}
void torusSizes(benchmark::internal::Benchmark* b) {
    b->ArgName("N")->Arg(500)->Unit(benchmark::kMillisecond);
}
/// The same, each with steps recorded once and every step.
void boxRecordings(benchmark::internal::Benchmark* b) {
    b->ArgNames({"N", "recorded_once"})->ArgsProduct({{1000, 2000}, {1, 0}});
    b->Unit(benchmark::kMillisecond);
}
void torusRecordings(benchmark::internal::Benchmark* b) {
    b->ArgNames({"N", "recorded_once"})->ArgsProduct({{500}, {1, 0}});
    b->Unit(benchmark::kMillisecond);
}

BENCHMARK_CAPTURE(precompute, box_3d, kBox)->Apply(boxSizes)->Iterations(1);
BENCHMARK_CAPTURE(precompute, torus_2d, kTorus)->Apply(torusSizes)->Iterations(1);
BENCHMARK_CAPTURE(cpuStep, box_3d, kBox, Integrator::Midpoint)
    ->Apply(boxSizes)
    ->Iterations(5)
    ->UseManualTime();
BENCHMARK_CAPTURE(cpuStep, box_3d_linearized, kBox, Integrator::Linearized)
    ->Apply(boxSizes)
    ->Iterations(5)
    ->UseManualTime();
BENCHMARK_CAPTURE(cpuStep, torus_2d, kTorus, Integrator::Midpoint)
    ->Apply(torusSizes)
    ->Iterations(20)
    ->UseManualTime();
BENCHMARK_CAPTURE(cpuStep, torus_2d_linearized, kTorus, Integrator::Linearized)
    ->Apply(torusSizes)
    ->Iterations(20)
    ->UseManualTime();
BENCHMARK_CAPTURE(deviceStep, box_3d, kBox, Integrator::Midpoint)
    ->Apply(boxSizes)
    ->Iterations(5)
    ->UseManualTime();
BENCHMARK_CAPTURE(deviceStep, box_3d_linearized, kBox, Integrator::Linearized)
    ->Apply(boxSizes)
    ->Iterations(5)
    ->UseManualTime();
BENCHMARK_CAPTURE(deviceStep, torus_2d, kTorus, Integrator::Midpoint)
    ->Apply(torusSizes)
    ->Iterations(20)
    ->UseManualTime();
BENCHMARK_CAPTURE(deviceStep, torus_2d_linearized, kTorus, Integrator::Linearized)
    ->Apply(torusSizes)
    ->Iterations(20)
    ->UseManualTime();
BENCHMARK(deviceObstacleStep)
    ->ArgNames({"N", "smoke_filled"})
    ->Args({1000, 0})
    ->Args({1000, 1})
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5)
    ->UseManualTime();
BENCHMARK_CAPTURE(deviceWall, box_3d, kBox, Integrator::Midpoint)
    ->Apply(boxRecordings)
    ->Iterations(10)
    ->UseManualTime();
BENCHMARK_CAPTURE(deviceWall, box_3d_linearized, kBox, Integrator::Linearized)
    ->Apply(boxRecordings)
    ->Iterations(10)
    ->UseManualTime();
BENCHMARK_CAPTURE(deviceWall, torus_2d, kTorus, Integrator::Midpoint)
    ->Apply(torusRecordings)
    ->Iterations(40)
    ->UseManualTime();
BENCHMARK_CAPTURE(deviceWall, torus_2d_linearized, kTorus, Integrator::Linearized)
    ->Apply(torusRecordings)
    ->Iterations(40)
    ->UseManualTime();

}  // namespace
}  // namespace modeflow::bench
