/// @file SpeedStudy.cpp
/// `speed`: the wall time of one reduced-dynamics step on the CPU reference (one thread) at 50,
/// 100 and 200 modes, dense coefficients (the unit disk) and sparse ones (a box), against the
/// seed's published figures per step (seedDense, seedSparse below; seed §6.4, an Intel i7 laptop;
/// tools/validate/README.md). Timings vary with the machine's load; they are measured
/// here, never asserted.

#include <algorithm>
#include <chrono>
#include <string>
#include <vector>

#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "engine/dynamics/ShapedBases.h"
#include "engine/dynamics/SparseCoefficients.h"
#include "tools/validate/Studies.h"
#include "tools/validate/StudyRuns.h"

namespace modeflow::validate {
namespace {

std::string speedScene(bool disk, int modes) {
    std::string text =
        "[grid]\nresolution = [32, 32]\nbounds_min = [-1.1, -1.1]\nbounds_max = [1.1, 1.1]\n";
    if (disk) text += "[[domain]]\nshape = \"ball\"\ncenter = [0.0, 0.0]\nradius = 1.0\n";
    return text + "[basis]\nvelocity_modes = " + std::to_string(modes) +
           "\nscalar_modes = 0\n[initial]\nvelocity = \"random\"\nenergy = 1.0\nseed = 11\n";
}

/// Median seconds per step of `scheme` over at least `budget` seconds and 5 steps, at a step of
/// 0.1 |v| / |R(v)| (a typical step: a few Newton iterations), and the mean iterations.
std::pair<double, double> secondsPerStep(const FluidSystem& system, const Eigen::VectorXd& v0,
                                         Integrator scheme, double budget) {
    Eigen::VectorXd rate;
    system.rhs(v0, rate);
    const double h = 0.1 * v0.norm() / rate.norm();
    ModalIntegrator integrator(system, {.scheme = scheme});
    Eigen::VectorXd v = v0;
    std::vector<double> times;
    double spent = 0.0, iterations = 0.0;
    while (spent < budget || times.size() < 5) {
        const auto start = std::chrono::steady_clock::now();
        iterations += integrator.step(v, h).iterations;
        times.push_back(
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        spent += times.back();
    }
    std::nth_element(times.begin(), times.begin() + std::ptrdiff_t(times.size() / 2), times.end());
    return {times[times.size() / 2], iterations / double(times.size())};
}

}  // namespace

StudyResult speedStudy(const StudyOptions& options) {
    const std::vector<int> counts =
        options.quick ? std::vector<int>{50, 100} : std::vector<int>{50, 100, 200};
    const double budget = options.quick ? 0.2 : 1.0;
    // Seed §6.4: seconds per step at 50, 100, 200 modes.
    const std::vector<double> seedDense = {0.098, 0.65, 2.0}, seedSparse = {0.026, 0.070, 0.28};
    StudyResult result;
    result.data["threads"] = 1;
    result.data["rows"] = nlohmann::json::array();
    double headline = 0.0;
    for (const bool disk : {true, false}) {
        // One basis of the most modes; the fewer modes are its leading ones.
        const RunInputs run = prepareStudyRun(
            sceneFromText(speedScene(disk, counts.back()), disk ? "speed_disk" : "speed_box"),
            options, RunParts::Dynamics);
        for (std::size_t c = 0; c < counts.size(); ++c) {
            const int n = counts[c];
            const char* storage = disk ? "dense" : "sparse";
            options.note(std::string(storage) + ", " + std::to_string(n) + " modes");
            std::unique_ptr<StructuralCoefficients> coefficients =
                leadingCoefficients(*run.coefficients, n);
            // Sparse keeps what the precompute keeps: |C| above 1e-12 of the largest.
            if (!disk)
                coefficients = std::make_unique<SparseCoefficients>(SparseCoefficients::fromDense(
                    static_cast<const DenseCoefficients&>(*coefficients), 1e-12));
            const FluidSystem system(*coefficients);
            const Eigen::VectorXd v0 = run.initialVelocity.head(n);
            const auto [midpoint, iterations] =
                secondsPerStep(system, v0, Integrator::Midpoint, budget);
            const double explicitStep =
                secondsPerStep(system, v0, Integrator::Explicit, budget).first;
            const double seed = (disk ? seedDense : seedSparse)[c];
            result.data["rows"].push_back({{"storage", storage},
                                           {"domain", disk ? "unit disk 32²" : "box 32²"},
                                           {"modes", n},
                                           {"stored_bytes", coefficients->storedBytes()},
                                           {"midpoint_seconds", midpoint},
                                           {"midpoint_iterations", iterations},
                                           {"explicit_seconds", explicitStep},
                                           {"seed_seconds", seed},
                                           {"speedup", seed / midpoint}});
            if (disk && c + 1 == counts.size()) headline = seed / midpoint;
        }
    }
    result.headline = {
        "the seed's step time / ours, " + std::to_string(counts.back()) + " dense modes, midpoint",
        headline, "above 1 (measured, never asserted: timings vary with the machine)",
        headline > 1.0};
    return result;
}

}  // namespace modeflow::validate
