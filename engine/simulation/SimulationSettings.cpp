#include "engine/simulation/SimulationSettings.h"

#include <string>

#include "engine/core/Error.h"

namespace modeflow {

SimulationSettings SimulationSettings::fromScene(const SceneSpec& scene, const BasisCache& cache) {
    const SimulationSpec& sim = scene.simulation;
    if (scene.sources.size() > std::size_t(maxSmokeEmitters))
        throw Error(scene.sourceFile.string() + ": " + std::to_string(scene.sources.size()) +
                    " [[source]] entries; the runtime takes at most " +
                    std::to_string(maxSmokeEmitters));
    SimulationSettings settings;
    settings.dt = sim.dt;
    settings.stepsPerFrame = scene.output.stepsPerFrame;
    settings.integrator = sim.integrator;
    settings.fluid = {cache.velocity.eigenvalues, sim.viscosity, sim.alpha};
    settings.mhd = sim.mhd;
    settings.magneticDiffusivity = sim.magneticDiffusivity;
    settings.buoyancy = scene.smoke.buoyancy;
    settings.smokeScale = scene.smoke.resolutionScale;
    settings.advection = scene.smoke.advection;
    settings.basisPrecision =
        sim.halfPrecisionBasis ? ModePrecision::Float16 : ModePrecision::Float32;
    for (const SourceSpec& source : scene.sources)
        settings.emitters.push_back(emitterFromSource(source));
    if (scene.obstacles.size() > std::size_t(maxObstacles))
        throw Error(scene.sourceFile.string() + ": " + std::to_string(scene.obstacles.size()) +
                    " [[obstacle]] entries; the runtime takes at most " + std::to_string(maxObstacles));
    for (const ObstacleSpec& obstacle : scene.obstacles) settings.obstacles.push_back({obstacle});
    return settings;
}

bool SimulationSettings::simulatesTemperature() const {
    if (buoyancy != 0.0) return true;
    for (const SmokeEmitter& emitter : emitters)
        if (emitter.temperatureRate != 0.0) return true;
    return false;
}

}  // namespace modeflow
