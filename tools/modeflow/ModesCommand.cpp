#include <cmath>
#include <cstdio>
#include <functional>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/Error.h"
#include "engine/core/KappaSquared.h"
#include "engine/core/SceneKeywords.h"
#include "engine/dynamics/Diagnostics.h"
#include "engine/dynamics/ModalDivergence.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "engine/run/Backend.h"
#include "precompute/scene/SceneLoader.h"
#include "tools/compose/CacheDirectory.h"
#include "tools/compose/Preflight.h"
#include "tools/modeflow/Commands.h"
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
                    "explicit | rk4 | midpoint | trapezoidal | linearized (default: "
                    "[simulation].integrator)");
    sub->add_option("--device", opts->device, kDeviceOptionHelp);
    sub->add_flag("--csv", opts->csv,
                  "CSV on stdout: step,time,energy,enstrophy,cross_helicity,iterations,residual");
    sub->add_option("--cache-dir", opts->cacheDir, "cache folder");
    return [sub, opts]() {
        if (!*sub) return -1;
        // Checked before any precompute work.
        const Preflight checked = preflight(opts->scene, opts->device, RunParts::Dynamics);
        const BackendChoice& choice = checked.backend;
        const SceneSpec& scene = checked.scene;
        const Integrator scheme = opts->integrator
                                      ? parseIntegrator(*opts->integrator, "--integrator")
                                      : scene.simulation.integrator;
        if (scheme == Integrator::Linearized && scene.simulation.mhd)
            throw Error(std::string("--integrator: ") + kLinearizedNeedsAFluid);
        const Backend backend(choice);
        std::cerr << backend.describe();
        backend.requireFits(scene);
        Progress progress = Progress::toStderr();
        const RunInputs run =
            prepareRun(scene, resolveCacheDir(opts->cacheDir), progress, RunParts::Dynamics);
        const int n = run.modeCount();
        const SimulationSpec& sim = scene.simulation;
        const Eigen::VectorXd k2 = checkedKappaSquared(run.cache.velocity.eigenvalues, "modes");
        const double h = opts->dt.value_or(sim.dt);
        const int steps = opts->steps.value_or(scene.output.frames * scene.output.stepsPerFrame);
        const std::unique_ptr<ModalStepping> stepper = backend.makeModalStepper(run, scheme);
        Eigen::VectorXd x = stepper->state();

        // Surfaces carry 2D flows: their vorticity is a scalar too.
        const bool twoD = run.cache.kind == BasisKind::Surface || run.cache.grid.dim == 2;
        // Conserved by the midpoint rule: ½Σ(1+α²κ²)v² (Euler, LANS-α) or ½(|v|²+|F|²) (MHD).
        auto totalEnergy = [&]() { return sim.mhd ? energy(x) : lansEnergy(x, k2, sim.alpha); };
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
                        std::string(sceneKeyword(scheme)).c_str(), h, steps);
        row(0, StepReport{});
        int unconverged = 0;
        for (int s = 1; s <= steps; ++s) {
            const StepReport r = stepper->step(h);
            x = stepper->state();
            unconverged += !r.converged;
            row(s, r);
            try {
                requireFiniteModalState(x, s, s * h);
            } catch (const ModalStateDiverged& e) {
                throw Error(divergenceAdvice(e, sceneKeyword(scheme), "--dt"));
            }
        }
        std::fflush(stdout);
        backend.requireCleanValidation();
        if (unconverged)
            std::cerr << "warning: the "
                      << (backend.kind() == BackendKind::Vulkan ? "fixed-point" : "Newton")
                      << " iteration did not converge in " << unconverged
                      << " steps; try a smaller --dt\n";
        return 0;
    };
}

}  // namespace modeflow::cli
