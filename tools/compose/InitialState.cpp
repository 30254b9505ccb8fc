#include "tools/compose/InitialState.h"

#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "engine/core/Error.h"
#include "engine/dynamics/InitialConditions.h"
#include "precompute/initial/UniformField.h"
#include "precompute/initial/VortexProjection.h"

namespace modeflow {
namespace {

/// `build()`'s state, checked (requireRepresentableState); any refusal names `key`, the scene
/// key that sets the state's size.
Eigen::VectorXd keyed(const std::string& key, const std::function<Eigen::VectorXd()>& build) {
    Eigen::VectorXd state;
    try {
        state = build();
    } catch (const Error& e) {
        throw Error(key + ": " + e.what());
    }
    requireRepresentableState(state, key);
    return state;
}

}  // namespace

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
            return keyed(where + "energy", [&] { return randomVelocity(modes, spec); });
        }
        case InitialVelocity::Modes: {
            std::vector<std::pair<int, double>> amplitudes;
            for (const auto& [mode, amplitude] : init.amplitudes) {
                if (mode < 1 || mode > modes)
                    throw Error(where + "amplitudes: mode " + std::to_string(mode) +
                                " is outside the basis (modes 1 to " + std::to_string(modes) + ")");
                amplitudes.emplace_back(mode - 1, amplitude);
            }
            return keyed(where + "amplitudes", [&] { return modalAmplitudes(modes, amplitudes); });
        }
        case InitialVelocity::Vortices: {
            Eigen::VectorXd v;
            try {
                v = projectVortices(cache, init.vortices, init.energy);
            } catch (const Error& e) {
                throw Error(scene.sourceFile.string() + ": " + e.what());
            }
            const char* size = init.energy > 0.0 ? "[[initial.vortex]].strength or [initial].energy"
                                                 : "[[initial.vortex]].strength";
            return keyed(scene.sourceFile.string() + ": " + size, [&] { return v; });
        }
    }
    throw Error(where + "velocity: unknown choice");
}

Eigen::VectorXd initialMagneticField(const SceneSpec& scene, const BasisCache& cache, int modes) {
    const InitialSpec& init = scene.initial;
    if (init.magnetic == InitialMagnetic::Random) {
        RandomVelocitySpec field;
        field.energy = init.magneticEnergy;
        field.seed = init.magneticSeed;
        const std::string where = scene.sourceFile.string() + ": [initial].magnetic_energy";
        return keyed(where, [&] { return randomVelocity(modes, field); });
    }
    Eigen::VectorXd f;
    try {
        const double layer =
            init.magneticWallLayer > 0.0 ? init.magneticWallLayer : uniformFieldLayer(cache);
        const UniformField field(cache, scene.domain, init.magneticDirection, init.magneticStrength,
                                 layer);
        f = projectUniformField(cache, field);
    } catch (const Error& e) {
        throw Error(scene.sourceFile.string() + ": [initial].magnetic: " + e.what());
    }
    return keyed(scene.sourceFile.string() + ": [initial].magnetic_strength", [&] { return f; });
}

}  // namespace modeflow
