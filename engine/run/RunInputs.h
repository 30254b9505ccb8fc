#pragma once
/// @file RunInputs.h
/// Everything a simulation of a scene needs: the basis cache, its structural coefficients, the
/// run's settings, the smoke mask and the initial state. Made by the composition
/// (tools/compose/RunPreparation.h: from a scene and a cache folder, precomputing on a miss);
/// Backend makes the simulation from it.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "engine/core/SceneSpec.h"
#include "engine/dynamics/StructuralCoefficients.h"
#include "engine/format/BasisCache.h"
#include "engine/simulation/SimulationSettings.h"

namespace modeflow {

struct RunInputs {
    SceneSpec scene;
    std::filesystem::path cachePath;  ///< the cache file the basis came from (empty: in memory)
    BasisCache cache;                 ///< without its tensor, which moved into `coefficients`
    std::unique_ptr<StructuralCoefficients> coefficients;
    SimulationSettings settings;
    std::vector<std::uint8_t> smokeMask;  ///< one byte per smoke cell; empty without smoke
    Eigen::VectorXd initialVelocity;
    Eigen::VectorXd initialMagneticField;  ///< empty without MHD

    int modeCount() const { return int(initialVelocity.size()); }
};

}  // namespace modeflow
