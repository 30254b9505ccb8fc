#pragma once
/// @file RunIdentity.h
/// What a run's files belong to: the scene text (in every frame's metadata) and, for its
/// checkpoint, the scene text with the basis it makes (mesh files included) and the device kind;
/// the frame count does not change results, so a longer run resumes a shorter one.

#include <cstdint>
#include <string>
#include <string_view>

#include "engine/core/SceneSpec.h"
#include "engine/simulation/BackendCapabilities.h"

namespace modeflow {

struct RunIdentity {
    std::string sceneHash;  ///< 16 hex digits of the scene file's bytes
    std::uint64_t runHash = 0;
};

/// @throw modeflow::Error as basisKey when a mesh file of the scene cannot be read.
RunIdentity runIdentity(const SceneSpec& scene, BackendKind backend);
/// The same for a scene read from `sceneText` rather than its file (the Python module's).
RunIdentity runIdentity(const SceneSpec& scene, BackendKind backend, std::string_view sceneText);

}  // namespace modeflow
