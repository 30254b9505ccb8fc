#include "engine/pipeline/InitialState.h"

#include <string>
#include <utility>
#include <vector>

#include "engine/dynamics/InitialConditions.h"
#include "engine/core/Error.h"
#include "precompute/initial/UniformField.h"
#include "precompute/initial/VortexProjection.h"

namespace modeflow {

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

Eigen::VectorXd initialMagneticField(const SceneSpec& scene, const BasisCache& cache, int modes) {
    const InitialSpec& init = scene.initial;
    if (init.magnetic == InitialMagnetic::Random) {
        RandomVelocitySpec field;
        field.energy = init.magneticEnergy;
        field.seed = init.magneticSeed;
        return randomVelocity(modes, field);
    }
    try {
        const double layer = init.magneticWallLayer > 0.0 ? init.magneticWallLayer : uniformFieldLayer(cache);
        const UniformField field(cache, scene.domain, init.magneticDirection, init.magneticStrength, layer);
        return projectUniformField(cache, field);
    } catch (const Error& e) {
        throw Error(scene.sourceFile.string() + ": [initial].magnetic: " + e.what());
    }
}

}  // namespace modeflow
