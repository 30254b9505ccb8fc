/// @file BenchRuntime.cpp
/// Speed of the Vulkan runtime's modal kernels (issue 4), as a table: for N = 50, 100, 200 the GPU
/// time of the dense pair-sum pass (the bandwidth-bound GEMV over the packed coefficients) and of
/// the combine pass, their GB/s over the float32 coefficient bytes, and the same contraction by
/// Eigen's GEMV on the same float32 data in the same run (1 thread), as a ratio; then the GPU time
/// of whole steps per scheme. Times are medians over repeated dispatches in one submission.
/// Run: bench_runtime [--device INDEX] [--repeat R].

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/PackedLayout.h"
#include "engine/kernels/DeviceCoefficients.h"
#include "engine/kernels/ModalKernels.h"
#include "engine/kernels/ModalStepper.h"
#include "engine/vulkan/CommandSequence.h"
#include "engine/vulkan/VulkanContext.h"

namespace {

using namespace modeflow;
using namespace modeflow::vulkan;

double median(std::vector<double> values) {
    std::sort(values.begin(), values.end());
    return values.empty() ? 0.0 : values[values.size() / 2];
}

DenseCoefficients randomCoefficients(int n) {
    std::mt19937_64 rng(std::uint64_t(n) * 7919);
    std::uniform_real_distribution<double> value(-1.0, 1.0);
    std::vector<double> packed(packedSize(std::size_t(n)));
    for (double& c : packed) c = value(rng);
    return DenseCoefficients(n, std::move(packed));
}

/// Median seconds of Eigen's float GEMV over the packed (pairs × N) row-major matrix.
double eigenGemvSeconds(const DenseCoefficients& c, int repeat) {
    const int n = c.size();
    const auto rows = Eigen::Index(pairCount(std::size_t(n)));
    const std::vector<float> packed(c.packed().begin(), c.packed().end());
    const Eigen::Map<const Eigen::Matrix<float, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> matrix(
        packed.data(), rows, n);
    const Eigen::VectorXf a = Eigen::VectorXf::Random(n);
    Eigen::VectorXf sums(rows);
    std::vector<double> seconds;
    for (int r = 0; r < repeat; ++r) {
        const auto start = std::chrono::steady_clock::now();
        sums.noalias() = matrix * a;
        seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    volatile float sink = sums.sum();
    (void)sink;
    return median(seconds);
}

void contractionTable(const VulkanContext& context, int repeat) {
    std::printf("\nDense contraction out = C(a, b), float32 (GB/s over the coefficient bytes)\n");
    std::printf("%5s %10s %12s %10s %12s %12s %8s\n", "N", "MB", "pair sums ms", "combine ms", "device GB/s",
                "Eigen GB/s", "ratio");
    const ModalKernels kernels(context);
    for (const int n : {50, 100, 200}) {
        const DenseCoefficients c = randomCoefficients(n);
        const DeviceCoefficients device(context, c);
        const std::vector<float> ones(paddedSize(n), 1.0f);
        const DeviceBuffer a = DeviceBuffer::fromValues<float>(context, ones, "a");
        DeviceBuffer out(context, std::size_t(n) * sizeof(float), "out");
        CommandSequence sequence(context, true, std::uint32_t(2 * repeat));
        for (int r = 0; r < repeat; ++r) device.recordApply(sequence, kernels, a, a, out);
        sequence.submitAndWait();
        std::vector<double> sums, combines;
        for (int r = 0; r < repeat; ++r) {
            sums.push_back(sequence.dispatchTimesMs()[2 * r]);
            combines.push_back(sequence.dispatchTimesMs()[2 * r + 1]);
        }
        const double bytes = double(device.streamedBytes());
        const double deviceSeconds = median(sums) * 1e-3;
        const double eigenSeconds = eigenGemvSeconds(c, repeat);
        const double deviceRate = bytes / deviceSeconds * 1e-9, eigenRate = bytes / eigenSeconds * 1e-9;
        std::printf("%5d %10.2f %12.3f %10.3f %12.2f %12.2f %7.0f%%\n", n, bytes * 1e-6, median(sums),
                    median(combines), deviceRate, eigenRate, 100.0 * deviceRate / eigenRate);
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

}  // namespace

int main(int argc, char** argv) {
    VulkanContextOptions options;
    int repeat = 20;
    for (int i = 1; i + 1 < argc; i += 2) {
        if (!std::strcmp(argv[i], "--device")) options.deviceIndex = std::uint32_t(std::atoi(argv[i + 1]));
        else if (!std::strcmp(argv[i], "--repeat")) repeat = std::max(3, std::atoi(argv[i + 1]));
    }
    try {
        const VulkanContext context(options);
        std::printf("%s", context.describe().c_str());
        contractionTable(context, repeat);
        stepTable(context, repeat);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_runtime: %s\n", e.what());
        return 1;
    }
    return 0;
}
