#pragma once
/// @file CacheSummary.h
/// What `modeflow inspect --json` prints of a basis cache (keys in tools/README.md), and the
/// cache a scene file or a cache file names; the CLI and the Python module's `inspect` share it.

#include <filesystem>

#include <nlohmann/json.hpp>

#include "engine/core/Progress.h"
#include "engine/core/SceneSpec.h"

namespace modeflow {

/// The summary of the cache file: grid, bases with their checks, coefficients, timings, file.
/// @throw modeflow::Error when the file is not a readable cache.
nlohmann::ordered_json cacheSummary(const std::filesystem::path& cacheFile);

/// `cacheOrScene` itself when it is a cache (told by its first bytes, not its name), else the
/// cache of the scene it holds, in `cacheDir`, precomputed on a miss.
/// @throw modeflow::Error for a file that is neither, a bad scene or a failed precompute.
std::filesystem::path inspectedCache(const std::filesystem::path& cacheOrScene,
                                     const std::filesystem::path& cacheDir, Progress& progress);

/// The cache of `scene` in `cacheDir`, precomputed on a miss.
std::filesystem::path sceneCache(const SceneSpec& scene, const std::filesystem::path& cacheDir,
                                 Progress& progress);

}  // namespace modeflow
