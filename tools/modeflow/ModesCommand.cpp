#include <cmath>
#include <functional>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "engine/dynamics/CachedCoefficients.h"
#include "engine/dynamics/Diagnostics.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/MhdSystem.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "engine/format/CacheFile.h"
#include "engine/format/Error.h"
#include "engine/kernels/ModalStepper.h"
#include "engine/simulation/SimulationSettings.h"
#include "engine/vulkan/CommandSequence.h"
#include "precompute/Precompute.h"
#include "precompute/scene/SceneLoader.h"
#include "tools/modeflow/Commands.h"
#include "tools/modeflow/DeviceOption.h"
#include "tools/modeflow/InitialState.h"
#include "tools/modeflow/NumberOptions.h"

namespace modeflow::cli {
Command addModes(CLI::App& app) {
    struct Options {
        std::string scene;
        std::optional<std::string> cacheDir;
        std::optional<int> steps;
        std::optional<double> dt;
        std::optional<std::string> integrator;
        std::string device = "cpu";
        bool csv = false;
    };
    auto opts = std::make_shared<Options>();
    CLI::App* sub = app.add_subcommand(
        "modes", "Run the reduced dynamics alone (no grid) and print energy per step");
    sub->add_option("SCENE", opts->scene, "scene file (TOML)")->required();
    sub->add_option("--steps", opts->steps, "number of steps (default: frames × steps_per_frame)")
        ->check(countUpTo(kMaxSteps));
    sub->add_option("--dt", opts->dt, "time step (default: [simulation].dt)")
        ->check(finitePositive());
    sub->add_option("--integrator", opts->integrator,
                    "explicit | rk4 | midpoint | trapezoidal (default: [simulation].integrator)");
    sub->add_option("--device", opts->device, kDeviceHelp);
    sub->add_flag("--csv", opts->csv,
                  "CSV on stdout: step,time,energy,enstrophy,cross_helicity,iterations,residual");
    sub->add_option("--cache-dir", opts->cacheDir, "cache folder");
    return [sub, opts]() {
        if (!*sub) return -1;
        const auto deviceOptions = parseDevice(opts->device);
        const SceneSpec scene = loadScene(opts->scene);
        IntegratorSettings settings;
        // Checked before any precompute work.
        settings.scheme = opts->integrator ? parseIntegrator(*opts->integrator, "--integrator")
                                           : scene.simulation.integrator;
        Progress progress = Progress::toStderr();
        requireRuntimeSupport(scene, deviceOptions ? Runtime::Device : Runtime::CpuReference);
        if (deviceOptions && settings.scheme == Integrator::Trapezoidal)
            throw Error("--integrator trapezoidal runs on the CPU reference only; on a Vulkan device use explicit, "
                        "rk4 or midpoint");
        const auto cachePath = ensureCache(scene, resolveCacheDir(opts->cacheDir), false, progress).path;
        const BasisCache cache = readCache(cachePath);
        const auto coefficients = coefficientsFromCache(cache);
        const int n = coefficients->size();

        const SimulationSpec& sim = scene.simulation;
        const auto& k2 = cache.velocity.eigenvalues;
        std::unique_ptr<ModalSystem> system;
        Eigen::VectorXd x = initialVelocity(scene, cache, n);
        if (sim.mhd) {
            MhdParameters parameters{k2, sim.viscosity, sim.magneticDiffusivity};
            auto mhd = std::make_unique<MhdSystem>(*coefficients, parameters);
            x = mhd->state(x, initialMagneticField(scene, cache, n));
            system = std::move(mhd);
        } else {
            system = std::make_unique<FluidSystem>(
                *coefficients, FluidParameters{k2, sim.viscosity, sim.alpha});
        }
        const double h = opts->dt.value_or(sim.dt);
        const int steps = opts->steps.value_or(scene.output.frames * scene.output.stepsPerFrame);

        // One step of the chosen device; it updates x and says how the step went.
        std::function<StepReport()> advance;
        std::unique_ptr<vulkan::VulkanContext> context;
        std::unique_ptr<vulkan::ModalStepper> stepper;
        std::unique_ptr<vulkan::CommandSequence> sequence;
        ModalIntegrator integrator(*system, settings);
        if (deviceOptions) {
            context = std::make_unique<vulkan::VulkanContext>(*deviceOptions);
            std::cerr << context->describe();
            stepper = std::make_unique<vulkan::ModalStepper>(
                *context, *coefficients, FluidParameters{k2, sim.viscosity, sim.alpha},
                vulkan::DeviceStepSettings{settings.scheme});
            stepper->setState(x);
            sequence = std::make_unique<vulkan::CommandSequence>(*context);
            advance = [&]() {
                stepper->recordStep(*sequence, h);
                sequence->submitAndWait();
                x = stepper->state();
                const vulkan::DeviceStepStatus status = stepper->status();
                return StepReport{status.iterations, 0, status.residual, status.converged};
            };
        } else {
            advance = [&]() { return integrator.step(x, h); };
        }
        const bool twoD = cache.grid.dim == 2;
        // Conserved by the midpoint rule: ½Σ(1+α²κ²)v² (Euler, LANS-α) or ½(|v|²+|F|²) (MHD).
        auto totalEnergy = [&]() {
            return sim.mhd ? energy(x) : lansEnergy(x, k2, sim.alpha);
        };
        const double e0 = totalEnergy();

        auto row = [&](int step, const StepReport& r) {
            const double e = totalEnergy();
            const Eigen::VectorXd v = x.head(n);
            const double helicity = sim.mhd ? crossHelicity(v, x.tail(n)) : std::nan("");
            if (opts->csv) {
                std::printf("%d,%.17g,%.17g,%.17g,%.17g,%d,%.3e\n", step, step * h, e,
                            twoD ? enstrophy(v, k2) : std::nan(""), helicity, r.iterations,
                            r.residual);
            } else if (step % std::max(1, steps / 20) == 0 || step == steps) {
                std::printf("%8d  t=%-10.4g energy %.15g  (drift %+.2e)", step, step * h, e,
                            e0 > 0 ? e / e0 - 1.0 : 0.0);
                if (sim.mhd) std::printf("  cross helicity %.15g", helicity);
                std::printf("  iterations %d\n", r.iterations);
            }
        };
        if (opts->csv)
            std::printf("step,time,energy,enstrophy,cross_helicity,iterations,residual\n");
        else
            std::printf("%d modes%s, %s, dt %g, %d steps\n", n, sim.mhd ? " (MHD)" : "",
                        std::string(sceneKeyword(settings.scheme)).c_str(), h, steps);
        row(0, StepReport{});
        int unconverged = 0;
        for (int s = 1; s <= steps; ++s) {
            const StepReport r = advance();
            unconverged += !r.converged;
            row(s, r);
            if (!x.allFinite())
                throw Error("the modal state diverged at step " + std::to_string(s) + " (t = " +
                            std::to_string(s * h) + "); " +
                            std::string(sceneKeyword(settings.scheme)) +
                            " is unstable at this step size: lower --dt or use midpoint");
        }
        std::fflush(stdout);
        if (context && context->validationMessageCount() > 0)
            throw Error("the Vulkan validation layer reported " + std::to_string(context->validationMessageCount()) +
                        " problems; the first: " + context->validationMessages().front());
        if (unconverged)
            std::cerr << "warning: the " << (deviceOptions ? "fixed-point" : "Newton")
                      << " iteration did not converge in " << unconverged << " steps; try a smaller --dt\n";
        return 0;
    };
}

}  // namespace modeflow::cli
