#pragma once
/// @file SurfaceStages.h
/// The precompute of a surface scene (scenes/README.md, "Curved surfaces"): its mesh read and
/// checked, the surface DEC, the bases and the structural coefficients (packed and dense:
/// Precompute chooses their storage), into a cache of kind Surface.

#include <string>

#include "engine/core/Progress.h"
#include "engine/core/SceneSpec.h"
#include "engine/format/BasisCache.h"

namespace modeflow {

/// @throw Error naming [surface].mesh (and the first offending element) for a mesh that is not
///        a closed, oriented manifold, or [basis] for more modes than the surface holds.
BasisCache computeSurfaceStages(const SceneSpec& scene, std::string key, Progress& progress);

}  // namespace modeflow
