/// @file BenchRuntime.cpp
/// Speed of the Vulkan runtime's kernels (issue 4), as tables: for N = 50, 100, 200 the GPU time of
/// the dense pair-sum pass (the bandwidth-bound GEMV over the packed coefficients) and of the
/// combine pass, their GB/s over the float32 coefficient bytes against Eigen's GEMV on the same
/// float32 data (1 thread), and the same for sparse coefficients against Eigen's sparse GEMV; then
/// the GPU time of whole steps per scheme; then the whole runtime step (Simulation: forces,
/// midpoint step, reconstruction, MacCormack advection) per stage on 2D 256² and 3D 48³, 64³ grids,
/// with the reconstruction's GB/s over the float32 basis against Eigen's GEMV Ψv on the same data;
/// then the two basis kernels alone (reconstruction Ψv and force projection Ψᵀx, float32 and
/// float16 modes) on the same grids against Eigen's float GEMVs. Times are medians over repeated
/// dispatches or steps. Eigen is timed two ways (`timings`): paired, one run after each device
/// round, so both meet the same machine (on this shared 2-core VM the load and the share of the L3
/// cache left to us vary 2× within minutes), and warm, back to back, its data in the cache where
/// it fits; shares are printed as paired/warm. The grid tables use synthetic bases (random modes
/// on every interior face, random coefficients): kernel speed does not depend on the basis being
/// an eigenbasis, and a 64³ eigenbasis takes minutes to compute.
/// Run: bench_runtime [--device INDEX] [--repeat R] [--only contraction|steps|runtime|kernels].

#include <algorithm>
#include <array>
#include <memory>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "engine/dynamics/DenseCoefficients.h"
#include "engine/core/PackedLayout.h"
#include "engine/dynamics/SparseCoefficients.h"
#include "engine/device/DeviceCoefficients.h"
#include "engine/device/ForceProjection.h"
#include "engine/device/ModalKernels.h"
#include "engine/device/ModalStepper.h"
#include "engine/device/ModeBuffer.h"
#include "engine/device/VelocityReconstruction.h"
#include "engine/device/Simulation.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/VulkanContext.h"

namespace {

using namespace modeflow;
using namespace modeflow::device;
using namespace modeflow::vulkan;

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

/// Random coefficients, a random `density` share of them non-zero.
DenseCoefficients randomCoefficients(int n, double density = 1.0) {
    std::mt19937_64 rng(std::uint64_t(n) * 7919);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    std::bernoulli_distribution keep(density);
    std::vector<double> packed(packedSize(std::size_t(n)));
    for (double& c : packed) c = keep(rng) ? value(rng) : 0.0;
    return DenseCoefficients(n, std::move(packed));
}

/// Seconds of one call of `work`.
template <typename Work>
double secondsOf(Work work) {
    const auto start = std::chrono::steady_clock::now();
    work();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Eigen's float GEMV over the packed (pairs × N) row-major coefficient matrix, one call a run.
class PackedGemv {
public:
    explicit PackedGemv(const DenseCoefficients& c)
        : mPacked(c.packed().begin(), c.packed().end()),
          mRows(Eigen::Index(pairCount(std::size_t(c.size())))),
          mA(Eigen::VectorXf::Random(c.size())),
          mSums(mRows) {}
    double seconds() {
        const Eigen::Map<
            const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>
            matrix(mPacked.data(), mRows, mA.size());
        const double s = secondsOf([&] { mSums.noalias() = matrix * mA; });
        volatile float sink = mSums[0];
        (void)sink;
        return s;
    }

private:
    std::vector<float> mPacked;
    Eigen::Index mRows;
    Eigen::VectorXf mA, mSums;
};

/// Eigen's float sparse GEMV over the same rows in CSR (pairs × N, row-major), one call a run.
class SparseGemv {
public:
    explicit SparseGemv(const SparseCoefficients& c)
        : mMatrix(Eigen::Index(c.pairK().size()), c.size()), mA(Eigen::VectorXf::Random(c.size())) {
        std::vector<Eigen::Triplet<float>> entries;
        for (std::size_t r = 0; r < c.pairK().size(); ++r)
            for (std::size_t e = std::size_t(c.rowStart()[r]); e < std::size_t(c.rowStart()[r + 1]);
                 ++e)
                entries.emplace_back(int(r), int(c.columns()[e]), float(c.values()[e]));
        mMatrix.setFromTriplets(entries.begin(), entries.end());
        mSums.resize(mMatrix.rows());
    }
    double seconds() {
        const double s = secondsOf([&] { mSums.noalias() = mMatrix * mA; });
        volatile float sink = mSums[0];
        (void)sink;
        return s;
    }

private:
    Eigen::SparseMatrix<float, Eigen::RowMajor> mMatrix;
    Eigen::VectorXf mA, mSums;
};

/// Medians (ms) of `device()` (ms) and of `eigen()` (seconds), Eigen two ways: paired, each device
/// round followed by one Eigen run, so both meet the same machine (Eigen's data is then usually
/// out of the cache, as within a simulation step where other work runs between contractions);
/// and warm, Eigen's runs back to back after the rounds (its data in the cache where it fits: the
/// strictest comparison for small data).
struct Timings {
    double deviceMs = 0.0, eigenPairedMs = 0.0, eigenWarmMs = 0.0;
};
template <typename Device, typename Eigen>
Timings timings(int repeat, Device device, Eigen eigen) {
    std::vector<double> deviceMs, paired, warm;
    for (int r = 0; r < repeat; ++r) {
        deviceMs.push_back(device());
        paired.push_back(eigen() * 1e3);
    }
    for (int r = 0; r < repeat; ++r) warm.push_back(eigen() * 1e3);
    return {median(deviceMs), median(paired), median(warm)};
}

/// "paired/warm%": the device's rate as a share of Eigen's, both ways (same bytes, so a time
/// ratio).
std::string shares(double deviceMs, double eigenPairedMs, double eigenWarmMs) {
    char text[32];
    std::snprintf(text, sizeof text, "%.0f/%.0f%%", 100.0 * eigenPairedMs / deviceMs,
                  100.0 * eigenWarmMs / deviceMs);
    return text;
}

/// One row of the contraction table: the pair-sum pass of `c` on the device against `gemv` (an
/// Eigen GEMV over the same stored values).
template <typename Gemv>
void contractionRow(const VulkanContext& context, const ModalKernels& kernels, const char* storage,
                    const StructuralCoefficients& c, Gemv& gemv, int repeat) {
    const int n = c.size();
    const DeviceCoefficients device(context, c);
    const std::vector<float> ones(paddedSize(n), 1.0f);
    const DeviceBuffer a = DeviceBuffer::fromValues<float>(context, ones, "a");
    DeviceBuffer out(context, std::size_t(n) * sizeof(float), "out");
    std::vector<double> combines;
    const Timings t = timings(
        repeat,
        [&] {
            CommandSequence sequence(context, true, 2);
            device.recordApply(sequence, kernels, a, a, out);
            sequence.submitAndWait();
            combines.push_back(sequence.dispatchTimesMs()[1]);
            return sequence.dispatchTimesMs()[0];
        },
        [&] { return gemv.seconds(); });
    const double bytes = double(device.streamedBytes());
    std::printf("%-7s %5d %8.2f %12.3f %10.3f %9.2f %8.2f %6.2f %11s\n", storage, n, bytes * 1e-6,
                t.deviceMs, median(combines), bytes / t.deviceMs * 1e-6,
                bytes / t.eigenPairedMs * 1e-6, bytes / t.eigenWarmMs * 1e-6,
                shares(t.deviceMs, t.eigenPairedMs, t.eigenWarmMs).c_str());
}

void contractionTable(const VulkanContext& context, int repeat) {
    std::printf(
        "\nContraction out = C(a, b), float32 (GB/s over the coefficient bytes; sparse: 10%% of "
        "the\n"
        "entries, values and indices, against Eigen's sparse row-major GEMV)\n");
    std::printf("%-7s %5s %8s %12s %10s %9s %15s %11s\n", "storage", "N", "MB", "pair sums ms",
                "combine ms", "dev GB/s", "Eigen GB/s p/w", "share p/w");
    const ModalKernels kernels(context);
    for (const int n : {50, 100, 200}) {
        const DenseCoefficients c = randomCoefficients(n);
        PackedGemv gemv(c);
        contractionRow(context, kernels, "dense", c, gemv, repeat);
    }
    for (const int n : {100, 200}) {
        const SparseCoefficients c = SparseCoefficients::fromDense(randomCoefficients(n, 0.1));
        SparseGemv gemv(c);
        contractionRow(context, kernels, "sparse", c, gemv, repeat);
    }
}

void stepTable(const VulkanContext& context, int repeat) {
    std::printf("\nWhole modal steps on the device (GPU ms per step; midpoint: iterations per step)\n");
    std::printf("%5s %12s %12s %14s %10s\n", "N", "explicit ms", "rk4 ms", "midpoint ms", "iterations");
    for (const int n : {50, 100, 200}) {
        const DenseCoefficients c = randomCoefficients(n);
        std::mt19937_64 rng(5);
        std::normal_distribution<double> normal;
        Eigen::VectorXd v(n);
        for (double& x : v) x = normal(rng);
        Eigen::VectorXd r;
        c.apply(v, v, r);
        const double h = 0.1 * v.norm() / r.norm();  // a tenth of a turnover per step
        std::printf("%5d", n);
        int iterations = 0;
        for (const Integrator scheme : {Integrator::Explicit, Integrator::Rk4, Integrator::Midpoint}) {
            const ModalStepper stepper(context, c, {}, {scheme});
            const_cast<ModalStepper&>(stepper).setState(v);
            std::vector<double> perStep;
            for (int r2 = 0; r2 < repeat; ++r2) {
                CommandSequence sequence(context, true, std::uint32_t(stepper.dispatchesPerStep()));
                stepper.recordStep(sequence, h);
                sequence.submitAndWait();
                double total = 0.0;
                for (double t : sequence.dispatchTimesMs()) total += t;
                perStep.push_back(total);
            }
            if (scheme == Integrator::Midpoint) iterations = stepper.status().iterations;
            std::printf(scheme == Integrator::Midpoint ? " %14.3f" : " %12.3f", median(perStep));
        }
        std::printf(" %10d\n", iterations);
    }
}

/// A box grid with `modes` random unit-norm modes on every interior face and random dense
/// coefficients (see the file comment).
struct SyntheticScene {
    BasisCache cache;
    std::unique_ptr<DenseCoefficients> coefficients;
};

SyntheticScene syntheticScene(int dim, int cells, int modes) {
    SyntheticScene scene;
    BasisCache& cache = scene.cache;
    cache.grid.dim = dim;
    cache.grid.resolution = {cells, cells, dim == 3 ? cells : 1};
    cache.grid.boundsMin = {-1.0, -1.0, dim == 3 ? -1.0 : 0.0};
    cache.grid.boundsMax = {1.0, 1.0, dim == 3 ? 1.0 : 0.0};
    const MacGrid grid = MacGrid::fromSpec(cache.grid);
    std::vector<double> star;
    for (int axis = 0; axis < dim; ++axis) {
        const std::array<int, 3> e = grid.faceExtent(axis);
        for (int z = 0; z < e[2]; ++z)
            for (int y = 0; y < e[1]; ++y)
                for (int x = 0; x < e[0]; ++x) {
                    const std::array<int, 3> p{x, y, z};
                    if (p[axis] == 0 || p[axis] == grid.cells[axis]) continue;  // walls carry no flux
                    cache.faces.push_back(grid.faceIndex(axis, x, y, z));
                    star.push_back(grid.spacing[axis] / grid.faceArea(axis));
                }
    }
    cache.faceStar = Eigen::Map<const Eigen::VectorXd>(star.data(), Eigen::Index(star.size()));
    cache.velocity.modes = Eigen::MatrixXd::Random(Eigen::Index(star.size()), modes);
    cache.velocity.modes.colwise().normalize();
    cache.velocity.eigenvalues = Eigen::VectorXd::LinSpaced(modes, 1.0, double(modes));
    scene.coefficients = std::make_unique<DenseCoefficients>(randomCoefficients(modes));
    return scene;
}

/// Eigen's float GEMV Ψv (or Ψᵀx when `transposed`) over the DOFs × N basis, one call a run.
class BasisGemv {
public:
    BasisGemv(const Eigen::MatrixXd& modes, bool transposed)
        : mBasis(modes.cast<float>()),
          mTransposed(transposed),
          mIn(Eigen::VectorXf::Random(transposed ? modes.rows() : modes.cols())),
          mOut(transposed ? modes.cols() : modes.rows()) {}
    double seconds() {
        const double s = secondsOf([&] {
            if (mTransposed)
                mOut.noalias() = mBasis.transpose() * mIn;
            else
                mOut.noalias() = mBasis * mIn;
        });
        volatile float sink = mOut[0];
        (void)sink;
        return s;
    }

private:
    Eigen::MatrixXf mBasis;
    bool mTransposed;
    Eigen::VectorXf mIn, mOut;
};

/// The grids of the runtime and basis kernel tables.
struct Grid {
    const char* name;
    int dim, cells;
};
constexpr std::array<Grid, 3> kGrids{Grid{"256^2", 2, 256}, Grid{"48^3", 3, 48}, Grid{"64^3", 3, 64}};

void runtimeTable(const VulkanContext& context, int repeat) {
    std::printf("\nWhole runtime step (device::Simulation, midpoint, MacCormack, smoke scale 1, buoyancy + one emitter):\n"
                "GPU ms per step by stage; reconstruction GB/s over the float32 basis vs Eigen GEMV\n");
    std::printf("%-6s %4s %9s %8s %8s %6s %8s %8s %8s %9s %11s\n", "grid", "N", "DOFs", "forces",
                "modal", "iters", "recon", "advect", "step", "dev GB/s", "share p/w");
    for (const Grid& g : kGrids) {
        for (const int n : {50, 100, 200}) {
            const SyntheticScene scene = syntheticScene(g.dim, g.cells, n);
            SimulationSettings settings;
            settings.fluid.kappaSquared = scene.cache.velocity.eigenvalues;
            settings.buoyancy = 1.0;
            SmokeEmitter emitter;
            emitter.radius = 0.2;
            emitter.densityRate = emitter.temperatureRate = 1.0;
            settings.emitters = {emitter};
            const MacGrid smokeGrid = MacGrid::fromSpec(scene.cache.grid);
            const std::vector<std::uint8_t> mask(std::size_t(smokeGrid.cellCount()), 1);
            device::Simulation simulation(context, scene.cache, *scene.coefficients, settings, mask, true);
            Eigen::VectorXd v = Eigen::VectorXd::Random(n);
            Eigen::VectorXd r;
            scene.coefficients->apply(v, v, r);
            v *= 0.05 / (settings.dt * r.norm() / v.norm());  // a twentieth of a turnover per step
            simulation.setVelocity(v);
            simulation.advanceFrame();  // warm-up
            std::vector<double> forces, modal, advect, step;
            int iterations = 0;
            BasisGemv gemv(scene.cache.velocity.modes, false);
            const Timings t = timings(
                repeat,
                [&] {
                    const FrameStats stats = simulation.advanceFrame();
                    forces.push_back(stats.forcesMs);
                    modal.push_back(stats.modalMs);
                    advect.push_back(stats.advectionMs);
                    step.push_back(stats.forcesMs + stats.modalMs + stats.reconstructionMs +
                                   stats.advectionMs);
                    iterations = std::max(iterations, stats.maxIterations);
                    return stats.reconstructionMs;
                },
                [&] { return gemv.seconds(); });
            const double basisBytes = double(scene.cache.faces.size()) * n * sizeof(float);
            std::printf("%-6s %4d %9zu %8.2f %8.2f %6d %8.2f %8.2f %8.2f %9.2f %11s\n", g.name, n,
                        scene.cache.faces.size(), median(forces), median(modal), iterations,
                        t.deviceMs, median(advect), median(step), basisBytes / t.deviceMs * 1e-6,
                        shares(t.deviceMs, t.eigenPairedMs, t.eigenWarmMs).c_str());
            std::fflush(stdout);
        }
    }
}

/// The GPU ms of what `record` records (its dispatches summed), one submission.
template <typename Record>
double kernelMs(const VulkanContext& context, Record record) {
    CommandSequence sequence(context, true, 64);
    record(sequence);
    sequence.submitAndWait();
    double total = 0.0;
    for (const double t : sequence.dispatchTimesMs()) total += t;
    return total;
}

void kernelTable(const VulkanContext& context, int repeat) {
    std::printf("\nBasis kernels alone (GPU ms; GB/s over the float32 basis bytes vs Eigen's float GEMV, 1 thread):\n"
                "reconstruction Psi v (one dispatch), projection Psi^T (w q) (both passes), float32 and float16 modes\n");
    std::printf("%-6s %4s %9s | %8s %7s %10s %8s | %8s %7s %10s %8s\n", "grid", "N", "DOFs",
                "recon32", "GB/s", "share p/w", "recon16", "proj32", "GB/s", "share p/w", "proj16");
    for (const Grid& g : kGrids) {
        for (const int n : {50, 100, 200}) {
            const SyntheticScene scene = syntheticScene(g.dim, g.cells, n);
            const BasisCache& cache = scene.cache;
            const ReconstructionKernel reconstruction(context, cache);
            const ForceProjectionKernel projection(context, cache, FaceQuantity::Density);
            const std::vector<float> ones(std::size_t((n + 3) / 4 * 4), 1.0f);
            const DeviceBuffer v = DeviceBuffer::fromValues<float>(context, ones, "v");
            const DeviceBuffer field = reconstruction.makeFaceField();
            const std::vector<float> density(cache.faces.size(), 1.0f);
            const DeviceBuffer q = DeviceBuffer::fromValues<float>(context, density, "q");
            const DeviceBuffer f(context, std::size_t(n) * sizeof(float), "f");
            Timings recon[2], proj[2];
            BasisGemv reconGemv(cache.velocity.modes, false), projGemv(cache.velocity.modes, true);
            // The kernel `record` records, timed against `gemv`.
            const auto against = [&](BasisGemv& gemv, const auto& record) {
                return timings(
                    repeat, [&] { return kernelMs(context, record); },
                    [&] { return gemv.seconds(); });
            };
            for (const ModePrecision precision : {ModePrecision::Float32, ModePrecision::Float16}) {
                const ModeBuffer modes(context, cache.velocity.modes, precision);
                const int p = precision == ModePrecision::Float16;
                recon[p] = against(reconGemv, [&](CommandSequence& s) {
                    reconstruction.record(s, modes, v, field);
                });
                proj[p] = against(projGemv,
                                  [&](CommandSequence& s) { projection.record(s, modes, q, f); });
            }
            // The shares compare the float32 rounds with Eigen.
            const double bytes = double(cache.faces.size()) * n * sizeof(float);
            std::printf(
                "%-6s %4d %9zu | %8.2f %7.2f %10s %8.2f | %8.2f %7.2f %10s %8.2f\n", g.name, n,
                cache.faces.size(), recon[0].deviceMs, bytes / recon[0].deviceMs * 1e-6,
                shares(recon[0].deviceMs, recon[0].eigenPairedMs, recon[0].eigenWarmMs).c_str(),
                recon[1].deviceMs, proj[0].deviceMs, bytes / proj[0].deviceMs * 1e-6,
                shares(proj[0].deviceMs, proj[0].eigenPairedMs, proj[0].eigenWarmMs).c_str(),
                proj[1].deviceMs);
            std::fflush(stdout);
        }
    }
}

}  // namespace

int main(int argc, char** argv) {
    VulkanContextOptions options;
    int repeat = 20;
    std::string only;  // one table, or all
    for (int i = 1; i < argc; ++i) {
        if (i + 1 < argc && !std::strcmp(argv[i], "--only"))
            only = argv[++i];
        else if (i + 1 < argc && !std::strcmp(argv[i], "--device")) options.deviceIndex = std::uint32_t(std::atoi(argv[++i]));
        else if (i + 1 < argc && !std::strcmp(argv[i], "--repeat")) repeat = std::max(3, std::atoi(argv[++i]));
    }
    try {
        const VulkanContext context(options);
        std::printf("%s", context.describe().c_str());
        // The grid tables repeat less by default: each repetition is a whole step or dispatch
        // over a 64^3 grid.
        const int gridRepeat = only.empty() ? std::max(3, repeat / 4) : repeat;
        if (only.empty() || only == "contraction") contractionTable(context, repeat);
        if (only.empty() || only == "steps") stepTable(context, repeat);
        if (only.empty() || only == "runtime") runtimeTable(context, gridRepeat);
        if (only.empty() || only == "kernels") kernelTable(context, gridRepeat);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_runtime: %s\n", e.what());
        return 1;
    }
    return 0;
}
