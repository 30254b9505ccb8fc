#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "engine/dynamics/DenseCoefficients.h"
#include "engine/dynamics/Diagnostics.h"
#include "engine/dynamics/FluidSystem.h"
#include "engine/dynamics/InitialConditions.h"
#include "engine/dynamics/ModalIntegrator.h"
#include "engine/dynamics/SparseCoefficients.h"
#include "engine/format/CacheFile.h"
#include "engine/format/Error.h"
#include "precompute/Precompute.h"
#include "precompute/initial/VortexProjection.h"
#include "precompute/scene/SceneLoader.h"
#include "tools/modeflow/Commands.h"

namespace modeflow::cli {
namespace {

std::unique_ptr<StructuralCoefficients> loadCoefficients(const BasisCache& cache) {
    const auto& c = cache.coefficients;
    const int n = int(cache.velocity.modes.cols());
    if (c.storage == BasisCache::Coefficients::Storage::Dense)
        return std::make_unique<DenseCoefficients>(n, c.packed);
    std::vector<CoefficientEntry> entries(c.value.size());
    for (size_t e = 0; e < entries.size(); ++e) entries[e] = {c.k[e], c.i[e], c.j[e], c.value[e]};
    return std::make_unique<SparseCoefficients>(n, std::move(entries));
}

TimeScheme schemeOf(Integrator integrator) {
    return parseTimeScheme(sceneKeyword(integrator));
}

/// The scene's [initial] velocity as a modal state on this basis. Mode numbers in the scene are
/// 1-based positions in the basis; the engine takes 0-based ones.
Eigen::VectorXd initialVelocity(const SceneSpec& scene, const BasisCache& cache, int modes) {
    const InitialSpec& init = scene.initial;
    const std::string where = scene.sourceFile.string() + ": [initial].";
    switch (init.velocity) {
        case InitialVelocity::Zero:
            return Eigen::VectorXd::Zero(modes);
        case InitialVelocity::Random: {
            RandomVelocitySpec spec;
            spec.energy = init.energy;
            spec.seed = init.seed;
            if (init.band) {
                // The loader checks the band against [basis]; a cache is checked again because
                // the engine's message would not name the key.
                if (init.band->last > modes)
                    throw Error(where + "band: mode " + std::to_string(init.band->last) +
                                " is beyond the basis (" + std::to_string(modes) + " modes)");
                spec.firstMode = init.band->first - 1;
                spec.lastMode = init.band->last - 1;
            }
            return randomVelocity(modes, spec);
        }
        case InitialVelocity::Modes: {
            std::vector<std::pair<int, double>> amplitudes;
            for (const auto& [mode, amplitude] : init.amplitudes) {
                if (mode < 1 || mode > modes)
                    throw Error(where + "amplitudes: mode " + std::to_string(mode) +
                                " is outside the basis (modes 1 to " + std::to_string(modes) +
                                ")");
                amplitudes.emplace_back(mode - 1, amplitude);
            }
            return modalAmplitudes(modes, amplitudes);
        }
        case InitialVelocity::Vortices:
            try {
                return projectVortices(cache, init.vortices, init.energy);
            } catch (const Error& e) {
                throw Error(scene.sourceFile.string() + ": " + e.what());
            }
    }
    throw Error(where + "velocity: unknown choice");
}

}  // namespace

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
        ->check(CLI::PositiveNumber);
    sub->add_option("--dt", opts->dt, "time step (default: [simulation].dt)")
        ->check(CLI::PositiveNumber);
    sub->add_option("--integrator", opts->integrator,
                    "explicit | rk4 | midpoint | trapezoidal (default: [simulation].integrator)");
    sub->add_option("--device", opts->device, "cpu (double-precision reference)");
    sub->add_flag("--csv", opts->csv, "CSV on stdout: step,time,energy,enstrophy,iterations,residual");
    sub->add_option("--cache-dir", opts->cacheDir, "cache folder");
    return [sub, opts]() {
        if (!*sub) return -1;
        if (opts->device != "cpu")
            throw Error("--device " + opts->device +
                        ": only the CPU reference runs the reduced dynamics so far");
        const SceneSpec scene = loadScene(opts->scene);
        IntegratorSettings settings;
        // Checked before any precompute work.
        settings.scheme = opts->integrator ? parseTimeScheme(*opts->integrator)
                                           : schemeOf(scene.simulation.integrator);
        Progress progress = Progress::toStderr();
        const auto cachePath = ensureCache(scene, resolveCacheDir(opts->cacheDir), false, progress).path;
        const BasisCache cache = readCache(cachePath);
        const auto coefficients = loadCoefficients(cache);
        const int n = coefficients->size();

        FluidParameters parameters;
        parameters.kappaSquared = cache.velocity.eigenvalues;
        parameters.viscosity = scene.simulation.viscosity;
        parameters.alpha = scene.simulation.alpha;
        const FluidSystem system(*coefficients, parameters);
        ModalIntegrator integrator(system, settings);

        const double h = opts->dt.value_or(scene.simulation.dt);
        const int steps = opts->steps.value_or(scene.output.frames * scene.output.stepsPerFrame);
        Eigen::VectorXd v = initialVelocity(scene, cache, n);
        const auto& k2 = cache.velocity.eigenvalues;
        const bool twoD = cache.grid.dim == 2;
        const double e0 = lansEnergy(v, k2, scene.simulation.alpha);

        auto row = [&](int step, const StepReport& r) {
            const double e = lansEnergy(v, k2, scene.simulation.alpha);
            if (opts->csv) {
                std::printf("%d,%.17g,%.17g,%.17g,%d,%.3e\n", step, step * h, e,
                            twoD ? enstrophy(v, k2) : std::nan(""), r.iterations, r.residual);
            } else if (step % std::max(1, steps / 20) == 0 || step == steps) {
                std::printf("%8d  t=%-10.4g energy %.15g  (drift %+.2e)  newton %d\n", step,
                            step * h, e, e0 > 0 ? e / e0 - 1.0 : 0.0, r.iterations);
            }
        };
        if (opts->csv) std::printf("step,time,energy,enstrophy,iterations,residual\n");
        else
            std::printf("%d modes, %s, dt %g, %d steps\n", n,
                        std::string(timeSchemeName(settings.scheme)).c_str(), h, steps);
        row(0, StepReport{});
        int unconverged = 0;
        for (int s = 1; s <= steps; ++s) {
            const StepReport r = integrator.step(v, h);
            unconverged += !r.converged;
            row(s, r);
            if (!v.allFinite())
                throw Error("the modal state diverged at step " + std::to_string(s) + " (t = " +
                            std::to_string(s * h) + "); " +
                            std::string(timeSchemeName(settings.scheme)) +
                            " is unstable at this step size: lower --dt or use midpoint");
        }
        std::fflush(stdout);
        if (unconverged)
            std::cerr << "warning: Newton did not converge in " << unconverged
                      << " steps; try a smaller --dt\n";
        return 0;
    };
}

}  // namespace modeflow::cli
