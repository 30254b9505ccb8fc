#pragma once
/// @file RunInputs.h
/// Scene + cache folder → everything a simulation of the scene needs: the basis cache
/// (precomputed on a miss), its structural coefficients, the run's settings, the smoke mask and
/// the initial state. The one way `run`, `stir`, `modes`, the tests and the benchmarks set up a
/// run; Backend makes the simulation from it.

#include <cstdint>
#include <filesystem>
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "engine/core/SceneSpec.h"
#include "engine/dynamics/StructuralCoefficients.h"
#include "engine/format/BasisCache.h"
#include "engine/simulation/SimulationSettings.h"
#include "precompute/Progress.h"

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

/// What a command needs of the scene: the reduced dynamics alone (`modes`), or the smoke too.
enum class RunParts { Dynamics, DynamicsAndSmoke };

/// The scene's cache from `cacheDir` (computed and written on a miss), and all the rest from it.
/// @throw modeflow::Error naming the scene key or stage that failed: an initial state that is
///        not finite, a [[source]] with no fluid cell to emit into, a failed precompute.
RunInputs prepareRun(const SceneSpec& scene, const std::filesystem::path& cacheDir,
                     Progress& progress, RunParts parts = RunParts::DynamicsAndSmoke);

/// The same on a basis already in memory (tests and benchmarks; `cache.key` may be empty, the
/// smoke mask is then built from the domain).
RunInputs prepareRun(const SceneSpec& scene, BasisCache cache,
                     RunParts parts = RunParts::DynamicsAndSmoke);

}  // namespace modeflow
