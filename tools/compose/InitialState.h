#pragma once
/// @file InitialState.h
/// The scene's [initial] velocity and magnetic field as modal states, shared by the commands that
/// simulate.

#include <Eigen/Core>

#include "engine/core/SceneSpec.h"
#include "engine/format/BasisCache.h"

namespace modeflow {

/// The scene's [initial] velocity as a modal state on this basis. Mode numbers in the scene are
/// 1-based positions in the basis; the engine takes 0-based ones.
/// @throw modeflow::Error naming the [initial] key when a mode is outside the basis, or when the
/// state is not one a step can take (requireRepresentableState: infinite, or |v| above ~1e77).
Eigen::VectorXd initialVelocity(const SceneSpec& scene, const BasisCache& cache, int modes);

/// The scene's [initial] magnetic field (MHD scenes, seed §6.3.5) as modal coefficients F on the
/// velocity basis: random amplitudes, or a uniform field projected like vortices are.
/// @throw modeflow::Error naming [initial].magnetic when the field cannot be built, or the key
/// that sets its size when a step could not take it.
Eigen::VectorXd initialMagneticField(const SceneSpec& scene, const BasisCache& cache, int modes);

}  // namespace modeflow
