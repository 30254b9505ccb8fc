#pragma once
/// @file InitialState.h
/// The scene's [initial] velocity as a modal state, shared by the commands that simulate.

#include <Eigen/Core>

#include "engine/format/BasisCache.h"
#include "precompute/scene/SceneSpec.h"

namespace modeflow::cli {

/// The scene's [initial] velocity as a modal state on this basis. Mode numbers in the scene are
/// 1-based positions in the basis; the engine takes 0-based ones.
/// @throw modeflow::Error naming the [initial] key when a mode is outside the basis.
Eigen::VectorXd initialVelocity(const SceneSpec& scene, const BasisCache& cache, int modes);

}  // namespace modeflow::cli
