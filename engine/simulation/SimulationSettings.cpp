#include "engine/simulation/SimulationSettings.h"

#include <algorithm>
#include <cmath>
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
    settings.fluid = {cache.velocity.eigenvalues, sim.viscosity, sim.alpha,
                      heldModes(scene, cache)};
    settings.mhd = sim.mhd;
    settings.magneticDiffusivity = sim.magneticDiffusivity;
    settings.buoyancy = scene.smoke.buoyancy;
    settings.smokeScale = scene.smoke.resolutionScale;
    settings.advection = scene.smoke.advection;
    settings.fire = scene.fire;
    settings.wind = scene.wind;
    settings.basisPrecision =
        sim.halfPrecisionBasis ? ModePrecision::Float16 : ModePrecision::Float32;
    for (const SourceSpec& source : scene.sources)
        settings.emitters.push_back(emitterFromSource(source));
    if (scene.obstacles.size() > std::size_t(maxObstacles))
        throw Error(scene.sourceFile.string() + ": " + std::to_string(scene.obstacles.size()) +
                    " [[obstacle]] entries; the runtime takes at most " +
                    std::to_string(maxObstacles));
    for (const ObstacleSpec& obstacle : scene.obstacles) settings.obstacles.push_back({obstacle});
    if (scene.inflows.size() > std::size_t(maxInflows))
        throw Error(scene.sourceFile.string() + ": " + std::to_string(scene.inflows.size()) +
                    " [[inflow]] entries; the runtime takes at most " + std::to_string(maxInflows));
    for (const InflowSpec& inflow : scene.inflows)
        settings.inflows.push_back(inflowFromSpec(inflow));
    settings.particles = scene.particles;
    settings.shotEnd = double(scene.output.frames) * scene.output.stepsPerFrame * sim.dt;
    return settings;
}

std::vector<int> heldModes(const SceneSpec& scene, const BasisCache& cache) {
    const ForcingSpec& forcing = scene.forcing;
    if (!forcing.holds()) return {};
    const auto n = int(cache.velocity.eigenvalues.size());
    std::vector<int> held;
    std::string key;
    if (!forcing.holdModes.empty()) {
        key = "[forcing].hold_modes";
        for (const ModeRange& range : forcing.holdModes)
            for (int m = range.first; m <= range.last && m <= n; ++m) held.push_back(m - 1);
    } else {
        key = "[forcing].hold_below_kappa";
        const double limit = forcing.holdBelowKappa * forcing.holdBelowKappa;
        for (int k = 0; k < n; ++k)
            if (cache.velocity.eigenvalues[k] < limit) held.push_back(k);
    }
    const std::string file = scene.sourceFile.empty() ? scene.name : scene.sourceFile.string();
    if (held.empty())
        throw Error(
            file + ": " + key + " holds none of the basis's " + std::to_string(n) +
            " modes (the lowest has κ = " +
            std::to_string(std::sqrt(std::max(0.0, cache.velocity.eigenvalues.minCoeff()))) + ")");
    if (int(held.size()) == n)
        throw Error(file + ": " + key + " holds all " + std::to_string(n) +
                    " modes of the basis: nothing would move");
    return held;
}

std::vector<MovingObstacle> SimulationSettings::velocityRegions(double t) const {
    std::vector<MovingObstacle> regions = obstacles;
    const auto drive = [&](const SmokeEmitter& emitter) {
        if (!emitter.velocity || !emitter.activeAt(t)) return;
        // Its shape about its rest centre, moved and turned by its own key frames.
        ObstacleSpec region;
        std::shared_ptr<const SolidLevelSet> levelSet;
        switch (emitter.shape) {
            case EmitterShape::Mesh:  // world coordinates: a mesh whose centre is the origin
                region.shape = ObstacleShape::Mesh;
                levelSet = emitter.levelSet;
                break;
            case EmitterShape::Box:
                region.shape = ObstacleShape::Box;
                for (int a = 0; a < 3; ++a)
                    region.halfSize[a] = 0.5 * (emitter.max[a] - emitter.min[a]);
                break;
            case EmitterShape::Ball:
                region.shape = ObstacleShape::Ball;
                region.radius = emitter.radius;
                break;
        }
        region.path = emitter.path.empty()
                          ? std::vector<std::pair<double, Vec3>>{{0.0, emitter.restCentre()}}
                          : emitter.path;
        region.rotation = emitter.rotation;
        MovingObstacle jet(region, levelSet);
        jet.drive = emitter.velocity;
        regions.push_back(std::move(jet));
    };
    for (const SmokeEmitter& emitter : emitters) drive(emitter);
    for (const InflowPatch& inflow : inflows) drive(inflow.region);
    return regions;
}

bool SimulationSettings::simulatesTemperature() const {
    if (buoyancy != 0.0 || fire) return true;
    for (const SmokeEmitter& emitter : emitters)
        if (emitter.temperatureRate != 0.0) return true;
    return false;
}

}  // namespace modeflow
